/*
 * uart_module.h — what the d_uart module shares between its two translation
 * units: the hack file (uart_hack.c, with the driver) defines it, the service
 * calls (uart_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_UART_MODULE_H
#define EV3LX_UART_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include "lms_uart.h"

extern struct file *uart_file;			/* /dev/lms_uart, opened at the first call */
extern const struct lms_uart_shm *uart_map;	/* its shared memory, mapped */

/* The open device, opening it (and mapping its memory) on first use; NULL if d_uart is not up. */
struct file *uart_hack_file(void);

#endif /* EV3LX_UART_MODULE_H */
