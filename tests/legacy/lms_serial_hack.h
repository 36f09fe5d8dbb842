/* lms_serial_hack.h — the lms_serial conformance module's interface (C types only). */
#ifndef LMS_SERIAL_HACK_H
#define LMS_SERIAL_HACK_H

#define LMS_HACK_API __attribute__((visibility("default")))

/* Runs the module's init (0 or -errno) / exit. */
LMS_HACK_API int lms_serial_load(void);
LMS_HACK_API void lms_serial_unload(void);
/* The converter's answers to its three SPI frames. */
LMS_HACK_API unsigned lms_serial_adc_answer(int frame);
/* The bytes its UART loopback received (up to max); their count. */
LMS_HACK_API int lms_serial_echo(char *buf, int max);
/* eCAP's CAP1 as its 32-bit read returned it after the 16-bit writes. */
LMS_HACK_API unsigned long lms_serial_pwm_period(void);
/* Its own Hw. */
LMS_HACK_API int lms_serial_board(void);

#endif
