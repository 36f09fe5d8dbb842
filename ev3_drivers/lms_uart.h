/* SPDX-License-Identifier: GPL-2.0 WITH Linux-syscall-note */
/*
 * lms_uart.h - user interface of d_uart (/dev/lms_uart): EV3 UART sensors on input ports 1..4.
 *
 * Interface-compatible with LEGO's lms2012 d_uart:
 *   ioctl  LMS_UART_SET_CONN (DEVCON) starts, re-modes or stops ports; the three UARTCTL
 *          ioctls hand the sensor's mode information to user space;
 *   mmap   struct lms_uart (LEGO's UART, 42744 bytes, same offsets on every target) followed
 *          by struct lms_uart_ext, our extension (see below), in one mapping of
 *          LMS_UART_MAP_SIZE bytes; LEGO user space maps only the first part and is unaffected;
 *   write  [0] = port 0..3, then 1..32 bytes sent to the sensor as a WRITE command; returns
 *          the count, -EBUSY while the port's previous WRITE is still pending;
 *   read   the four port states (LMS_UART_STATE_*) as text, e.g. "5 0 0 0\n".
 *
 * Reading a value without a system call (see lms_uart_sample()): the newest sample of port p
 * is raw[p][actual[p]]; it is valid for mode m only while ext.port[p].data_mode == m and
 * ext.sample_mode[p][actual[p]] == m.  After a mode change, data_mode is -1 until a frame of
 * the new mode has arrived, so no value of the old mode is ever served; a sensor that stops
 * sending is flagged LMS_UART_FLAG_STALE and its data withdrawn the same way.
 */
#ifndef LMS_UART_H
#define LMS_UART_H

#ifdef __KERNEL__
#include <linux/types.h>
/* Mode-info limits as IEEE-754 single bit patterns: the kernel never does float arithmetic. */
typedef uint32_t lms_uart_float;
#else
#include <stdint.h>
typedef float lms_uart_float;
#endif

#define LMS_UART_DEVICE_NAME	"lms_uart"

#define LMS_UART_PORTS		4	/* input ports 1..4 are indexes 0..3 */
#define LMS_UART_MODES		8	/* modes 0..7 */
#define LMS_UART_DATA_SIZE	32	/* bytes per sample (a DATA payload, zero padded) */
#define LMS_UART_LOG_SIZE	300	/* samples kept per port */
#define LMS_UART_NAME_SIZE	11	/* characters of a mode name (plus NUL) */
#define LMS_UART_SYMBOL_SIZE	4	/* characters of a unit symbol (plus NUL) */

/* Status[port] bits. */
#define LMS_UART_PORT_CHANGED	0x01	/* new mode information: read it, then CLEAR_CHANGED */
#define LMS_UART_DATA_READY	0x08	/* raw[port][actual[port]] holds valid data */
#define LMS_UART_WRITE_REQUEST	0x10	/* a write() is waiting to be sent */

/* Codes shared with lms_analog.h (identical definitions). */
#define LMS_CONN_INPUT_UART	122	/* DEVCON connection that hands a port to d_uart */
#define LMS_TYPE_TERMINAL	124	/* no sensor protocol found: raw bytes at 115200 baud */

/* DATA formats (TYPES.format). */
#define LMS_UART_DATA8		0
#define LMS_UART_DATA16		1
#define LMS_UART_DATA32		2
#define LMS_UART_DATAF		3

/* LEGO's TYPES: the information a sensor gives about one mode, 56 bytes. */
struct lms_uart_types {
	char name[LMS_UART_NAME_SIZE + 1];	/* e.g. "COL-REFLECT", NUL terminated */
	int8_t type;				/* sensor type, e.g. 29 colour */
	int8_t connection;			/* LMS_CONN_INPUT_UART */
	int8_t mode;				/* this mode's number */
	int8_t data_sets;			/* values per sample */
	int8_t format;				/* LMS_UART_DATA* */
	int8_t figures;				/* digits shown */
	int8_t decimals;			/* decimals shown */
	int8_t views;				/* modes the sensor shows to users */
	lms_uart_float raw_min, raw_max;	/* range of the raw values */
	lms_uart_float pct_min, pct_max;	/* percent range (default 0..100) */
	lms_uart_float si_min, si_max;		/* range in SI units */
	uint16_t invalid_time;			/* not set by the driver (user-space type table) */
	uint16_t id_value;			/* not used for UART sensors */
	int8_t pins;				/* not used for UART sensors */
	char symbol[LMS_UART_SYMBOL_SIZE + 1];	/* unit, e.g. "pct", NUL terminated */
};

/* LEGO's DEVCON: the argument of LMS_UART_SET_CONN, 12 bytes. */
struct lms_uart_devcon {
	int8_t connection[LMS_UART_PORTS];	/* LMS_CONN_INPUT_UART starts/keeps a port */
	int8_t type[LMS_UART_PORTS];		/* informational, not used by the driver */
	int8_t mode[LMS_UART_PORTS];		/* the mode wanted, 0..7 */
};

/* LEGO's UARTCTL: the argument of the other three ioctls, 60 bytes. */
struct lms_uart_ctl {
	struct lms_uart_types type_data;
	int8_t port;				/* 0..3 */
	int8_t mode;				/* 0..7 */
};

/*
 * LMS_UART_SET_CONN: for each port, connection LMS_CONN_INPUT_UART on an idle port starts
 *   the handshake (2400 baud, TYPE/MODES/SPEED/INFO, ACK, DATA); on a running port a different
 *   mode is selected (SELECT); any other connection stops the port.  -EINVAL for a mode
 *   outside 0..7 (or beyond the sensor's modes once known), -ENODEV for a port without
 *   hardware; on error no port is changed.
 * LMS_UART_READ_MODE_INFO: copies TYPES[port][mode] out; name[0] is 0 when that mode's
 *   information did not change since it was last read.
 * LMS_UART_NACK_MODE_INFO: flags the mode's information as changed again.
 * LMS_UART_CLEAR_CHANGED: clears LMS_UART_PORT_CHANGED; samples are stored only while it is
 *   clear (LEGO's rule: user space has accepted the sensor's description first).
 */
#define LMS_UART_SET_CONN	0xC00C7500U	/* _IOWR('u', 0, struct lms_uart_devcon) */
#define LMS_UART_READ_MODE_INFO	0xC03C7501U	/* _IOWR('u', 1, struct lms_uart_ctl) */
#define LMS_UART_NACK_MODE_INFO	0xC03C7502U	/* _IOWR('u', 2, struct lms_uart_ctl) */
#define LMS_UART_CLEAR_CHANGED	0xC03C7503U	/* _IOWR('u', 3, struct lms_uart_ctl) */

/* LEGO's UART: the shared memory, 42744 bytes. */
struct lms_uart {
	struct lms_uart_types types[LMS_UART_PORTS][LMS_UART_MODES];
	uint16_t repeat[LMS_UART_PORTS][LMS_UART_LOG_SIZE];	/* ms each sample was current */
	int8_t raw[LMS_UART_PORTS][LMS_UART_LOG_SIZE][LMS_UART_DATA_SIZE];
	uint16_t actual[LMS_UART_PORTS];	/* index of the newest sample */
	uint16_t log_in[LMS_UART_PORTS];	/* index the next sample goes to */
	int8_t status[LMS_UART_PORTS];		/* LMS_UART_PORT_CHANGED ... */
	int8_t output[LMS_UART_PORTS][LMS_UART_DATA_SIZE];	/* pending write() data */
	int8_t output_length[LMS_UART_PORTS];
};

#define LMS_UART_SIZE		42744	/* sizeof(struct lms_uart) */

/* Port states, as read() reports them and ext.port[].state holds. */
#define LMS_UART_STATE_IDLE	0	/* not in use */
#define LMS_UART_STATE_SYNC	1	/* 2400 baud, looking for the sensor's TYPE */
#define LMS_UART_STATE_INFO	2	/* collecting MODES, SPEED and the mode INFO */
#define LMS_UART_STATE_ACK	3	/* sensor's ACK accepted, host ACK due */
#define LMS_UART_STATE_SPEED	4	/* host ACK sent, speed change due */
#define LMS_UART_STATE_DATA	5	/* receiving DATA, NACK keep-alive running */
#define LMS_UART_STATE_TERMINAL	6	/* no sensor protocol: raw bytes at 115200 baud */

/* ext.port[].flags */
#define LMS_UART_FLAG_STALE	0x01	/* no frame of the selected mode for stale_ms */
#define LMS_UART_FLAG_SELECTING	0x02	/* SELECT sent, waiting for the new mode's data */

/* Our extension: per-port state and counters, after LEGO's layout in the same mapping. */
struct lms_uart_port_ext {
	uint32_t seq;			/* +1 for every sample stored */
	int8_t data_mode;		/* mode of the current valid data, -1 when none */
	uint8_t state;			/* LMS_UART_STATE_* */
	uint8_t flags;			/* LMS_UART_FLAG_* */
	uint8_t modes;			/* modes the sensor announced, 0 before the handshake */
	int8_t mode;			/* the mode selected (SET_CONN), while state is not IDLE */
	uint8_t reserved[3];
	uint32_t speed;			/* baud rate in use */
	uint32_t frames;		/* valid DATA frames received */
	uint32_t check_errors;		/* DATA frames with a bad check byte */
	uint32_t keepalive_misses;	/* keep-alive periods without a valid frame */
	uint32_t fifo_overruns;		/* receive overruns in the UART (LSR.OE; bytes were lost) */
	uint32_t ring_overflows;	/* bytes lost because the receive ring was full */
	uint32_t line_errors;		/* framing and parity errors */
	uint32_t breaks;		/* break conditions (line held low) */
	uint32_t reconnects;		/* handshakes restarted after errors, unplug or silence */
	uint32_t handshake_errors;	/* handshakes abandoned (bad INFO, bad check, bad ACK) */
	uint32_t selects;		/* SELECT commands sent */
	uint32_t size_errors;		/* headers announcing more than the longest valid message */
	uint32_t resyncs;		/* losses of frame sync in DATA (each ends at the next valid frame) */
};

struct lms_uart_ext {
	uint32_t magic;			/* LMS_UART_EXT_MAGIC */
	uint32_t size;			/* sizeof(struct lms_uart_ext) */
	struct lms_uart_port_ext port[LMS_UART_PORTS];
	int8_t sample_mode[LMS_UART_PORTS][LMS_UART_LOG_SIZE];	/* mode of each raw[][] sample */
};

#define LMS_UART_EXT_MAGIC	0x54584555U	/* "UEXT" */

/* The whole mapping: LEGO's part at offset 0, the extension at LMS_UART_SIZE. */
struct lms_uart_shm {
	struct lms_uart lms;
	struct lms_uart_ext ext;
};

#define LMS_UART_MAP_SIZE	45056	/* sizeof(struct lms_uart_shm) rounded up to 4 KiB pages */

/*
 * Returns the newest sample of @port if it is valid data of @mode, else NULL.  Lock-free: the
 * driver fills a sample slot before publishing its index, and reuses it only 300 samples later
 * or, when the port restarts (its samples start again in slot 0), after a new handshake.
 */
static inline const int8_t *lms_uart_sample(const struct lms_uart_shm *shm, unsigned int port,
					    int mode)
{
	unsigned int slot = *(const volatile uint16_t *)&shm->lms.actual[port];

	if (*(const volatile int8_t *)&shm->ext.port[port].data_mode != mode ||
	    *(const volatile int8_t *)&shm->ext.sample_mode[port][slot] != mode)
		return (const int8_t *)0;
	return shm->lms.raw[port][slot];
}

#endif /* LMS_UART_H */
