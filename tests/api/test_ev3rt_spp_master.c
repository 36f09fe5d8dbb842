/*
 * test_ev3rt_spp_master.c — the brick as Bluetooth SPP master, as EV3RT's
 * platform interface layer gives it to SDK libraries: an attempt with no
 * slave ends after the page timeout and leaves SIO_PORT_SPP_MASTER_TEST
 * closed (E_OBJ); bad arguments are refused; with a slave listening the
 * attempt succeeds after the page answer and the port's stream (fdopen on
 * its file number) carries bytes both ways.  Writes to a serial stream go
 * straight to the port; on other streams they stay the C library's.
 * EV3RT 1.x's form: ev3_spp_master_connect starts an attempt and returns,
 * refusing while the master is not idle; reset closes the link.
 */
#define _GNU_SOURCE
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include "api_test.h"
#include "text_files_test.h"
#include "ev3sim/brick_io.h"
#include "platform_interface_layer.h"
#include "syssvc/serial.h"
#include "target_test.h"

/* The app build renames an app's calls to these (mk/ev3rt_app_fs.syms). */
FILE *ev3rt_fs_fdopen(int fd, const char *mode);
int ev3rt_fs_fprintf(FILE *f, const char *fmt, ...);
int ev3rt_fs_fputs(const char *s, FILE *f);
size_t ev3rt_fs_fwrite(const void *p, size_t size, size_t n, FILE *f);
/* EV3RT 1.x's SPP master and port numbering, which ev3api_fs.h declares
 * for apps built in the HRP3 profile. */
ER ev3_spp_master_reset(void);
ER ev3_spp_master_connect(const uint8_t *addr, const char *pin, const char *service);
bool_t ev3_spp_master_is_connected(void);
FILE *ev3lx_hrp3_ev3_serial_open_file(int port);

static const uint8_t addr[6] = { 0x00, 0x16, 0x53, 0x01, 0x02, 0x03 };
static char dir[64], sock_path[96], got[32];
static SYSTIM took;
static ER ref_after;

static void no_slave_body(void)
{
	T_SERIAL_RPOR rpor;
	SYSTIM t0, t1;

	is_int(serial_ref_por(SIO_PORT_SPP_MASTER_TEST, &rpor), E_OBJ, "before any attempt the port is closed");
	is_int(serial_ref_por(SIO_PORT_BT, &rpor), E_OBJ, "so is SIO_PORT_BT with no PC connected");
	is_int(spp_master_test_connect(addr, ""), E_PAR, "an empty PIN: E_PAR");
	is_int(spp_master_test_connect(addr, "12345678901234567"), E_PAR, "a 17-byte PIN: E_PAR");
	is_int(spp_master_test_connect(NULL, "1234"), E_MACV, "no address: E_MACV");
	is_int(spp_master_test_connect(addr, NULL), E_MACV, "no PIN: E_MACV");
	get_tim(&t0);
	is_int(spp_master_test_connect(addr, "1234"), E_OK, "an attempt with no slave ends with E_OK, as EV3RT's");
	get_tim(&t1);
	took = t1 - t0;
	ref_after = serial_ref_por(SIO_PORT_SPP_MASTER_TEST, &rpor);
}

static FILE *spp_stream;

static void slave_body(void)
{
	T_SERIAL_RPOR rpor;
	SYSTIM t0, t1;

	get_tim(&t0);
	is_int(spp_master_test_connect(addr, "0000"), E_OK, "the attempt with a slave listening: E_OK");
	get_tim(&t1);
	took = t1 - t0;
	is_int(serial_ref_por(SIO_PORT_SPP_MASTER_TEST, &rpor), E_OK, "the port is open: connected");
	is_int(spp_master_test_connect(addr, "0000"), E_OK, "connecting again while connected: E_OK at once");
	spp_stream = ev3rt_fs_fdopen(SIO_PORT_SPP_MASTER_TEST_FILENO, "a+");
	ok(spp_stream != NULL, "fdopen(SIO_PORT_SPP_MASTER_TEST_FILENO) is the spp_stream's stream");
	ok(spp_stream == ev3rt_fs_fdopen(SIO_PORT_SPP_MASTER_TEST_FILENO, "r"), "the same stream every time");
	ok(spp_stream != NULL && ev3rt_fs_fprintf(spp_stream, "SENSOR %d\n", 2) == 9, "fprintf sends 9 bytes");
	ok(spp_stream != NULL && ev3rt_fs_fputs("ab", spp_stream) == 0 && ev3rt_fs_fwrite("cd", 1, 2, spp_stream) == 2,
	   "fputs and fwrite send theirs");
}

static void hrp3_body(void)
{
	SYSTIM t0, t1;

	ok(!ev3_spp_master_is_connected(), "EV3RT 1.x: the master starts idle");
	is_int(ev3_spp_master_connect(addr, "1234", NULL), E_MACV, "no service name: E_MACV");
	get_tim(&t0);
	is_int(ev3_spp_master_connect(addr, "1234", "Serial Port"), E_OK, "connect starts the attempt and returns");
	is_int(ev3_spp_master_connect(addr, "1234", "Serial Port"), E_CTX, "a second while it connects: E_CTX");
	while (!ev3_spp_master_is_connected())
		dly_tsk(10);
	get_tim(&t1);
	took = t1 - t0;
	is_int(ev3_spp_master_connect(addr, "1234", "Serial Port"), E_CTX, "and while connected: E_CTX");
	ok(ev3lx_hrp3_ev3_serial_open_file(3) == ev3rt_fs_fdopen(SIO_PORT_SPP_MASTER_TEST_FILENO, "r"),
	   "port 3 (EV3_SERIAL_SPP_MASTER) is the master's stream");
	ok(ev3lx_hrp3_ev3_serial_open_file(2) == ev3_serial_open_file(EV3_SERIAL_BT), "port 2 is Bluetooth's");
	ok(ev3lx_hrp3_ev3_serial_open_file(4) == NULL, "there is no port 4");
	is_int(ev3_spp_master_reset(), E_OK, "reset: E_OK");
	ok(!ev3_spp_master_is_connected(), "the master is idle again, its link closed");
}

static void answer_body(void)
{
	char line[32] = "";

	ok(spp_stream != NULL && fgets(line, sizeof(line), spp_stream) != NULL, "fgets reads the slave's line");
	strcpy(got, line);
}

/* A listening Unix socket at path (the slave), or -1. */
static int listen_at(const char *path)
{
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	int fd = socket(AF_UNIX, SOCK_STREAM, 0);

	snprintf(sa.sun_path, sizeof(sa.sun_path), "%s", path);
	if (fd >= 0 && (bind(fd, (struct sockaddr *)&sa, sizeof(sa)) != 0 || listen(fd, 1) != 0)) {
		close(fd);
		fd = -1;
	}
	return fd;
}

int main(void)
{
	char err[256], heard[64] = "";
	int srv, peer = -1;
	ssize_t n;
	FILE *plain;

	snprintf(dir, sizeof(dir), "/tmp/ev3_spp_XXXXXX");
	tf_make_scratch_dir(dir);
	snprintf(sock_path, sizeof(sock_path), "%s/slave.sock", dir);
	at_include(&brick_io_cfg);

	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "no card, no serial port");
	is_int(brick_io_bt_master(sock_path, err, sizeof(err)), E_OK, "the slave is to be at %s", sock_path);
	ok(at_run(NULL, no_slave_body, 1, 20), "the app ran with nobody listening");
	ok(took >= 5120 && took < 5140, "the attempt took the page timeout, 5.12 s (%lu ms)", (unsigned long)took);
	is_int(ref_after, E_OBJ, "and the port stays closed");
	brick_io_teardown();

	srv = listen_at(sock_path);
	ok(srv >= 0, "a slave listens");
	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "setup again");
	is_int(brick_io_bt_master(sock_path, err, sizeof(err)), E_OK, "the slave is at %s", sock_path);
	ok(at_run(NULL, slave_body, 1, 20), "the app ran with the slave listening");
	ok(took >= 640 && took < 660, "the attempt took the page answer, 640 ms (%lu ms)", (unsigned long)took);
	peer = srv >= 0 ? accept(srv, NULL, NULL) : -1;
	n = peer >= 0 ? read(peer, heard, sizeof(heard) - 1) : -1;
	heard[n > 0 ? n : 0] = '\0';
	is_str(heard, "SENSOR 2\nabcd", "the slave heard the request");
	ok(peer >= 0 && write(peer, "SENSOR 1\n", 9) == 9, "and answers");
	ok(at_run(NULL, answer_body, 1, 20), "the app ran again, still connected");
	is_str(got, "SENSOR 1\n", "the answer came back");
	brick_io_teardown();
	if (peer >= 0)
		close(peer);
	if (srv >= 0)
		close(srv);

	unlink(sock_path);
	srv = listen_at(sock_path);
	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "setup again");
	is_int(brick_io_bt_master(sock_path, err, sizeof(err)), E_OK, "the slave is at %s", sock_path);
	ok(srv >= 0 && at_run(NULL, hrp3_body, 1, 20), "EV3RT 1.x's SPP master calls ran");
	ok(took >= 640 && took < 660, "connected once the slave answered the page (%lu ms)", (unsigned long)took);
	peer = srv >= 0 ? accept(srv, NULL, NULL) : -1;
	n = peer >= 0 ? read(peer, heard, sizeof(heard)) : -1;
	is_int((int)n, 0, "the slave saw the reset close the link");
	if (peer >= 0)
		close(peer);
	if (srv >= 0)
		close(srv);
	brick_io_teardown();

	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "setup again");
	memset(err, 0, sizeof(err));
	is_int(brick_io_bt_master("/tmp/" "a-socket-path-longer-than-a-unix-socket-address-can-hold-"
				  "0123456789012345678901234567890123456789012345678901234567890123",
				  err, sizeof(err)), E_PAR, "--bt-master with too long a path: E_PAR");
	ok(strstr(err, "--bt-master") != NULL, "named (%s)", err);
	brick_io_teardown();

	plain = tmpfile();
	ok(plain != NULL && ev3rt_fs_fprintf(plain, "%d", 42) == 2 && ev3rt_fs_fputs("x", plain) >= 0 &&
	   ev3rt_fs_fwrite("yz", 1, 2, plain) == 2, "on a plain stream the calls are the C library's");
	if (plain != NULL) {
		char back[8] = "";

		rewind(plain);
		ok(fgets(back, sizeof(back), plain) != NULL && strcmp(back, "42xyz") == 0, "and land in it (%s)", back);
		fclose(plain);
	}
	at_include(NULL);
	tf_remove_tree(dir);
	return tap_done();
}
