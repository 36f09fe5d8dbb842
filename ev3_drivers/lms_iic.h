/* SPDX-License-Identifier: GPL-2.0 WITH Linux-syscall-note */
/*
 * lms_iic.h - user interface of d_iic (/dev/lms_iic): NXT I2C sensors on input ports 1..4.
 *
 * Interface-compatible with LEGO's lms2012 d_iic (ioctl type 'i'):
 *   ioctl  LMS_IIC_SET_CONN (DEVCON) starts or stops ports (connection LMS_CONN_NXT_IIC);
 *          LMS_IIC_READ_TYPE_INFO returns the probed manufacturer and sensor type strings;
 *          LMS_IIC_SET gives the setup and poll strings for auto-polling;
 *          LMS_IIC_SETUP runs one (or repeated) raw transaction;
 *   mmap   struct lms_iic (LEGO's IIC, 42748 bytes, same offsets on every target), from
 *          offset 0, LMS_IIC_MAP_SIZE bytes at most;
 *   read   the four port states (LMS_IIC_STATE_*) as text, "%2u %2u %2u %2u\r";
 *   write  accepted and ignored (LEGO's user space sends [port][bytes] there).
 *
 * Byte conventions: the first byte of a transaction (wr_data[0], the top byte of a setup or
 * poll string) is the 7-bit slave address; setup and poll strings pack up to 4 bytes
 * MSB-first (0x4C016000 = address 0x4C, bytes 0x01 0x60).  A read length n > 1 stores the
 * bytes reversed (last received first: big-endian register pairs become little-endian), a
 * negative n stores |n| bytes in bus order, and one byte b is stored as [b, 0].
 */
#ifndef LMS_IIC_H
#define LMS_IIC_H

#ifdef __KERNEL__
#include <linux/types.h>
#else
#include <stdint.h>
#endif

#define LMS_IIC_DEVICE_NAME	"lms_iic"

#define LMS_IIC_PORTS		4	/* input ports 1..4 are indexes 0..3 */
#define LMS_IIC_DATA_SIZE	32	/* bytes per sample and per transaction */
#define LMS_IIC_LOG_SIZE	300	/* samples kept per port */
#define LMS_IIC_NAME_SIZE	9	/* manufacturer / sensor type: 8 characters and a NUL */
#define LMS_IIC_STRING_SIZE	4	/* bytes of a setup or poll string */

/* Status[port] bits. */
#define LMS_IIC_PORT_CHANGED	0x01	/* new identification strings: READ_TYPE_INFO */
#define LMS_IIC_DATA_READY	0x08	/* data valid (raw[][actual] or a SETUP's answer) */
#define LMS_IIC_WRITE_REQUEST	0x10	/* a SETUP transaction is pending */

/* Codes shared with lms_analog.h (identical definitions). */
#define LMS_CONN_NXT_IIC	120	/* DEVCON connection that hands a port to d_iic */
#define LMS_TYPE_NXT_IIC	123

/* RESULT of LMS_IIC_SETUP. */
#define LMS_IIC_OK		0
#define LMS_IIC_BUSY		1
#define LMS_IIC_FAIL		2

/* LEGO's DEVCON: the argument of LMS_IIC_SET_CONN, 12 bytes. */
struct lms_iic_devcon {
	int8_t connection[LMS_IIC_PORTS];	/* LMS_CONN_NXT_IIC starts/keeps a port */
	int8_t type[LMS_IIC_PORTS];		/* informational */
	int8_t mode[LMS_IIC_PORTS];		/* a new mode re-runs the setup string */
};

/* LEGO's IICSTR: identification and auto-polling of a port, 44 bytes. */
struct lms_iic_str {
	int8_t port;
	int8_t pad0;
	int16_t time;				/* poll period in ms */
	int8_t type;
	int8_t mode;
	char manufacturer[LMS_IIC_NAME_SIZE];	/* NUL terminated */
	char sensor_type[LMS_IIC_NAME_SIZE];	/* NUL terminated */
	int8_t setup_lng;			/* 0..4 bytes of setup_string (0: none) */
	int8_t pad1[3];
	uint32_t setup_string;			/* MSB-first: address, register, value */
	int8_t poll_lng;			/* 0..4 bytes of poll_string (0: no polling) */
	int8_t pad2[3];
	uint32_t poll_string;			/* MSB-first: address, register */
	int8_t read_lng;			/* bytes read per poll, sign as above */
	int8_t pad3[3];
};

/* LEGO's IICDAT: one raw transaction (LMS_IIC_SETUP), 76 bytes. */
struct lms_iic_dat {
	int32_t result;				/* out: LMS_IIC_OK, _BUSY or _FAIL */
	int8_t port;
	int8_t repeat;				/* 0: repeat forever, n: n transactions */
	int16_t time;				/* ms between repeats */
	int8_t wr_lng;				/* 1..32 bytes of wr_data (address first) */
	uint8_t wr_data[LMS_IIC_DATA_SIZE];
	int8_t rd_lng;				/* bytes to read, sign as above */
	uint8_t rd_data[LMS_IIC_DATA_SIZE];	/* out: the answer */
	uint8_t pad[2];
};

/*
 * LMS_IIC_SET_CONN: per port, LMS_CONN_NXT_IIC on an idle port starts it (the bus is enabled
 *   and the sensor probed); a changed mode on a running port runs its setup string again; any
 *   other connection stops the port.
 * LMS_IIC_READ_TYPE_INFO: in port, out manufacturer and sensor_type; clears changed[port].
 *   LEGO declares it with a 60-byte argument but transfers an IICSTR: 44 bytes are copied.
 * LMS_IIC_SETUP: while no request is pending, latches the transaction and answers BUSY; once
 *   its data is ready, returns it with OK (FAIL if the slave did not answer) and clears the
 *   status.  Callers repeat the ioctl until the result is not BUSY.
 * LMS_IIC_SET: the setup and poll strings and read length of a port; its setup string is sent,
 *   then the poll string every time ms, the answers going to the raw ring.
 * All return -EINVAL for a port outside 0..3 or a length out of range, -EFAULT for a bad
 * pointer.
 */
#define LMS_IIC_SET_CONN	0xC00C6902U	/* _IOWR('i', 2, DEVCON) */
#define LMS_IIC_READ_TYPE_INFO	0xC03C6903U	/* _IOWR('i', 3, IICCTL), really an IICSTR */
#define LMS_IIC_SETUP		0xC04C6905U	/* _IOWR('i', 5, IICDAT) */
#define LMS_IIC_SET		0xC02C6906U	/* _IOWR('i', 6, IICSTR) */

/* LEGO's IIC: the shared memory, 42748 bytes. */
struct lms_iic {
	uint8_t type_data[LMS_IIC_PORTS][8][56];	/* LEGO's TYPES area, unused by the driver */
	uint16_t repeat[LMS_IIC_PORTS][LMS_IIC_LOG_SIZE];	/* ms each sample was current */
	int8_t raw[LMS_IIC_PORTS][LMS_IIC_LOG_SIZE][LMS_IIC_DATA_SIZE];
	uint16_t actual[LMS_IIC_PORTS];		/* index of the newest sample */
	uint16_t log_in[LMS_IIC_PORTS];		/* index the next sample goes to */
	int8_t status[LMS_IIC_PORTS];		/* LMS_IIC_PORT_CHANGED ... */
	int8_t changed[LMS_IIC_PORTS];		/* 1: new identification strings */
	int8_t output[LMS_IIC_PORTS][LMS_IIC_DATA_SIZE];
	int8_t output_length[LMS_IIC_PORTS];
};

#define LMS_IIC_SIZE		42748	/* sizeof(struct lms_iic) */
#define LMS_IIC_MAP_SIZE	45056	/* rounded up to 4 KiB pages (11) */

/* Port states, as read() reports them. */
#define LMS_IIC_STATE_IDLE		0
#define LMS_IIC_STATE_INIT		1
#define LMS_IIC_STATE_RESTART		2
#define LMS_IIC_STATE_ENABLE		3
#define LMS_IIC_STATE_TEMP_START	4
#define LMS_IIC_STATE_TEMP_WRITE	5
#define LMS_IIC_STATE_TEMP_READ		6
#define LMS_IIC_STATE_MANUF_START	7
#define LMS_IIC_STATE_MANUF_WRITE	8
#define LMS_IIC_STATE_MANUF_READ	9
#define LMS_IIC_STATE_TYPE_START	10
#define LMS_IIC_STATE_TYPE_WRITE	11
#define LMS_IIC_STATE_TYPE_READ		12
#define LMS_IIC_STATE_SETUP_WAIT	13
#define LMS_IIC_STATE_SETUP_START	14
#define LMS_IIC_STATE_SETUP_WRITE	15
#define LMS_IIC_STATE_SETUP_READ	16
#define LMS_IIC_STATE_WAITING		17
#define LMS_IIC_STATE_WRITING		18
#define LMS_IIC_STATE_READING		19
#define LMS_IIC_STATE_REPEAT		20
#define LMS_IIC_STATE_ERROR		21
#define LMS_IIC_STATE_EXIT		22

#endif /* LMS_IIC_H */
