/* lms_motor_hack.h — the lms_motor conformance module's interface (C types only). */
#ifndef LMS_MOTOR_HACK_H
#define LMS_MOTOR_HACK_H

#define LMS_MOTOR_API __attribute__((visibility("default")))

/* Runs the module's init (0 or -errno) / exit. */
LMS_MOTOR_API int lms_motor_load(void);
LMS_MOTOR_API void lms_motor_unload(void);
/* Sets the eHRPWM1 A compare value (the driver's SetDuty). */
LMS_MOTOR_API void lms_motor_duty(unsigned short duty);
/* The board revision its init selected (its global Hw). */
LMS_MOTOR_API int lms_motor_board(void);

#endif
