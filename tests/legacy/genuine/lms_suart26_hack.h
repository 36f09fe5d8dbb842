/* lms_suart26_hack.h — the lms_suart26 module's interface (C types only). */
#ifndef LMS_SUART26_HACK_H
#define LMS_SUART26_HACK_H

#define LMS_SUART26_API __attribute__((visibility("default")))

/* The board's part: registers its soft-UART device and firmware (present), or removes them. */
LMS_SUART26_API int lms_suart26_board(int present);
/* request_firmware of a name no one registered: its error (NULL left in the pointer), or 0. */
LMS_SUART26_API int lms_suart26_missing_firmware(void);
/* Runs the module's init (0 or -errno) / exit. */
LMS_SUART26_API int lms_suart26_load(void);
LMS_SUART26_API void lms_suart26_unload(void);
/* Sets both channels' baud through the port's set_termios. */
LMS_SUART26_API void lms_suart26_set_baud(unsigned int baud);
/* Queues bytes for the soft UART (the count queued) / takes received ones (the count taken). */
LMS_SUART26_API int lms_suart26_write(const unsigned char *data, int size);
LMS_SUART26_API int lms_suart26_read(unsigned char *data, int size);
/* The port's timeout in jiffies (uart_update_timeout). */
LMS_SUART26_API unsigned int lms_suart26_timeout(void);
/* 1 if the transmit channel is idle (the port's tx_empty). */
LMS_SUART26_API int lms_suart26_tx_idle(void);
/* Interrupts taken, full halves and time-outs received. */
LMS_SUART26_API void lms_suart26_counts(int *irqs, int *halves, int *timeouts);

#endif
