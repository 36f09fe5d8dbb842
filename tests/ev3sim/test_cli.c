/*
 * test_cli.c — ev3sim's command line: --help for each command, exit status 2
 * with a message naming the problem for every kind of bad input, the motor
 * and sensors applications' output, and the balance run's files (CSV, serial
 * log, VCD, PNG when gnuplot is installed).
 */
#include "ev3sim_test.h"
#include <sys/stat.h>
#include "ev3sim/balance_run.h"
#include "ev3sim/plot.h"

static struct et_run run;

static void test_help(void)
{
	const char *top[] = { "--help", NULL };
	const char *none[] = { NULL };
	const char *bal[] = { "balance", "--help", NULL };
	const char *mot[] = { "motor", "--help", NULL };
	const char *sen[] = { "sensors", "-h", NULL };

	et_run(&run, top);
	ok(run.status == 0 && strstr(run.out, "balance") && strstr(run.out, "sensors"),
	   "ev3sim --help lists the commands");
	et_run(&run, none);
	ok(run.status == 2 && strstr(run.err, "usage:"), "no command: usage on stderr, status 2");
	et_run(&run, bal);
	ok(run.status == 0 && strstr(run.out, "--logger-hz") && strstr(run.out, "--fault") &&
	   strstr(run.out, "--plot"), "balance --help documents its options");
	et_run(&run, mot);
	ok(run.status == 0 && strstr(run.out, "--port") && strstr(run.out, "--speed"),
	   "motor --help documents its options");
	et_run(&run, sen);
	ok(run.status == 0 && strstr(run.out, "--in1") && strstr(run.out, "--outA"),
	   "sensors -h documents its options");
}

/* A bad command line: status 2 and a message containing what. */
static void bad(const char *const *args, const char *what, const char *name)
{
	et_run(&run, args);
	ok(run.status == 2 && strstr(run.err, what) != NULL, "%s: status 2, message names '%s'", name, what);
	if (run.status != 2 || strstr(run.err, what) == NULL)
		tap_diag("status %d, stderr: %s", run.status, run.err);
	ok(run.out[0] == '\0', "%s: nothing on stdout", name);
}

static void test_bad_input(void)
{
	bad((const char *[]){ "dance", NULL }, "unknown command 'dance'", "unknown command");
	bad((const char *[]){ "balance", "--frobnicate", NULL }, "unknown option --frobnicate", "unknown option");
	bad((const char *[]){ "balance", "--seconds", NULL }, "--seconds needs a value", "missing value");
	bad((const char *[]){ "balance", "--seconds", "0", NULL }, "--seconds: bad value '0'", "zero seconds");
	bad((const char *[]){ "balance", "--seconds=abc", NULL }, "--seconds: bad value 'abc'", "--opt=value form");
	bad((const char *[]){ "balance", "--seconds", "4000", NULL }, "bad value '4000'", "too long");
	bad((const char *[]){ "balance", "--logger-hz", "1001", NULL }, "--logger-hz: bad value", "logger rate");
	bad((const char *[]){ "balance", "--logger-hz", "-5", NULL }, "--logger-hz: bad value", "negative rate");
	bad((const char *[]){ "balance", "--seed", "x1", NULL }, "--seed: bad value", "bad seed");
	bad((const char *[]){ "balance", "--push", "5", NULL }, "--push: bad value '5'", "push without torque");
	bad((const char *[]){ "balance", "--push", "5:9", NULL }, "--push: bad value '5:9'", "push too strong");
	bad((const char *[]){ "balance", "--push", "5q:0.1", NULL }, "--push: bad value", "push bad time");
	bad((const char *[]){ "balance", "--fault", "meteor:1", NULL }, "unknown fault kind 'meteor'", "unknown fault");
	bad((const char *[]){ "balance", "--fault", "uart-bit-errors:2", NULL }, "missing or bad value",
	    "probability above 1");
	bad((const char *[]){ "balance", "--fault", "encoder-noise:E:5", NULL }, "bad port 'E'", "fault port");
	bad((const char *[]){ "balance", "--fault", "unplug:2:5s:1s:9", NULL }, "too many fields",
	    "fault with extra fields");
	bad((const char *[]){ "balance", "--tilt", "50", NULL }, "--tilt: bad value", "tilt too big");
	bad((const char *[]){ "balance", "--log-baud", "10", NULL }, "--log-baud: bad value", "baud too low");
	bad((const char *[]){ "balance", "stray", NULL }, "unexpected argument 'stray'", "stray argument");
	bad((const char *[]){ "motor", "--port", "E", NULL }, "--port: bad value 'E'", "motor port");
	bad((const char *[]){ "motor", "--speed", "101", NULL }, "bad value '101'", "speed range");
	bad((const char *[]){ "motor", "--speed", "2.5", NULL }, "bad value '2.5'", "fractional speed");
	bad((const char *[]){ "motor", "--speed", "5", "--power", "5", NULL }, "exclude each other",
	    "speed and power");
	bad((const char *[]){ "motor", "--kind", "huge", NULL }, "--kind: bad value 'huge'", "motor kind");
	bad((const char *[]){ "motor", "--every", "0", NULL }, "--every: bad value '0'", "zero period");
	bad((const char *[]){ "sensors", "--in5", "gyro", NULL }, "unknown option --in5", "input port 5");
	bad((const char *[]){ "sensors", "--in1", "lidar", NULL }, "bad input device 'lidar'", "input device");
	bad((const char *[]){ "sensors", "--outE", "large", NULL }, "unknown option --outE", "output port E");
	bad((const char *[]){ "sensors", "--outA", "gyro", NULL }, "bad output device 'gyro'", "output device");
}

static void test_motor(void)
{
	const char *args[] = { "motor", "--port", "B", "--speed", "50", "--seconds", "1", "--every", "250", NULL };
	char line[512];

	ok(et_run(&run, args) && run.status == 0, "motor --port B --speed 50 --seconds 1 runs");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(strstr(run.out, "# t_s  speed_pct  counts_deg") != NULL, "rows have a header");
	ok(strstr(run.out, "  1.000    ") != NULL, "a row at 1.000 s");
	ok(strstr(line, "port=B kind=large mode=speed value=50 seconds=1 ") == line, "summary names the run");
	ok(et_number(line, "final_speed_pct") >= 45 && et_number(line, "final_speed_pct") <= 55,
	   "the regulated speed reaches 50 %% (%g)", et_number(line, "final_speed_pct"));
	/* 50 % of the large motor's 1050 deg/s, after a short start-up */
	ok(et_number(line, "counts") > 400 && et_number(line, "counts") < 560,
	   "counts after 1 s match about 525 deg/s (%g)", et_number(line, "counts"));
	is_int(et_number(line, "api_errors"), 0, "no API errors");

	{
		const char *rev[] = { "motor", "--port", "C", "--kind", "medium", "--power", "-60", "--seconds",
				      "0.5", NULL };

		ok(et_run(&run, rev) && run.status == 0, "a medium motor at power -60 runs");
		et_last_line(&run, line, sizeof(line));
		ok(et_number(line, "counts") < -100, "and turns backwards (%g)", et_number(line, "counts"));
	}
}

static void test_sensors(void)
{
	const char *args[] = { "sensors", "--seconds", "1", "--in3", "ir", "--outC", "medium", NULL };
	char line[1024];

	ok(et_run(&run, args) && run.status == 0, "sensors with an IR sensor on 3 and a medium motor on C");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(strstr(run.out, "in1  touch      InConn=121 INPUT_DUMB") != NULL, "d_analog: touch is an EV3 dumb input");
	ok(strstr(run.out, "in2  gyro       InConn=122 INPUT_UART") != NULL, "d_analog: the gyro is a UART sensor");
	ok(strstr(run.out, "OutDcm=  7 large motor") != NULL, "OutDcm 7 for the large motor");
	ok(strstr(run.out, "outC medium     OutConn=125 OUTPUT_TACHO OutDcm=  8") != NULL,
	   "OutDcm 8 for the medium motor on C");
	ok(strstr(run.out, "/dev/lms_dcm: in 125 125 125 125, out 7 8 8 7") != NULL, "the DCM device agrees");
	ok(strstr(run.out, "in2 angle=") && strstr(run.out, "in3 prox=") && strstr(run.out, "in4 cm=50"),
	   "live values of the gyro, IR and ultrasonic sensors");
	ok(strstr(run.out, "in1 pressed=1") && strstr(run.out, "in1 pressed=0"), "the touch sensor toggles");
	ok(strstr(line, "in3=ir/INPUT_UART") && strstr(line, "outC=medium/OUTPUT_TACHO"), "summary per port");
	is_int(et_number(line, "api_errors"), 0, "no API errors");
}

/* The NXT I2C sensors on three ports: d_analog calls them NXT IIC, the API reads ev3sim's scene. */
static void test_nxt_iic_sensors(void)
{
	const char *args[] = { "sensors", "--seconds", "1", "--in1", "ht-accel", "--in2", "ht-color",
			       "--in3", "nxt-temp", NULL };
	char line[1024];

	ok(et_run(&run, args) && run.status == 0, "sensors with ht-accel, ht-color, nxt-temp on 1..3");
	et_last_line(&run, line, sizeof(line));
	ok(strstr(run.out, "/dev/lms_dcm: in 123 123 123") != NULL, "d_analog: three NXT IIC devices (123)");
	ok(strstr(run.out, "in1 accel=0,0,200") && strstr(run.out, "in2 ht_color=17") &&
	   strstr(run.out, "in3 temp_c=22.5000"), "live values through the API");
	ok(strstr(line, "in1=ht-accel/NXT_IIC") && strstr(line, "in3=nxt-temp/NXT_IIC"), "summary per port");
	is_int(et_number(line, "api_errors"), 0, "no API errors");
}

static void test_files(void)
{
	char csv[] = "/tmp/ev3sim-test-XXXXXX", log[] = "/tmp/ev3sim-test-XXXXXX",
	     vcd[] = "/tmp/ev3sim-test-XXXXXX", png[] = "/tmp/ev3sim-test-XXXXXX";
	const char *args[] = { "balance", "--seconds", "1", "--csv", csv, "--log", log, "--trace", vcd,
			       "--no-progress", NULL };
	char buf[256];
	FILE *f;

	close(mkstemp(csv));
	close(mkstemp(log));
	close(mkstemp(vcd));
	close(mkstemp(png));
	ok(et_run(&run, args) && run.status == 0, "balance with --csv, --log and --trace");
	if (run.status != 0)
		tap_diag("status %d, stderr: %s", run.status, run.err);
	f = fopen(csv, "r");
	ok(f && fgets(buf, sizeof(buf), f) && strncmp(buf, "t_s,tilt_deg,", 13) == 0, "CSV header");
	ok(f && fgets(buf, sizeof(buf), f) && strncmp(buf, "0.000,0.5000,", 13) == 0,
	   "first row at the release, 0.5 deg tilt");
	if (f)
		fclose(f);
	f = fopen(log, "r");
	ok(f && fgets(buf, sizeof(buf), f) && strchr(buf, ',') && strstr(buf, "\r\n"),
	   "the serial log holds lines 'ms,rate,tilt'");
	if (f)
		fclose(f);
	f = fopen(vcd, "r");
	ok(f && fgets(buf, sizeof(buf), f) && buf[0] == '$', "the trace is a VCD");
	if (f)
		fclose(f);
	if (ev3sim_have_gnuplot()) {
		const char *plot[] = { "balance", "--seconds", "1", "--plot", png, NULL };
		unsigned char sig[8] = { 0 };

		ok(et_run(&run, plot) && run.status == 0, "balance --plot");
		f = fopen(png, "rb");
		ok(f && fread(sig, 1, 8, f) == 8 && memcmp(sig, "\x89PNG\r\n\x1a\n", 8) == 0, "the plot is a PNG");
		if (f)
			fclose(f);
	} else {
		tap_skip(2, "gnuplot is not installed");
	}
	{
		const char *bad_dir[] = { "balance", "--seconds", "1", "--csv", "/nonexistent/dir/x.csv", NULL };

		et_run(&run, bad_dir);
		ok(run.status == 1 && strstr(run.err, "cannot write /nonexistent/dir/x.csv"),
		   "an unwritable CSV path: status 1 and a message");
	}
	unlink(csv);
	unlink(log);
	unlink(vcd);
	unlink(png);
}

/* Outputs that cannot be written: refused before the run (a missing directory), or reported
 * after it with status 1 (a full disk: /dev/full); never a silent success, never PNG bytes on
 * stdout; option values on flags refused. */
static void test_output_errors(void)
{
	static const char *const outputs[] = { "--csv", "--log", "--trace", "--plot" };
	char line[1024];

	for (unsigned i = 0; i < sizeof(outputs) / sizeof(outputs[0]); i++) {
		const char *missing[] = { "balance", "--seconds", "30", outputs[i], "/nonexistent/dir/out",
					  "--no-progress", NULL };
		const char *full[] = { "balance", "--seconds", "1", outputs[i], "/dev/full", "--no-progress",
				       NULL };

		if (!strcmp(outputs[i], "--plot") && !ev3sim_have_gnuplot()) {
			tap_skip(4, "gnuplot is not installed");
			continue;
		}
		ok(et_run(&run, missing) && run.status == 1 && strstr(run.err, "cannot write /nonexistent/dir/out") &&
		   run.out[0] == '\0', "%s in a missing directory: refused before the run, status 1", outputs[i]);
		ok(strchr(run.err, '\n') == strrchr(run.err, '\n') && !strstr(run.err, "BUG"),
		   "%s: one line, no internal report", outputs[i]);
		ok(et_run(&run, full) && run.status == 1 && strstr(run.err, "/dev/full"),
		   "%s /dev/full: the write error is reported, status 1", outputs[i]);
		et_last_line(&run, line, sizeof(line));
		ok(strncmp(line, "result=", 7) == 0 && !memchr(run.out, 0x89, strlen(run.out)),
		   "%s /dev/full: the summary is still there, no PNG bytes on stdout", outputs[i]);
	}
	{
		const char *help[] = { "balance", "--help=1", NULL };
		const char *flag[] = { "balance", "--no-balancer=yes", NULL };

		ok(et_run(&run, help) && run.status == 2 && strstr(run.err, "--help takes no value"),
		   "--help=1 is refused");
		ok(et_run(&run, flag) && run.status == 2 && strstr(run.err, "takes no value"),
		   "a flag with a value is refused");
	}
}

/* Standard output on a full disk: every command reports it and fails, with or without a run. */
static void test_stdout_full(void)
{
	static const char *const cmds[][8] = {
		{ "--help", NULL },
		{ "balance", "--help", NULL },
		{ "motor", "--seconds", "0.2", NULL },
		{ "sensors", "--seconds", "0.2", NULL },
		{ "balance", "--seconds", "0.2", "--no-progress", NULL },
	};

	for (unsigned i = 0; i < sizeof(cmds) / sizeof(cmds[0]); i++) {
		ok(et_run_main(&run, cmds[i], ev3sim_main, "/dev/full") && run.status == 1 &&
		   strstr(run.err, "cannot write the standard output: No space left on device"),
		   "ev3sim %s %s > /dev/full: status 1, the lost output named", cmds[i][0], cmds[i][1]);
		if (run.status != 1)
			tap_diag("status %d, stderr: %s", run.status, run.err);
		ok(strstr(run.err, "standard output") == strrchr(run.err, '\n') - strlen("standard output: No space left "
		   "on device"), "reported once");
	}
}

/* A FIFO nobody reads is refused at once (it would block the open for ever); one with a reader
 * takes the CSV as it streams; an output written later by name refuses a FIFO before the run. */
static void test_fifo_outputs(void)
{
	static const char *const streamed[] = { "--csv", "--log" };
	static const char *const by_name[] = { "--trace", "--plot" };
	char dir[] = "/tmp/ev3sim-fifo-XXXXXX", fifo[64];
	int fd;

	if (!mkdtemp(dir)) {
		tap_skip(2 * 2 + 2 * 2 + 2, "no temporary directory");
		return;
	}
	snprintf(fifo, sizeof(fifo), "%s/fifo", dir);
	if (mkfifo(fifo, 0600) != 0) {
		tap_skip(2 * 2 + 2 * 2 + 2, "cannot make a FIFO");
		rmdir(dir);
		return;
	}
	for (unsigned i = 0; i < 2; i++) {
		const char *args[] = { "balance", "--seconds", "0.2", streamed[i], fifo, NULL };

		ok(et_run(&run, args) && run.status == 1 && strstr(run.err, "a FIFO no process is reading"),
		   "%s to a FIFO without a reader: refused at once, status 1", streamed[i]);
		if (run.status != 1)
			tap_diag("status %d, stderr: %s", run.status, run.err);
		ok(strstr(run.err, fifo) != NULL && run.out[0] == '\0', "%s: the message names the FIFO", streamed[i]);
	}
	for (unsigned i = 0; i < 2; i++) {
		const char *args[] = { "balance", "--seconds", "0.2", by_name[i], fifo, NULL };

		if (!strcmp(by_name[i], "--plot") && !ev3sim_have_gnuplot()) {
			tap_skip(2, "gnuplot is not installed");
			continue;
		}
		ok(et_run(&run, args) && run.status == 1 && strstr(run.err, "cannot write") &&
		   strstr(run.err, ": a FIFO ("), "%s to a FIFO: refused before the run, status 1", by_name[i]);
		ok(strstr(run.err, fifo) != NULL && run.out[0] == '\0', "%s: the message names the FIFO", by_name[i]);
	}
	/* a reader (this test, holding the FIFO's read end): the CSV streams through it */
	if ((fd = et_fifo_reader(fifo)) >= 0) {
		const char *args[] = { "balance", "--seconds", "0.2", "--csv", fifo, "--no-progress", NULL };
		static char csv[65536];
		size_t n;
		unsigned lines = 0;

		ok(et_run(&run, args) && run.status == 0, "--csv to a FIFO with a reader: the run is done");
		n = et_fifo_drain(fd, csv, sizeof(csv));
		for (size_t i = 0; i < n; i++)
			lines += csv[i] == '\n';
		ok(lines == 1 + 201 && strncmp(csv, "t_s,", 4) == 0, "the reader got the header and 201 rows (%u lines)",
		   lines);
		close(fd);
	} else {
		tap_skip(2, "cannot open the FIFO");
	}
	unlink(fifo);
	rmdir(dir);
}

/* --fault as often as the help says ("up to 16"), and once more refused. */
static void test_fault_limit(void)
{
	const char *help[] = { "balance", "--help", NULL };
	const char *args[64] = { "balance", "--seconds", "0.01", "--logger-hz", "0", "--no-progress" };
	unsigned n = 6;

	et_run(&run, help);
	ok(strstr(run.out, "may repeat (up to 16)") != NULL, "balance --help: --fault may repeat up to 16 times");
	for (unsigned i = 0; i < EV3SIM_MAX_FAULTS; i++) {
		args[n++] = "--fault";
		args[n++] = "gyro-drift:0.1";
	}
	args[n] = NULL;
	ok(et_run(&run, args) && run.status == 0, "16 faults are accepted");
	if (run.status != 0)
		tap_diag("status %d, stderr: %s", run.status, run.err);
	args[n++] = "--fault";
	args[n++] = "gyro-drift:0.1";
	args[n] = NULL;
	ok(et_run(&run, args) && run.status == 2 && strstr(run.err, "--fault: more than 16 faults"),
	   "the 17th is refused, naming the limit");
}

int main(void)
{
	tap_plan(5 + 29 * 2 + 9 + 10 + 5 + 8 + 4 * 4 + 2 + 3 + 5 * 2 + 2 * 2 + 2 * 2 + 2);
	test_help();
	test_bad_input();
	test_motor();
	test_sensors();
	test_nxt_iic_sensors();
	test_files();
	test_output_errors();
	test_fault_limit();
	test_stdout_full();
	test_fifo_outputs();
	return tap_done();
}
