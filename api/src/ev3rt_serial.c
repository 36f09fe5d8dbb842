/*
 * ev3rt_serial.c — TOPPERS's serial interface (syssvc/serial.h) on the EV3's
 * ports: the SIO_PORT_* numbers mapped onto the serial ports the API's files
 * use (ev3api_fs.h), over the platform's serial service calls
 * (ev3api_brick_io.h).  Bytes cross the service call through a buffer on the
 * caller's stack, as in ev3rt_fs.c.
 */
#include <string.h>
#include "ev3api_brick_io.h"
#include "syssvc/serial.h"
#include "driver_interface_bluetooth.h"
#include "api_internal.h"

#define CHUNK 256U

/* The modes serial_ctl_por accepts: CRLF and ECHO act, flow control has nothing to do. */
#define IOCTL_KNOWN (IOCTL_ECHO | IOCTL_CRLF | IOCTL_FCSND | IOCTL_FCANY | IOCTL_FCRCV)

static uint_t port_modes[TNUM_PORT + 1];

/* Every port starts in IOCTL_NULL mode at boot. */
void api_serial_boot(void)
{
	memset(port_modes, 0, sizeof(port_modes));
}

/* The API's serial port behind portid, or the error for portid. */
static ER port_of(ID portid, serial_port_t *port)
{
	switch (portid) {
	case SIO_PORT_UART:
		*port = EV3_SERIAL_UART;
		return E_OK;
	case SIO_PORT_BT:
		*port = EV3_SERIAL_BT;
		return E_OK;
	case SIO_PORT_USB_CDC:
		*port = EV3_SERIAL_USB_CDC;
		return E_OK;
	case SIO_PORT_SPP_MASTER_TEST:
		*port = BRICK_IO_SERIAL_SPP_MASTER;
		return E_OK;
	case SIO_PORT_LCD:
		return E_NOSPT;
	default:
		return E_ID;
	}
}

/* The head of every call: task context, a port the platform provides. */
static ER serial_check(ID portid, serial_port_t *port)
{
	ER ercd = api_may_wait();

	return ercd != E_OK ? ercd : port_of(portid, port);
}

/* Sends all of buf (n <= CHUNK), waiting 1 ms at a time while the port is full. */
static ER send_all(serial_port_t port, const char *buf, uint_t n)
{
	uint_t done = 0;

	while (done < n) {
		ER_UINT put = brick_io_serial_write(port, buf + done, n - done);

		if (put < 0)
			return put == E_RSFN ? E_NOSPT : (ER)put;
		if (put == 0)
			dly_tsk(1);
		done += (uint_t)put;
	}
	return E_OK;
}

ER serial_opn_por(ID portid)
{
	serial_port_t port;

	return serial_check(portid, &port);
}

ER serial_cls_por(ID portid)
{
	serial_port_t port;

	return serial_check(portid, &port);
}

ER_UINT serial_rea_dat(ID portid, char *buf, uint_t len)
{
	char chunk[CHUNK];
	serial_port_t port;
	uint_t done = 0;
	ER ercd;

	if ((ercd = serial_check(portid, &port)) != E_OK)
		return ercd;
	if (len > 0 && (buf == NULL || prb_mem(buf, len, TSK_SELF, TPM_WRITE) != E_OK))
		return E_MACV;
	while (done < len) {
		uint_t n = len - done < CHUNK ? len - done : CHUNK;
		ER_UINT got = brick_io_serial_read(port, chunk, n);

		if (got < 0)
			return got == E_RSFN ? E_NOSPT : got;
		if (got == 0) {
			dly_tsk(1);
			continue;
		}
		memcpy(buf + done, chunk, (size_t)got);
		if ((port_modes[portid] & IOCTL_ECHO) && (ercd = send_all(port, chunk, (uint_t)got)) != E_OK)
			return ercd;
		done += (uint_t)got;
	}
	return (ER_UINT)done;
}

ER_UINT serial_wri_dat(ID portid, const char *buf, uint_t len)
{
	char chunk[CHUNK + 1];
	serial_port_t port;
	uint_t done = 0;
	ER ercd;

	if ((ercd = serial_check(portid, &port)) != E_OK)
		return ercd;
	/* read in the caller's domain, as EV3RT's API reads an app's string; the
	 * service checks the stack copy */
	if (len > 0 && buf == NULL)
		return E_MACV;
	while (done < len) {
		uint_t n = 0;

		/* a CR goes before each LF in CRLF mode: at most one more byte per source byte */
		while (done < len && n < CHUNK) {
			if (buf[done] == '\n' && (port_modes[portid] & IOCTL_CRLF))
				chunk[n++] = '\r';
			chunk[n++] = buf[done++];
		}
		if ((ercd = send_all(port, chunk, n)) != E_OK)
			return ercd;
	}
	return (ER_UINT)len;
}

ER serial_ctl_por(ID portid, uint_t ioctl)
{
	serial_port_t port;
	ER ercd;

	if ((ercd = serial_check(portid, &port)) != E_OK)
		return ercd;
	if (ioctl & ~IOCTL_KNOWN)
		return E_PAR;
	port_modes[portid] = ioctl;
	return E_OK;
}

/* EV3RT opens a Bluetooth or USB port when its far end connects and closes
 * it when the far end goes, so the port's state is E_OBJ (not open) while
 * nothing is connected (ev3rt-git/ev3rt-hrp2,
 * target/ev3_gcc/drivers/bluetooth/src/bluetooth_dri.c); the UART's port is
 * open from boot. */
ER serial_ref_por(ID portid, T_SERIAL_RPOR *pk_rpor)
{
	serial_port_t port;
	ER ercd;

	if ((ercd = serial_check(portid, &port)) != E_OK || (ercd = API_CHECK_OUT(pk_rpor)) != E_OK)
		return ercd;
	if (port != EV3_SERIAL_UART && brick_io_serial_write(port, NULL, 0) != E_OK)
		return E_OBJ;
	pk_rpor->reacnt = 0;
	pk_rpor->wricnt = 0;
	return E_OK;
}

/* Starts an SPP master connection attempt; the address and PIN are read in
 * the caller's domain and cross the service call as copies on the stack,
 * as serial_wri_dat's bytes do. */
static ER spp_start(const uint8_t addr[6], const char *pin)
{
	uint8_t addr_copy[6];
	char pin_copy[BRICK_IO_MAX_PIN + 1];
	size_t n;
	ER ercd;

	if (addr == NULL || pin == NULL)
		return E_MACV;
	for (n = 0; n <= BRICK_IO_MAX_PIN && pin[n] != '\0'; n++)
		continue;
	if (n == 0 || n > BRICK_IO_MAX_PIN)
		return E_PAR;
	memcpy(addr_copy, addr, sizeof(addr_copy));
	memcpy(pin_copy, pin, n + 1);
	ercd = brick_io_spp_connect(addr_copy, pin_copy);
	return ercd == E_RSFN ? E_NOSPT : ercd;
}

/* EV3RT starts the attempt and waits for its end 10 ms at a time
 * (bluetooth_dri.c's _spp_master_test_connect). */
ER spp_master_test_connect(const uint8_t addr[6], const char *pin)
{
	ER_UINT connecting;
	ER ercd;

	if ((ercd = api_may_wait()) != E_OK || (ercd = spp_start(addr, pin)) != E_OK)
		return ercd;
	while ((connecting = brick_io_spp_connecting()) > 0)
		dly_tsk(10);
	return connecting < 0 ? (ER)connecting : E_OK;
}

/* EV3RT 1.x's SPP master (the HRP3 profile's ev3api_fs.h declares these for
 * apps; the library is built once for both profiles). */
ER ev3_spp_master_reset(void);
ER ev3_spp_master_connect(const uint8_t *addr, const char *pin, const char *service);
bool_t ev3_spp_master_is_connected(void);

ER ev3_spp_master_reset(void)
{
	ER ercd = api_may_wait();

	if (ercd != E_OK)
		return ercd;
	ercd = brick_io_spp_reset();
	return ercd == E_RSFN ? E_NOSPT : ercd;
}

/* EV3RT 1.x starts the attempt and returns; a master that is not idle
 * (connecting, or connected) refuses with E_CTX.  Every service has the
 * name ev3sim's slave is reached by: the name is read, not matched. */
ER ev3_spp_master_connect(const uint8_t *addr, const char *pin, const char *service)
{
	ER ercd;

	if ((ercd = api_may_wait()) != E_OK)
		return ercd;
	if (service == NULL)
		return E_MACV;
	if (ev3_spp_master_is_connected() || brick_io_spp_connecting() > 0)
		return E_CTX;
	return spp_start(addr, pin);
}

bool_t ev3_spp_master_is_connected(void)
{
	T_SERIAL_RPOR rpor;

	return serial_ref_por(SIO_PORT_SPP_MASTER_TEST, &rpor) == E_OK;
}
