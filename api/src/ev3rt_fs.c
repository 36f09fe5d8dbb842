/*
 * ev3rt_fs.c — EV3RT's file and serial groups (ev3api_fs.h): files and
 * directories of the SD card and stdio streams on the serial ports, over the
 * platform's storage and serial service calls (ev3api_brick_io.h).
 *
 * Data crosses the service calls through buffers on the calling task's stack
 * (its domain may always pass those), so a memfile's heap buffer or libc's
 * stream buffers never need to be in the caller's domain.
 */
#define _GNU_SOURCE     /* fopencookie (glibc and newlib) */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "ev3api_fs.h"
#include "ev3api_brick_io.h"
#include "driver_interface_filesys.h"
#include "api_internal.h"

#define CHUNK 512U      /* bytes per service call through the stack */

/* Service calls nobody provides (the AM1808 link provider has no SD card or
 * serial port model yet): E_NOSPT, as for any unsupported feature. */
static ER provided(ER ercd)
{
	return ercd == E_RSFN ? E_NOSPT : ercd;
}

/*
 * Copies the app's path to the stack for the service call: E_MACV for NULL,
 * E_PAR for an empty path or one longer than TMAX_FILENAME_LEN.  The API runs
 * in the app's domain and reads the path as EV3RT's fopen would; the service
 * checks the copy against the domain.
 */
static ER copy_path(const char *path, char *out)
{
	size_t n;

	if (path == NULL)
		return E_MACV;
	n = strnlen(path, BRICK_IO_MAX_PATH);
	if (n == 0 || n == BRICK_IO_MAX_PATH)
		return E_PAR;
	memcpy(out, path, n + 1);
	return E_OK;
}

/* ---- files ---- */

ER ev3_memfile_load(const char *path, memfile_t *p_memfile)
{
	char name[BRICK_IO_MAX_PATH], chunk[CHUNK];
	ER_UINT size, got;
	uint8_t *buffer;
	ER ercd;

	if ((ercd = api_may_wait()) != E_OK || (ercd = API_CHECK_OUT(p_memfile)) != E_OK)
		return ercd;
	p_memfile->buffer = NULL;
	p_memfile->filesz = p_memfile->buffersz = 0;
	if ((ercd = copy_path(path, name)) != E_OK)
		return ercd;
	size = brick_io_file_size(name);
	if (size < 0) {
		syslog(LOG_ERROR, "ev3_memfile_load: cannot open '%s' (%d)", name, (int)provided((ER)size));
		return provided((ER)size);
	}
	/* from the apps' heap, in the app's domain; an empty file still gets a buffer */
	if ((buffer = api_app_heap_alloc(size > 0 ? (SIZE)size : 1U)) == NULL) {
		syslog(LOG_ERROR, "ev3_memfile_load: out of memory for '%s' (%u bytes)", name, (unsigned)size);
		return E_NOMEM;
	}
	for (uint_t at = 0; at < (uint_t)size; at += (uint_t)got) {
		uint_t want = (uint_t)size - at < CHUNK ? (uint_t)size - at : CHUNK;

		got = brick_io_file_read(name, at, chunk, want);
		if (got <= 0) {     /* the file shrank or vanished under us */
			api_app_heap_free(buffer);
			syslog(LOG_ERROR, "ev3_memfile_load: reading '%s' failed at %u", name, at);
			return got < 0 ? provided((ER)got) : E_OBJ;
		}
		memcpy(buffer + at, chunk, (size_t)got);
	}
	p_memfile->buffer = buffer;
	p_memfile->filesz = p_memfile->buffersz = (uint32_t)size;
	return E_OK;
}

ER ev3_memfile_free(memfile_t *p_memfile)
{
	ER ercd;

	if ((ercd = API_CHECK_OUT(p_memfile)) != E_OK)
		return ercd;
	/* only what ev3_memfile_load gave out is freed (EV3RT frees any pointer: a crash) */
	if (p_memfile->buffer != NULL && (ercd = api_app_heap_free(p_memfile->buffer)) != E_OK)
		return ercd;
	p_memfile->buffer = NULL;
	p_memfile->filesz = p_memfile->buffersz = 0;
	return E_OK;
}

/* ---- directories ---- */

ER_ID ev3_sdcard_opendir(const char *path)
{
	char name[BRICK_IO_MAX_PATH];
	ER ercd;

	if ((ercd = api_may_wait()) != E_OK || (ercd = copy_path(path, name)) != E_OK)
		return ercd;
	return provided(brick_io_dir_open(name));
}

ER ev3_sdcard_readdir(ID dirid, fileinfo_t *p_fileinfo)
{
	ER ercd;

	if ((ercd = api_may_wait()) != E_OK || (ercd = API_CHECK_OUT(p_fileinfo)) != E_OK)
		return ercd;
	return provided(brick_io_dir_read(dirid, p_fileinfo));
}

ER ev3_sdcard_closedir(ID dirid)
{
	ER ercd;

	if ((ercd = api_may_wait()) != E_OK)
		return ercd;
	return provided(brick_io_dir_close(dirid));
}

/* ---- serial ports ---- */

static ssize_t serial_write(void *cookie, const char *buf, size_t len)
{
	serial_port_t port = (serial_port_t)(intptr_t)cookie;
	char chunk[CHUNK];
	size_t done = 0;

	if (api_may_wait() != E_OK)
		return -1;
	while (done < len) {
		uint_t n = len - done < CHUNK ? (uint_t)(len - done) : CHUNK;
		ER_UINT put;

		memcpy(chunk, buf + done, n);
		put = brick_io_serial_write(port, chunk, n);
		if (put < 0)
			return done > 0 ? (ssize_t)done : -1;
		if (put == 0)       /* the far end is not taking bytes yet */
			dly_tsk(1);
		done += (size_t)put;
	}
	return (ssize_t)done;
}

/* Waits (1 ms at a time) until the port has bytes; 0 at the far end's end. */
static ssize_t serial_read(void *cookie, char *buf, size_t len)
{
	serial_port_t port = (serial_port_t)(intptr_t)cookie;
	char chunk[CHUNK];
	uint_t n = len < CHUNK ? (uint_t)len : CHUNK;

	if (api_may_wait() != E_OK)
		return -1;
	for (;;) {
		ER_UINT got = brick_io_serial_read(port, chunk, n);

		if (got > 0) {
			memcpy(buf, chunk, (size_t)got);
			return (ssize_t)got;
		}
		if (got == E_OBJ)
			return 0;
		if (got < 0)
			return -1;
		dly_tsk(1);
	}
}

static FILE *serial_files[BRICK_IO_SERIAL_LAST + 1];

/* The stream of the platform's serial port (any port of the service calls). */
static FILE *serial_stream(serial_port_t port)
{
	static const cookie_io_functions_t io = { .read = serial_read, .write = serial_write };
	FILE *f;

	if (serial_files[port] != NULL) {
		clearerr(serial_files[port]);   /* an end seen earlier is not the end now */
		return serial_files[port];
	}
	f = fopencookie((void *)(intptr_t)port, "r+", io);
	if (f == NULL)
		return NULL;
	setvbuf(f, NULL, _IONBF, 0);
	serial_files[port] = f;
	return f;
}

/* Open once, the same stream ever after; unbuffered, so every fprintf
 * reaches the port when it returns.  Every port gives a stream, connected
 * or not, as EV3RT's does (its sample apps assert it): what is written to a
 * port with no far end is lost, and a read waits for the far end. */
FILE *ev3_serial_open_file(serial_port_t port)
{
	FILE *f;

	if ((unsigned)port > EV3_SERIAL_USB_CDC) {
		api_warn("ev3_serial_open_file", (int)port, E_ID);
		return NULL;
	}
	if ((f = serial_stream(port)) == NULL)
		api_warn("ev3_serial_open_file", (int)port, E_NOMEM);
	return f;
}

/* EV3RT 1.x's numbering (the HRP3 profile's serial_port_t, which binds
 * ev3_serial_open_file here): 3 is the Bluetooth SPP master's port. */
FILE *ev3lx_hrp3_ev3_serial_open_file(int port);

FILE *ev3lx_hrp3_ev3_serial_open_file(int port)
{
	FILE *f;

	if (port < 0 || port > 3) {
		api_warn("ev3_serial_open_file", port, E_ID);
		return NULL;
	}
	if (port != 3)
		return ev3_serial_open_file((serial_port_t)port);
	if ((f = serial_stream(BRICK_IO_SERIAL_SPP_MASTER)) == NULL)
		api_warn("ev3_serial_open_file", port, E_NOMEM);
	return f;
}

/*
 * Writes to a serial stream.  EV3RT's newlib has no stream locks and writes
 * an unbuffered stream straight to its port, so one task may write a
 * serial stream while another waits in a read on the same stream (the
 * SDK's Bluetooth samples do: one task sends requests, another reads the
 * answers).  glibc's stream state is not built for that: a write would
 * take the stream out of the read the other task is in.  So the app's
 * writes to a serial stream go straight to the port here, never through
 * the FILE; on any other stream they are the C library's.  The app build
 * renames the app's calls to these (mk/ev3rt_app_fs.syms).
 */
FILE *ev3rt_fs_fdopen(int fd, const char *mode);
int ev3rt_fs_vfprintf(FILE *f, const char *fmt, va_list ap);
int ev3rt_fs_fprintf(FILE *f, const char *fmt, ...);
int ev3rt_fs___vfprintf_chk(FILE *f, int flag, const char *fmt, va_list ap);
int ev3rt_fs___fprintf_chk(FILE *f, int flag, const char *fmt, ...);
int ev3rt_fs_fputs(const char *s, FILE *f);
int ev3rt_fs_fputc(int c, FILE *f);
int ev3rt_fs_putc(int c, FILE *f);
size_t ev3rt_fs_fwrite(const void *p, size_t size, size_t n, FILE *f);

/* Whether f is one of the serial ports' streams; its port in *port. */
static bool is_serial_stream(const FILE *f, serial_port_t *port)
{
	for (unsigned i = 0; f != NULL && i < sizeof(serial_files) / sizeof(serial_files[0]); i++)
		if (serial_files[i] == f) {
			*port = (serial_port_t)i;
			return true;
		}
	return false;
}

/* Sends len bytes to port as the stream would: len, or EOF if they could not go. */
static int serial_put(serial_port_t port, const char *buf, size_t len)
{
	return len > INT32_MAX || serial_write((void *)(intptr_t)port, buf, len) != (ssize_t)len ? EOF : (int)len;
}

int ev3rt_fs_vfprintf(FILE *f, const char *fmt, va_list ap)
{
	serial_port_t port;
	char small[CHUNK], *text = small;
	va_list again;
	int n;

	if (!is_serial_stream(f, &port))
		return vfprintf(f, fmt, ap);
	va_copy(again, ap);
	n = vsnprintf(small, sizeof(small), fmt, ap);
	if (n >= (int)sizeof(small) && (text = malloc((size_t)n + 1)) != NULL)
		n = vsnprintf(text, (size_t)n + 1, fmt, again);
	va_end(again);
	if (text == NULL) {
		errno = ENOMEM;
		return -1;
	}
	if (n > 0 && serial_put(port, text, (size_t)n) == EOF)
		n = -1;
	if (text != small)
		free(text);
	return n;
}

int ev3rt_fs_fprintf(FILE *f, const char *fmt, ...)
{
	va_list ap;
	int n;

	va_start(ap, fmt);
	n = ev3rt_fs_vfprintf(f, fmt, ap);
	va_end(ap);
	return n;
}

/* _FORTIFY_SOURCE's forms: the flag asks for checks the C library's own
 * form makes; on a serial stream the text is formatted by vsnprintf. */
int ev3rt_fs___vfprintf_chk(FILE *f, int flag, const char *fmt, va_list ap)
{
	(void)flag;
	return ev3rt_fs_vfprintf(f, fmt, ap);
}

int ev3rt_fs___fprintf_chk(FILE *f, int flag, const char *fmt, ...)
{
	va_list ap;
	int n;

	(void)flag;
	va_start(ap, fmt);
	n = ev3rt_fs_vfprintf(f, fmt, ap);
	va_end(ap);
	return n;
}

int ev3rt_fs_fputs(const char *s, FILE *f)
{
	serial_port_t port;

	if (!is_serial_stream(f, &port))
		return fputs(s, f);
	return serial_put(port, s, strlen(s)) == EOF ? EOF : 0;
}

int ev3rt_fs_fputc(int c, FILE *f)
{
	serial_port_t port;
	char byte = (char)c;

	if (!is_serial_stream(f, &port))
		return fputc(c, f);
	return serial_put(port, &byte, 1) == EOF ? EOF : (unsigned char)c;
}

int ev3rt_fs_putc(int c, FILE *f)
{
	return ev3rt_fs_fputc(c, f);
}

size_t ev3rt_fs_fwrite(const void *p, size_t size, size_t n, FILE *f)
{
	serial_port_t port;

	if (!is_serial_stream(f, &port))
		return fwrite(p, size, n, f);
	if (size == 0 || n == 0)
		return 0;
	if (n > SIZE_MAX / size)
		return 0;
	return serial_write((void *)(intptr_t)port, p, size * n) == (ssize_t)(size * n) ? n : 0;
}

/* EV3RT's newlib maps its serial file numbers (driver_interface_filesys.h)
 * to the ports (ev3rt-git/ev3rt-hrp2, target/ev3_gcc/drivers/newlib/src/
 * newlib_dri.c); an app's fdopen on one is that port's stream, on any
 * other number the C library's. */
FILE *ev3rt_fs_fdopen(int fd, const char *mode)
{
	static const serial_port_t filenos[] = {
		[SIO_STD_FILENO] = EV3_SERIAL_DEFAULT,
		[SIO_UART_FILENO] = EV3_SERIAL_UART,
		[SIO_BT_FILENO] = EV3_SERIAL_BT,
		[SIO_PORT_SPP_MASTER_TEST_FILENO] = BRICK_IO_SERIAL_SPP_MASTER,
		[SIO_USB_CDC_FILENO] = EV3_SERIAL_USB_CDC,
	};

	if (fd < SIO_STD_FILENO || fd > SIO_USB_CDC_FILENO)
		return fdopen(fd, mode);
	if (mode == NULL) {
		errno = EINVAL;
		return NULL;
	}
	return serial_stream(filenos[fd]);
}

/* A peer is there when the platform takes a zero-length write on the port. */
bool_t ev3_bluetooth_is_connected(void)
{
	return api_may_wait() == E_OK && brick_io_serial_write(EV3_SERIAL_BT, NULL, 0) == E_OK;
}

bool_t ev3_usb_cdc_is_connected(void)
{
	return api_may_wait() == E_OK && brick_io_serial_write(EV3_SERIAL_USB_CDC, NULL, 0) == E_OK;
}
