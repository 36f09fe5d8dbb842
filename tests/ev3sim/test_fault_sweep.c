/*
 * test_fault_sweep.c — a short version of the reliability sweep
 * (docs/reliability.md): `ev3sim balance` under heavy corruption of the gyro's
 * UART stream — bit errors, dropped and duplicated bytes, and the 50 % bit
 * error rate that used to overrun d_uart's message buffer — always finishes
 * with exit status 0 and an honest summary: the robot may fall, but the
 * driver's link counters say why (errors and resynchronisations counted, valid
 * frames still received) and no kernel bug is reported.
 */
#include "ev3sim_test.h"

static struct et_run run;

static void sweep(const char *fault, const char *seed, bool must_stay_up)
{
	const char *secs = et_seconds("20", "8", "2");
	const char *args[] = { "balance", "--seconds", secs, "--seed", seed, "--fault", fault, NULL };
	char line[1024];
	double frames, errors, resyncs;

	ok(et_run(&run, args) && run.status == 0, "--fault %s --seed %s: finished, status 0", fault, seed);
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	frames = et_number(line, "gyro_frames");
	errors = et_number(line, "gyro_check_errors") + et_number(line, "gyro_size_errors");
	resyncs = et_number(line, "gyro_resyncs");
	ok(frames > 0 && errors > 0, "the summary counts frames (%g) and errors (%g)", frames, errors);
	is_int(resyncs, errors, "every error lost sync once and resynchronised");
	is_int(et_number(line, "bugs"), 0, "no bug reports from the stack");
	if (must_stay_up)
		ok(strncmp(line, "result=upright ", 15) == 0, "upright through it");
	else
		ok(strncmp(line, "result=", 7) == 0, "a result either way (%.13s)", line);
}

int main(void)
{
	tap_plan(25);
	sweep("uart-bit-errors:0.001", "3", true);
	sweep("uart-bit-errors:0.01", "5", true);
	sweep("uart-bit-errors:0.5", "1", false);
	sweep("uart-drop:0.05", "2", false);
	sweep("uart-dup:0.05", "4", true);
	return tap_done();
}
