/*
 * serial_log.h — the serial log channel: a simulated serial port whose far
 * end writes every byte to a file, standing in for the EV3's Bluetooth SPP
 * link, and the extended service call applications write it with.
 *
 * The port is a UART transmitter with its FIFO off (a holding register and
 * a shift register): each byte takes (1 + 8 + 1) bit times at the baud.
 * serial_log_write() is a polled driver: it puts each byte into the holding
 * register as soon as the register is empty and spins (virtual CPU time of
 * the calling task) while it is full, so a task that logs faster than the
 * link carries is busy all the time — as it would be on the brick.  Host
 * only: the port model uses rtos_host_consume.
 */
#ifndef EV3SIM_SERIAL_LOG_H
#define EV3SIM_SERIAL_LOG_H

#include <stdint.h>
#include <stdio.h>
#include "kernel.h"
#include "rtos_cfg.h"

#define SERIAL_LOG_FN_WRITE   TNUM_FNCD  /* (const char *buf, uint_t len): returns len; the last code (the drivers' are below) */
#define SERIAL_LOG_MAX_WRITE  256U  /* bytes per call */
#define SERIAL_LOG_DEFAULT_BAUD 115200U

/* CPU time of one register access of the polled driver (host_sim's default
 * access cost); the busy wait between bytes is rtos_host_spin_until's. */
#define SERIAL_LOG_ACCESS_NS  50U

/* The DEF_SVC row (INCLUDE it in the application's configuration). */
extern const struct rtos_cfg serial_log_cfg;

/* Sets the port up before boot: baud (> 0) and where the far end writes
 * (NULL: bytes are timed and counted, then dropped).  E_PAR for baud 0. */
ER serial_log_setup(uint32_t baud, FILE *out);

struct serial_log_stats {
	uint64_t bytes;             /* bytes that went onto the wire */
	uint64_t writes;            /* successful calls */
	uint64_t spin_ns;           /* CPU time callers spent waiting for the port */
};
/* Counters since serial_log_setup. */
const struct serial_log_stats *serial_log_get_stats(void);

/* The polled write of len bytes by the calling task, as the service call
 * does after its checks (brick_io's serial port uses it when it is this
 * port, brick_io_serial_to_uart). */
ER_UINT serial_log_send(const char *buf, uint_t len);

/* Writes len (1..SERIAL_LOG_MAX_WRITE) bytes; returns len once the last one
 * is in the port (not yet on the wire).  E_CTX outside a task, E_PAR for a
 * bad length, E_MACV for a buffer the caller may not read. */
static inline ER_UINT serial_log_write(const char *buf, uint_t len)
{
	return cal_svc(SERIAL_LOG_FN_WRITE, (intptr_t)buf, (intptr_t)len, 0, 0, 0);
}

#endif /* EV3SIM_SERIAL_LOG_H */
