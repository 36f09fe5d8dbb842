/*
 * test_ev3rt_fs.c — EV3RT's file and serial groups as EV3RT apps use them:
 * a resource read from the SD card with ev3_memfile_load, the card's
 * directory listed with ev3_sdcard_*, a report written and a command read
 * with stdio on ev3_serial_open_file — over ev3sim's card (a host directory
 * the app cannot leave) and serial port (a host file, then a
 * pseudo-terminal).
 */
#define _XOPEN_SOURCE 700
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "api_test.h"
#include "text_files_test.h"
#include "ev3api_brick_io.h"
#include "ev3sim/brick_io.h"

#define BIG_SIZE 3000U      /* several of the API's transfer chunks */

static char dir[64], card[96], serial_out[96];
static fileinfo_t global_info;  /* outside the app's domain */
static char line_buf[16];       /* outside it too */

static void make_card(void)
{
	char path[256], big[BIG_SIZE];

	snprintf(dir, sizeof(dir), "/tmp/ev3rt_fs_XXXXXX");
	tf_make_scratch_dir(dir);
	snprintf(card, sizeof(card), "%s/card", dir);
	snprintf(serial_out, sizeof(serial_out), "%s/serial.txt", dir);
	mkdir(card, 0755);
	snprintf(path, sizeof(path), "%s/ev3rt", card);
	mkdir(path, 0755);
	snprintf(path, sizeof(path), "%s/ev3rt/res", card);
	mkdir(path, 0755);
	tf_put_file(card, "ev3rt/res/hello.txt", "hello, brick\n", 13);
	tf_put_file(card, "ev3rt/res/empty.txt", "", 0);
	tf_put_file(card, "ev3rt/res/.hidden", "h", 1);
	for (unsigned i = 0; i < BIG_SIZE; i++)
		big[i] = (char)(i * 7 + 3);
	tf_put_file(card, "ev3rt/res/big.bin", big, BIG_SIZE);
	snprintf(path, sizeof(path), "%s/secret.txt", dir);     /* beside the card, not on it */
	FILE *f = fopen(path, "w");
	if (f == NULL || fputs("secret\n", f) < 0 || fclose(f) != 0)
		tap_bail_out(path);
	snprintf(path, sizeof(path), "%s/escape", card);        /* a link out of the card */
	if (symlink("..", path) != 0)
		tap_bail_out("symlink");
}

/* ---- files and directories ---- */

static void files_body(void)
{
	memfile_t memfile;
	fileinfo_t info;
	bool seen_hello = false, seen_res = false, seen_hidden = false;
	unsigned entries = 0;
	ER_ID dirid, ids[BRICK_IO_MAX_DIRS];
	ER ercd;

	is_int(ev3_memfile_load("/ev3rt/res/hello.txt", &memfile), E_OK, "memfile_load a resource");
	is_int(memfile.filesz, 13, "filesz");
	is_int(memfile.buffersz, 13, "buffersz");
	ok(memfile.buffer != NULL && memcmp(memfile.buffer, "hello, brick\n", 13) == 0, "the file's bytes");
	is_int(ev3_memfile_free(&memfile), E_OK, "memfile_free");
	ok(memfile.buffer == NULL, "free clears the buffer");
	is_int(ev3_memfile_free(&memfile), E_OK, "freeing twice is harmless");

	is_int(ev3_memfile_load("/ev3rt/res/big.bin", &memfile), E_OK, "a 3000-byte file");
	bool same = memfile.filesz == BIG_SIZE;
	for (unsigned i = 0; same && i < BIG_SIZE; i++)
		same = ((const uint8_t *)memfile.buffer)[i] == (uint8_t)(i * 7 + 3);
	ok(same, "every byte of it, across the transfer chunks");
	ev3_memfile_free(&memfile);
	is_int(ev3_memfile_load("ev3rt/./res//empty.txt", &memfile), E_OK, "an empty file, relative path");
	ok(memfile.filesz == 0 && memfile.buffer != NULL, "size 0, a buffer to free");
	ev3_memfile_free(&memfile);
	is_int(ev3_memfile_load("/ev3rt/../ev3rt/res/hello.txt", &memfile), E_OK, ".. inside the card");
	ev3_memfile_free(&memfile);

	/* errors: clear codes, nothing loaded */
	is_int(ev3_memfile_load("/ev3rt/res/none.txt", &memfile), E_NOEXS, "a missing file: E_NOEXS");
	ok(memfile.buffer == NULL && memfile.filesz == 0, "nothing loaded");
	is_int(ev3_memfile_load("/ev3rt/res", &memfile), E_OBJ, "a directory: E_OBJ");
	is_int(ev3_memfile_load("/../secret.txt", &memfile), E_PAR, "above the root: E_PAR");
	is_int(ev3_memfile_load("/ev3rt/../../secret.txt", &memfile), E_PAR, "climbing out: E_PAR");
	is_int(ev3_memfile_load("/escape/secret.txt", &memfile), E_PAR, "out through a link: E_PAR");
	is_int(ev3_memfile_load("", &memfile), E_PAR, "an empty path: E_PAR");
	is_int(ev3_memfile_load(NULL, &memfile), E_MACV, "a NULL path: E_MACV");
	is_int(ev3_memfile_load("/ev3rt/res/hello.txt", NULL), E_MACV, "a NULL memfile: E_MACV");
	memset(line_buf, 0, sizeof(line_buf));
	is_int(brick_io_file_size(line_buf), E_MACV, "the service itself: a path outside the domain, E_MACV");
	is_int(brick_io_file_read("/ev3rt/res/hello.txt", 0, line_buf, 4), E_MACV,
	       "the service itself: a buffer outside the domain, E_MACV");
	is_int(ev3_memfile_free(NULL), E_MACV, "free(NULL): E_MACV");

	/* the directory, as EV3RT's file browser lists it */
	dirid = ev3_sdcard_opendir("/ev3rt/res");
	ok(dirid > 0, "opendir /ev3rt/res (%d)", (int)dirid);
	while ((ercd = ev3_sdcard_readdir(dirid, &info)) == E_OK) {
		entries++;
		if (strcmp(info.name, "hello.txt") == 0)
			seen_hello = info.size == 13 && !info.is_dir && !info.is_hidden && info.date != 0;
		if (strcmp(info.name, ".hidden") == 0)
			seen_hidden = info.is_hidden;
	}
	is_int(ercd, E_NOEXS, "the end of the directory: E_NOEXS");
	is_int(entries, 4, "four entries (no . or ..)");
	ok(seen_hello, "hello.txt: its size, a file, not hidden, dated");
	ok(seen_hidden, ".hidden is hidden");
	is_int(ev3_sdcard_readdir(dirid, &global_info), E_MACV, "readdir into another domain: E_MACV");
	is_int(ev3_sdcard_readdir(dirid, NULL), E_MACV, "readdir into NULL: E_MACV");
	is_int(ev3_sdcard_closedir(dirid), E_OK, "closedir");
	is_int(ev3_sdcard_readdir(dirid, &info), E_ID, "readdir after close: E_ID");
	is_int(ev3_sdcard_closedir(dirid), E_ID, "closing twice: E_ID");
	is_int(ev3_sdcard_closedir(99), E_ID, "closedir of a bad ID: E_ID");
	dirid = ev3_sdcard_opendir("/");
	while (ev3_sdcard_readdir(dirid, &info) == E_OK)
		if (strcmp(info.name, "ev3rt") == 0)
			seen_res = info.is_dir;
	ok(seen_res, "the root lists /ev3rt as a directory");
	ev3_sdcard_closedir(dirid);
	is_int(ev3_sdcard_opendir("/nowhere"), E_NOEXS, "opendir of nothing: E_NOEXS");
	is_int(ev3_sdcard_opendir("/ev3rt/res/hello.txt"), E_OBJ, "opendir of a file: E_OBJ");
	is_int(ev3_sdcard_opendir("/.."), E_PAR, "opendir above the root: E_PAR");
	for (unsigned i = 0; i < BRICK_IO_MAX_DIRS; i++)
		ids[i] = ev3_sdcard_opendir("/");
	is_int(ev3_sdcard_opendir("/"), E_NOMEM, "every directory slot in use: E_NOMEM");
	for (unsigned i = 0; i < BRICK_IO_MAX_DIRS; i++)
		ev3_sdcard_closedir(ids[i]);
}

/* ---- serial: a report to a file ---- */

static void serial_file_body(void)
{
	FILE *uart = ev3_serial_open_file(EV3_SERIAL_DEFAULT);
	char line[32];

	ok(uart != NULL, "the default serial port opens");
	ok(ev3_serial_open_file(EV3_SERIAL_DEFAULT) == uart, "the same stream every time");
	ok(ev3_serial_open_file(EV3_SERIAL_UART) != NULL, "the sensor-port UART opens");
	if (uart == NULL)
		return;
	fprintf(uart, "battery %d mV\n", 8000);
	fputs("done\n", ev3_serial_open_file(EV3_SERIAL_UART));
	fflush(uart);   /* stdio's rule between writing and reading a stream */
	ok(fgets(line, sizeof(line), uart) == NULL, "reading a file port finds its end");
	{
		FILE *bt = ev3_serial_open_file(EV3_SERIAL_BT);

		ok(bt != NULL, "Bluetooth: a stream, as EV3RT always gives");
		ok(bt != NULL && fprintf(bt, "lost\n") == 5, "writing to Bluetooth without a peer takes the bytes");
		ok(ev3_serial_open_file(EV3_SERIAL_USB_CDC) != NULL, "USB CDC: a stream");
	}
	ok(!ev3_bluetooth_is_connected(), "Bluetooth is never connected");
	ok(ev3_serial_open_file((serial_port_t)7) == NULL, "a bad port: NULL");
}

/* ---- serial: a command over a pseudo-terminal ---- */

static char command[32];

static void serial_pty_body(void)
{
	FILE *uart = ev3_serial_open_file(EV3_SERIAL_UART);
	char line[32] = "";
	uint64_t t0 = at_now_ms();

	if (uart == NULL || fgets(line, sizeof(line), uart) == NULL)
		line[0] = '\0';
	strcpy(command, line);
	ok(at_now_ms() - t0 < 100, "the line arrives without waiting long");
	if (uart)
		/* cppcheck-suppress IOWithoutPositioning ; as EV3RT apps do: the serial stream is unbuffered and not seekable */
		fprintf(uart, "ack %s", line);
}

static void no_card_body(void)
{
	memfile_t memfile;

	is_int(ev3_memfile_load("/a.txt", &memfile), E_OBJ, "without a card: E_OBJ");
	{
		FILE *uart = ev3_serial_open_file(EV3_SERIAL_DEFAULT);

		ok(uart != NULL, "without a far end: still a stream");
		ok(uart != NULL && fputs("lost\n", uart) >= 0, "what is written to it is lost, not an error");
	}
}

int main(void)
{
	char err[256], got[128] = "", slave[64];
	FILE *f;
	int master;
	ssize_t n;

	make_card();
	at_include(&brick_io_cfg);

	is_int(brick_io_setup(card, serial_out, err, sizeof(err)), E_OK, "ev3sim's card and serial file");
	ok(at_run(NULL, files_body, 1, 20), "the files app ran");
	ok(at_run(NULL, serial_file_body, 1, 20), "the serial-file app ran");
	brick_io_teardown();
	f = fopen(serial_out, "r");
	if (f != NULL) {
		n = (ssize_t)fread(got, 1, sizeof(got) - 1, f);
		got[n > 0 ? n : 0] = '\0';
		fclose(f);
	}
	is_str(got, "battery 8000 mV\ndone\n", "the host file holds what the app wrote");

	master = posix_openpt(O_RDWR | O_NOCTTY);
	if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0 || ptsname(master) == NULL) {
		tap_skip(5, "no pseudo-terminal");
	} else {
		snprintf(slave, sizeof(slave), "%s", ptsname(master));
		is_int(brick_io_setup(NULL, slave, err, sizeof(err)), E_OK, "the serial port on %s", slave);
		ok(write(master, "go 42\n", 6) == 6, "the host sends a command");
		ok(at_run(NULL, serial_pty_body, 1, 20), "the pty app ran");
		brick_io_teardown();
		is_str(command, "go 42\n", "the app read the command line");
		memset(got, 0, sizeof(got));
		fcntl(master, F_SETFL, O_NONBLOCK);
		for (size_t at = 0; at < sizeof(got) - 1 && (n = read(master, got + at, sizeof(got) - 1 - at)) > 0;)
			at += (size_t)n;
		ok(strstr(got, "ack go 42") != NULL, "the host reads the app's answer");
		close(master);
	}

	is_int(brick_io_setup(NULL, NULL, err, sizeof(err)), E_OK, "no card, no port");
	ok(at_run(NULL, no_card_body, 1, 20), "the app without them ran");
	is_int(brick_io_setup("/nonexistent/dir", NULL, err, sizeof(err)), E_OBJ, "a card that is not there");
	ok(strstr(err, "not a directory") != NULL, "is reported (%s)", err);
	brick_io_teardown();
	at_include(NULL);
	tf_remove_tree(dir);
	return tap_done();
}
