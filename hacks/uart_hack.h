/*
 * uart_hack.h — d_uart's interface on the RTOS: extended service calls
 * (function codes UART_FN_FIRST.. are d_uart's) and the configuration fragment that
 * defines them.  Plain TOPPERS C: applications and the api include it.
 *
 * Reading a value needs no service call: uart_svc_map() gives the driver's
 * shared memory, and lms_uart_sample() (lms_uart.h) returns the newest
 * sample of a port if it is valid data of the wanted mode.
 *
 * Every call checks its arguments and returns a TOPPERS code:
 *   E_ID    port number out of range (0..3 are ports 1..4)
 *   E_PAR   bad mode (outside 0..7, or beyond the sensor's modes) or length
 *   E_MACV  a buffer the calling task may not access (the driver's -EFAULT)
 *   E_OBJ   the port has no UART, is not started, or has no sensor description
 *           yet; or the driver is not loaded
 *   E_QOVR  the port's previous WRITE has not been sent yet
 *   E_CTX   called from non-task context
 */
#ifndef EV3LX_UART_HACK_H
#define EV3LX_UART_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: UART_FN_FIRST .. + UART_FN_COUNT - 1
 * (EV3LX_FNCD_BASE moves every module's range, -DUART_FN_FIRST=n this one; boot rejects ranges
 * that overlap another module's). */
#ifndef UART_FN_FIRST
#define UART_FN_FIRST (EV3LX_FNCD_BASE + 31)
#endif
#define UART_FN_COUNT 16
#define UART_FN_LAST  (UART_FN_FIRST + UART_FN_COUNT - 1)

#define UART_FN_SET_MODE      (UART_FN_FIRST + 0)  /* (uint_t port, uint_t mode): start the port / select the mode */
#define UART_FN_STOP          (UART_FN_FIRST + 1)  /* (uint_t port): stop the port, withdraw its data */
#define UART_FN_MODE_INFO     (UART_FN_FIRST + 2)  /* (uint_t port, uint_t mode, struct lms_uart_types *out) */
#define UART_FN_CLEAR_CHANGED (UART_FN_FIRST + 3)  /* (uint_t port): accept the sensor's description (data flows) */
#define UART_FN_WRITE         (UART_FN_FIRST + 4)  /* (uint_t port, const void *data, uint_t len): WRITE, 1..32 bytes */
#define UART_FN_MAP           (UART_FN_FIRST + 5)  /* (const struct lms_uart_shm **out): the shared memory */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "lms_uart.h"

/* The DEF_SVC rows and the board settings (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg uart_hack_cfg;

/* Hands input port (0..3) to d_uart in mode (0..7): starts the handshake, or selects the mode. */
static inline ER uart_svc_set_mode(uint_t port, uint_t mode)
{
	return (ER)cal_svc(UART_FN_SET_MODE, (intptr_t)port, (intptr_t)mode, 0, 0, 0);
}

/* Stops d_uart on the port. */
static inline ER uart_svc_stop(uint_t port)
{
	return (ER)cal_svc(UART_FN_STOP, (intptr_t)port, 0, 0, 0, 0);
}

/* Copies what the sensor said about one of its modes (name, format, ranges). */
static inline ER uart_svc_mode_info(uint_t port, uint_t mode, struct lms_uart_types *out)
{
	return (ER)cal_svc(UART_FN_MODE_INFO, (intptr_t)port, (intptr_t)mode, (intptr_t)out, 0, 0);
}

/*
 * Accepts a new sensor description (LMS_UART_PORT_CHANGED): as in LEGO's
 * driver, samples are stored only after this.
 */
static inline ER uart_svc_clear_changed(uint_t port)
{
	return (ER)cal_svc(UART_FN_CLEAR_CHANGED, (intptr_t)port, 0, 0, 0, 0);
}

/* Sends len (1..32) bytes to the sensor as a WRITE command. */
static inline ER uart_svc_write(uint_t port, const void *data, uint_t len)
{
	return (ER)cal_svc(UART_FN_WRITE, (intptr_t)port, (intptr_t)data, (intptr_t)len, 0, 0);
}

/* The driver's shared memory (LEGO's UART and d_uart's extension), read-only for callers. */
static inline ER uart_svc_map(const struct lms_uart_shm **out)
{
	return (ER)cal_svc(UART_FN_MAP, (intptr_t)out, 0, 0, 0, 0);
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_UART_HACK_H */
