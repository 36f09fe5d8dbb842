/* lms_pins26_hack.h — the lms_pins26 module's interface (C types only). */
#ifndef LMS_PINS26_HACK_H
#define LMS_PINS26_HACK_H

#define LMS_PINS26_API __attribute__((visibility("default")))

/* Runs the module's init (0 or -errno) / exit. */
LMS_PINS26_API int lms_pins26_load(void);
LMS_PINS26_API void lms_pins26_unload(void);
/* Drives the output pin (PinsDrive). */
LMS_PINS26_API void lms_pins26_drive(int level);
/* Copies the input pin to the output (PinsMirror); the count of mirrors so far. */
LMS_PINS26_API int lms_pins26_mirror(void);

#endif
