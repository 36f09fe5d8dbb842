/*
 * test_ev3rt_bt.c — Bluetooth SPP as EV3RT apps use it, with a PC program
 * at the far end (ev3sim's --bt: a Unix socket): ev3_bluetooth_is_connected
 * follows the peer, ev3_serial_open_file(EV3_SERIAL_BT) and SIO_PORT_BT
 * carry its bytes both ways, and when the peer goes, the app's writes are
 * lost and it is disconnected until another connects.  USB CDC (--usb)
 * the same way.
 */
#define _GNU_SOURCE
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include "api_test.h"
#include "text_files_test.h"
#include "ev3sim/brick_io.h"
#include "syssvc/serial.h"
#include "target_test.h"

static char dir[64], sock_path[96], got_line[32], got_bytes[8];
static bool connected_seen;

static void connected_body(void)
{
	FILE *bt = ev3_serial_open_file(EV3_SERIAL_BT);
	char line[32] = "", bytes[4] = "";

	connected_seen = ev3_bluetooth_is_connected();
	ok(bt != NULL && fgets(line, sizeof(line), bt) != NULL, "the app reads the PC's line");
	strcpy(got_line, line);
	is_int(serial_rea_dat(SIO_PORT_BT, bytes, 3), 3, "and 3 more bytes with serial_rea_dat(SIO_PORT_BT)");
	memcpy(got_bytes, bytes, 3);
	ok(bt != NULL && fprintf(bt, "pong %s", line) > 0, "answers with fprintf");
}

static void alone_body(void)
{
	FILE *bt = ev3_serial_open_file(EV3_SERIAL_BT);
	char line[8];

	ok(bt != NULL && fgets(line, sizeof(line), bt) == NULL && feof(bt),
	   "the peer's leaving ends the stream once, as on EV3RT (an app's read loop ends)");
	connected_seen = ev3_bluetooth_is_connected();
	ok(bt != NULL && fprintf(bt, "nobody hears this\n") > 0, "writing with no peer takes the bytes");
}

static void usb_alone_body(void)
{
	T_SERIAL_RPOR rpor;

	connected_seen = ev3_usb_cdc_is_connected();
	is_int(serial_ref_por(SIO_PORT_USB_CDC, &rpor), E_OBJ, "SIO_PORT_USB_CDC is closed with no PC");
}

static void usb_body(void)
{
	FILE *usb = ev3_serial_open_file(EV3_SERIAL_USB_CDC);
	T_SERIAL_RPOR rpor;
	char line[32] = "";

	connected_seen = ev3_usb_cdc_is_connected();
	is_int(serial_ref_por(SIO_PORT_USB_CDC, &rpor), E_OK, "SIO_PORT_USB_CDC is open with the PC there");
	ok(usb != NULL && fgets(line, sizeof(line), usb) != NULL, "the app reads the PC's line over USB");
	strcpy(got_line, line);
	ok(usb != NULL && fprintf(usb, "pong %s", line) > 0, "answers with fprintf");
}

static int connect_to(const char *path)
{
	struct sockaddr_un addr = { .sun_family = AF_UNIX };
	int fd = socket(AF_UNIX, SOCK_STREAM, 0);

	snprintf(addr.sun_path, sizeof(addr.sun_path), "%s", path);
	if (fd >= 0 && connect(fd, (struct sockaddr *)&addr, sizeof(addr)) != 0) {
		close(fd);
		fd = -1;
	}
	return fd;
}

int main(void)
{
	char err[256], answer[64] = "";
	int pc;
	ssize_t n;

	snprintf(dir, sizeof(dir), "/tmp/ev3_bt_XXXXXX");
	tf_make_scratch_dir(dir);
	snprintf(sock_path, sizeof(sock_path), "%s/bt.sock", dir);
	at_include(&brick_io_cfg);

	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "no card, no serial port");
	is_int(brick_io_bt_listen(sock_path, err, sizeof(err)), E_OK, "Bluetooth listens at %s", sock_path);
	pc = connect_to(sock_path);
	ok(pc >= 0, "the PC program connects");
	ok(pc >= 0 && write(pc, "ping\nabc", 8) == 8, "and sends a line and 3 bytes");
	ok(at_run(NULL, connected_body, 1, 10), "the app ran");
	ok(connected_seen, "ev3_bluetooth_is_connected: true with the PC connected");
	is_str(got_line, "ping\n", "the line arrived");
	ok(memcmp(got_bytes, "abc", 3) == 0, "the bytes arrived");
	n = pc >= 0 ? read(pc, answer, sizeof(answer) - 1) : -1;
	answer[n > 0 ? n : 0] = '\0';
	is_str(answer, "pong ping\n", "the PC reads the answer");
	if (pc >= 0)
		close(pc);

	ok(at_run(NULL, alone_body, 1, 10), "the app ran again after the PC left");
	ok(!connected_seen, "ev3_bluetooth_is_connected: false once the peer is gone");
	brick_io_teardown();
	ok(access(sock_path, F_OK) != 0, "the socket's file is removed at the end");

	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "setup again");
	is_int(brick_io_usb_listen(sock_path, err, sizeof(err)), E_OK, "USB CDC listens at %s", sock_path);
	ok(at_run(NULL, usb_alone_body, 1, 10), "the app ran with no PC on USB");
	ok(!connected_seen, "ev3_usb_cdc_is_connected: false with no PC");
	pc = connect_to(sock_path);
	ok(pc >= 0 && write(pc, "usb\n", 4) == 4, "a PC connects to USB and sends a line");
	ok(at_run(NULL, usb_body, 1, 10), "the app ran with the PC on USB");
	ok(connected_seen, "ev3_usb_cdc_is_connected: true");
	is_str(got_line, "usb\n", "the line arrived on EV3_SERIAL_USB_CDC");
	n = pc >= 0 ? read(pc, answer, sizeof(answer) - 1) : -1;
	answer[n > 0 ? n : 0] = '\0';
	is_str(answer, "pong usb\n", "the PC reads the answer");
	if (pc >= 0)
		close(pc);
	brick_io_teardown();

	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "setup again");
	is_int(brick_io_bt_listen(dir, err, sizeof(err)), E_OBJ, "--bt on a directory: E_OBJ");
	ok(strstr(err, "not a socket") != NULL, "named (%s)", err);
	brick_io_teardown();
	at_include(NULL);
	tf_remove_tree(dir);
	return tap_done();
}
