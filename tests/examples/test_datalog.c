/*
 * test_datalog.c — examples/datalog: settings loaded from ev3sim's SD card
 * (--sd), the resource directory listed, CSV written to the serial port
 * (--serial FILE) at the configured pace; and the runner's --sd/--serial
 * options from the command line.
 */
#define _XOPEN_SOURCE 700
#include <stdlib.h>
#include <sys/stat.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "ev3api_lcd.h"
#include "ev3api_speaker.h"
#include "example_test.h"
#include "text_files_test.h"
#include "stderr_capture.h"

static char dir[64], card[96], serial[96];

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	char path[160], csv[1024];
	unsigned lines = 0;
	int last_t = -1;
	const char *p;

	snprintf(dir, sizeof(dir), "/tmp/ev3_datalog_XXXXXX");
	tf_make_scratch_dir(dir);
	snprintf(card, sizeof(card), "%s/card", dir);
	snprintf(serial, sizeof(serial), "%s/serial.csv", dir);
	snprintf(path, sizeof(path), "%s/ev3rt/res", card);
	mkdir(card, 0755);
	snprintf(csv, sizeof(csv), "%s/ev3rt", card);
	mkdir(csv, 0755);
	mkdir(path, 0755);
	snprintf(path, sizeof(path), "%s/ev3rt/res/datalog.txt", card);
	if (!tf_write_text(path, "samples 4\nperiod_ms 250\n"))
		tap_bail_out(path);

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "datalog";
	o.seconds = 2;
	o.sd_dir = card;
	o.serial_path = serial;
	if (!ok(ex_run(&o, &r), "datalog runs with a card and a serial file"))
		return tap_done();
	ok(ex_logged("datalog: 4 samples every 250 ms") != NULL, "the settings came from the card");
	ok(ex_logged("datalog: file datalog.txt 24 bytes") != NULL, "the directory listing shows the file");
	ok(ex_logged("datalog: done, 4 lines") != NULL, "it finished");
	tf_read_text(serial, csv, sizeof(csv));
	ok(strncmp(csv, "sample,t_ms,enter\n", 18) == 0, "the serial file starts with the CSV header");
	for (p = strchr(csv, '\n'); p != NULL && p[1] != '\0'; p = strchr(p + 1, '\n')) {
		int i, t, e;

		if (sscanf(p + 1, "%d,%d,%d", &i, &t, &e) == 3 && i == (int)lines && e == 0 && t > last_t) {
			if (lines > 0 && (t - last_t < 250 || t - last_t > 260))
				break;
			last_t = t;
			lines++;
		}
	}
	is_int(lines, 4, "four samples 250 ms apart on the serial port");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	/* without a card: the defaults, and the reason logged */
	o.sd_dir = NULL;
	if (ok(ex_run(&o, &r), "datalog runs without a card"))
		ok(ex_logged("datalog: no /ev3rt/res/datalog.txt") != NULL &&
		   ex_logged("datalog: 5 samples every 100 ms") != NULL, "defaults, the reason logged");

	/* the runner's command line (what `ev3sim run APP_DIR` executes) */
	{
		char *good[] = { "run_datalog", "--sd", card, "--serial", serial, "--seconds", "2", "--quiet", NULL };
		char *bad_sd[] = { "run_datalog", "--sd", "/nonexistent/card", NULL };
		char bad_path[128];
		char *bad_serial[] = { "run_datalog", "--serial", bad_path, "--seconds", "1", NULL };
		struct stderr_capture cap;
		const char *msg;
		int status;

		remove(serial);
		is_int(ev3sim_run_main(8, good, "datalog", &ev3rt_app_cfg), 0, "--sd DIR --serial FILE: status 0");
		ok(tf_read_text(serial, csv, sizeof(csv)) > 18 && strstr(csv, "\n3,") != NULL,
		   "the command-line run wrote its CSV");
		stderr_capture_begin(&cap);
		status = ev3sim_run_main(3, bad_sd, "datalog", &ev3rt_app_cfg);
		msg = stderr_capture_end(&cap);
		is_int(status, 2, "--sd of no directory: status 2");
		if (!ok(strstr(msg, "--sd: '/nonexistent/card' is not a directory") != NULL, "...and the message says so"))
			tap_diag("  stderr: %s", msg);
		snprintf(bad_path, sizeof(bad_path), "%s/no/such/dir/serial", dir);
		stderr_capture_begin(&cap);
		status = ev3sim_run_main(5, bad_serial, "datalog", &ev3rt_app_cfg);
		msg = stderr_capture_end(&cap);
		is_int(status, 1, "--serial that cannot be opened: status 1");
		if (!ok(strstr(msg, bad_path) != NULL && strstr(msg, "No such file or directory") != NULL,
			"...and the message names the file and why"))
			tap_diag("  stderr: %s", msg);
	}
	tf_remove_tree(dir);
	return tap_done();
}
