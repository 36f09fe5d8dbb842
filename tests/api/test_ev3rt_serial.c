/*
 * test_ev3rt_serial.c — TOPPERS's serial interface (syssvc/serial.h) as
 * EV3RT's sample apps use it: a command read byte by byte with
 * serial_rea_dat and echoed with serial_wri_dat on the sensor-port UART
 * (ev3sim's port on a pseudo-terminal), CRLF mode, the port numbers of
 * target_serial.h, and every error a bad call gets.
 */
#define _DEFAULT_SOURCE     /* cfmakeraw */
#define _XOPEN_SOURCE 700
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>
#include "api_test.h"
#include "ev3sim/brick_io.h"
#include "syssvc/serial.h"
#include "target_test.h"

static char received[16];
static char outside_domain[8];   /* a global: not in the app's domain */

static void echo_body(void)
{
	char buf[8];
	T_SERIAL_RPOR rpor;

	is_int(serial_opn_por(SIO_PORT_UART), E_OK, "the UART port is there (opened at boot)");
	is_int(serial_ctl_por(SIO_PORT_UART, IOCTL_CRLF | IOCTL_FCSND), E_OK, "CRLF mode, flow control accepted");
	is_int(serial_rea_dat(SIO_PORT_UART, buf, 5), 5, "reads exactly the 5 bytes asked for");
	memcpy(received, buf, 5);
	is_int(serial_wri_dat(SIO_PORT_UART, "ok\n", 3), 3, "writes 3 bytes (the CR added is not counted)");
	is_int(serial_ref_por(SIO_PORT_UART, &rpor), E_OK, "the port's state");
	ok(rpor.reacnt == 0 && rpor.wricnt == 0, "nothing left in ev3lx's buffers");

	is_int(serial_wri_dat(0, "x", 1), E_ID, "port 0: E_ID");
	is_int(serial_wri_dat(TNUM_PORT + 1, "x", 1), E_ID, "a port past TNUM_PORT: E_ID");
	is_int(serial_wri_dat(SIO_PORT_LCD, "x", 1), E_NOSPT, "the LCD console: E_NOSPT");
	is_int(serial_rea_dat(SIO_PORT_UART, NULL, 1), E_MACV, "a NULL buffer: E_MACV");
	is_int(serial_rea_dat(SIO_PORT_UART, outside_domain, 1), E_MACV, "a buffer outside the domain: E_MACV");
	is_int(serial_ctl_por(SIO_PORT_UART, 0x8000U), E_PAR, "an unknown mode bit: E_PAR");
	is_int(serial_wri_dat(SIO_PORT_BT, "lost", 4), 4, "Bluetooth without a peer takes the bytes");
	is_int(serial_cls_por(SIO_PORT_UART), E_OK, "closing keeps the platform's port");
}

int main(void)
{
	char err[256], got[64] = "", slave[64];
	int master;
	ssize_t n;

	ok(SIO_PORT_UART == 1 && SIO_PORT_BT == 2 && SIO_PORT_LCD == 3 && SIO_PORT_USB_CDC == 5 && TNUM_PORT == 5,
	   "target_serial.h numbers the ports as EV3RT does");
	at_include(&brick_io_cfg);
	master = posix_openpt(O_RDWR | O_NOCTTY);
	if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0 || ptsname(master) == NULL) {
		tap_skip(18, "no pseudo-terminal");
		return tap_done();
	}
	snprintf(slave, sizeof(slave), "%s", ptsname(master));
	{
		/* a raw line, as a serial link is: no echo, no CR added by the terminal */
		struct termios tio;
		int fd = open(slave, O_RDWR | O_NOCTTY);

		if (fd >= 0 && tcgetattr(fd, &tio) == 0) {
			cfmakeraw(&tio);
			tcsetattr(fd, TCSANOW, &tio);
		}
		if (fd >= 0)
			close(fd);
	}
	is_int(brick_io_setup(NULL, slave, err, sizeof(err)), E_OK, "the serial port on %s", slave);
	ok(write(master, "hello", 5) == 5, "the host sends 5 bytes");
	ok(at_run(NULL, echo_body, 1, 20), "the app ran");
	brick_io_teardown();
	is_str(received, "hello", "the app read them");
	fcntl(master, F_SETFL, O_NONBLOCK);
	for (size_t at = 0; at < sizeof(got) - 1 && (n = read(master, got + at, sizeof(got) - 1 - at)) > 0;)
		at += (size_t)n;
	is_str(got, "ok\r\n", "the host reads the answer, a CR before its LF");
	close(master);
	at_include(NULL);
	return tap_done();
}
