/*
 * speed.h — multisrc's second module (in APPL_DIRS, found through INCLUDES).
 */
extern int speed_lookups;
int speed_for(int port);
