/*
 * ev3api_brick_io.h — the extended service calls behind the API's file and
 * serial groups (ev3api_fs.h): the SD card's files and directories and the
 * serial ports' byte streams.  Not for applications: the platform provides
 * them (ev3sim: a host directory and a host file or pseudo-terminal,
 * ev3sim/brick_io.h); where nothing provides them cal_svc returns E_RSFN and
 * the API reports E_NOSPT.
 *
 * Paths are absolute or relative to the card's root ("/ev3rt/res/a.wav");
 * a provider confines them to the card (a ".." above the root is E_PAR).
 * Every call checks its pointers with prb_mem against the caller's domain.
 */
#ifndef EV3API_BRICK_IO_H
#define EV3API_BRICK_IO_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdint.h>
#include "kernel.h"
#include "ev3api_fs.h"
#include "hack_interface.h"

/* The function codes this module owns: BRICK_IO_FN_FIRST .. + BRICK_IO_FN_COUNT - 1
 * (after the hacks' ranges, EV3LX_FNCD_BASE moves it with them, -DBRICK_IO_FN_FIRST=n alone; boot rejects ranges
 * that overlap another module's). */
#ifndef BRICK_IO_FN_FIRST
#define BRICK_IO_FN_FIRST (EV3LX_FNCD_BASE + 111)
#endif
#define BRICK_IO_FN_COUNT 16
#define BRICK_IO_FN_LAST  (BRICK_IO_FN_FIRST + BRICK_IO_FN_COUNT - 1)

#define BRICK_IO_FN_FILE_SIZE   (BRICK_IO_FN_FIRST + 0)  /* (const char *path): the file's size; E_NOEXS none, E_OBJ a directory */
#define BRICK_IO_FN_FILE_READ   (BRICK_IO_FN_FIRST + 1)  /* (path, uint_t offset, void *buf, uint_t len): returns bytes read */
#define BRICK_IO_FN_DIR_OPEN    (BRICK_IO_FN_FIRST + 2)  /* (const char *path): a directory ID 1..BRICK_IO_MAX_DIRS; E_NOMEM none free */
#define BRICK_IO_FN_DIR_READ    (BRICK_IO_FN_FIRST + 3)  /* (ID, fileinfo_t *out): the next entry; E_NOEXS at the end, E_ID bad ID */
#define BRICK_IO_FN_DIR_CLOSE   (BRICK_IO_FN_FIRST + 4)  /* (ID): E_ID if not open */
#define BRICK_IO_FN_SERIAL_WRITE (BRICK_IO_FN_FIRST + 5) /* (serial_port_t, const void *buf, uint_t len): bytes taken, 0 full; len 0: E_OBJ unless connected */
#define BRICK_IO_FN_SERIAL_READ (BRICK_IO_FN_FIRST + 6)  /* (serial_port_t, void *buf, uint_t len): returns bytes, 0 none yet, E_OBJ at end */
#define BRICK_IO_FN_SPP_CONNECT (BRICK_IO_FN_FIRST + 7)  /* (const uint8_t addr[6], const char *pin): starts the SPP master's connection attempt; E_OK (at once if connected), E_CTX while one is under way */
#define BRICK_IO_FN_SPP_CONNECTING (BRICK_IO_FN_FIRST + 8) /* (): 1 while the attempt is under way, else 0 */
#define BRICK_IO_FN_SPP_RESET   (BRICK_IO_FN_FIRST + 9)  /* (): closes the SPP master's link, ends an attempt: idle */

/* The Bluetooth SPP master link (the brick connects to a remote slave,
 * SIO_PORT_SPP_MASTER_TEST): a port of the serial service calls beyond
 * serial_port_t's, so that apps never see it among EV3_SERIAL_*. */
#define BRICK_IO_SERIAL_SPP_MASTER ((serial_port_t)4)
#define BRICK_IO_SERIAL_LAST       BRICK_IO_SERIAL_SPP_MASTER

/* A Bluetooth PIN code has 1 to 16 bytes (Bluetooth Core Specification,
 * Vol 3 Part C, "Bluetooth PIN"). */
#define BRICK_IO_MAX_PIN 16U

#define BRICK_IO_MAX_DIRS       8U   /* directories open at once */
#define BRICK_IO_MAX_PATH       (TMAX_FILENAME_LEN + 1)   /* bytes of a path with its NUL */
#define BRICK_IO_MAX_XFER       4096U                     /* bytes per read or write call */

static inline ER_UINT brick_io_file_size(const char *path)
{
	return cal_svc(BRICK_IO_FN_FILE_SIZE, (intptr_t)path, 0, 0, 0, 0);
}

static inline ER_UINT brick_io_file_read(const char *path, uint_t offset, void *buf, uint_t len)
{
	return cal_svc(BRICK_IO_FN_FILE_READ, (intptr_t)path, (intptr_t)offset, (intptr_t)buf, (intptr_t)len, 0);
}

static inline ER_ID brick_io_dir_open(const char *path)
{
	return (ER_ID)cal_svc(BRICK_IO_FN_DIR_OPEN, (intptr_t)path, 0, 0, 0, 0);
}

static inline ER brick_io_dir_read(ID dirid, fileinfo_t *out)
{
	return (ER)cal_svc(BRICK_IO_FN_DIR_READ, (intptr_t)dirid, (intptr_t)out, 0, 0, 0);
}

static inline ER brick_io_dir_close(ID dirid)
{
	return (ER)cal_svc(BRICK_IO_FN_DIR_CLOSE, (intptr_t)dirid, 0, 0, 0, 0);
}

static inline ER_UINT brick_io_serial_write(serial_port_t port, const void *buf, uint_t len)
{
	return cal_svc(BRICK_IO_FN_SERIAL_WRITE, (intptr_t)port, (intptr_t)buf, (intptr_t)len, 0, 0);
}

static inline ER_UINT brick_io_serial_read(serial_port_t port, void *buf, uint_t len)
{
	return cal_svc(BRICK_IO_FN_SERIAL_READ, (intptr_t)port, (intptr_t)buf, (intptr_t)len, 0, 0);
}

static inline ER brick_io_spp_connect(const uint8_t addr[6], const char *pin)
{
	return (ER)cal_svc(BRICK_IO_FN_SPP_CONNECT, (intptr_t)addr, (intptr_t)pin, 0, 0, 0);
}

static inline ER_UINT brick_io_spp_connecting(void)
{
	return cal_svc(BRICK_IO_FN_SPP_CONNECTING, 0, 0, 0, 0, 0);
}

static inline ER brick_io_spp_reset(void)
{
	return (ER)cal_svc(BRICK_IO_FN_SPP_RESET, 0, 0, 0, 0, 0);
}

#ifdef __cplusplus
}
#endif

#endif /* EV3API_BRICK_IO_H */
