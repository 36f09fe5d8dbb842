/*
 * speed.c — multisrc's second module: its own ATT_MOD, so its statics are
 * the app domain's too.
 */
#include "speed.h"

int speed_lookups;

int speed_for(int port)
{
	speed_lookups++;
	return 40 + 10 * port;
}
