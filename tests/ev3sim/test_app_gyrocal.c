/*
 * test_app_gyrocal.c — the simulated gyro at rest reads as an EV3 gyro does
 * (host_sim's UART_SENSOR_GYRO_NOISE_AT_REST_DPS): LEGO's Gyro Boy
 * calibration (tests/ev3sim/apps/gyrocal: 200 readings 4 ms apart spanning
 * less than 2 deg/s) passes first time with the gyro boy's default noise for
 * each of nine seeds, as it does on a brick; nearly every reading is 0.
 * ev3sim run's --gyro-noise sets the noise, as balance's does: at 0.3 deg/s
 * (the default before) the calibration fails.
 */
#include "ev3sim_test.h"
#include "ev3sim/run.h"

extern const struct rtos_cfg ev3rt_app_cfg;

static struct et_run run;

static int gyrocal_main(int argc, char **argv)
{
	return ev3sim_run_main(argc, argv, "gyrocal", &ev3rt_app_cfg);
}

/* Runs the app in the gyro boy, held, with args after the robot's; its line's numbers. */
static bool calibrate(const char *seed, const char *noise, char *first, int *passed, int *widest, int *off)
{
	const char *args[] = { "--robot", "gyroboy", "--seconds", "8", "--seed", seed,
			       noise ? "--gyro-noise" : NULL, noise, NULL };
	const char *line;

	if (!et_run_main(&run, args, gyrocal_main, NULL) || run.status != 0) {
		tap_diag("status %d, stderr:\n%s", run.status, run.err);
		return false;
	}
	line = strstr(run.out, "gyrocal: ");
	return line != NULL && sscanf(line, "gyrocal: first %7[a-z], %d of 5 passed, widest span %d, %d of 1000",
				      first, passed, widest, off) == 4;
}

int main(void)
{
	static const char *const seeds[] = { "1", "2", "3", "4", "5", "6", "7", "8", "9" };
	int firsts = 0, total = 0, off_total = 0, widest = 0;
	char first[8];
	int passed = -1, span = -1, off = -1;
	bool ran;

	for (size_t i = 0; i < sizeof(seeds) / sizeof(seeds[0]); i++) {
		ran = calibrate(seeds[i], NULL, first, &passed, &span, &off);

		ok(ran && strcmp(first, "passed") == 0, "seed %s: the first calibration passes (%d of 5, widest span %d)",
		   seeds[i], ran ? passed : -1, ran ? span : -1);
		firsts += ran && strcmp(first, "passed") == 0;
		total += ran ? passed : 0;
		off_total += ran ? off : 0;
		widest = ran && span > widest ? span : widest;
	}
	in_range(total, 44, 45, "%d of 45 calibrations pass", total);
	in_range(off_total, 0, 20, "%d of 9000 readings at rest are not 0 (about 1 in 1200)", off_total);
	ok(widest <= 2, "no calibration spans more than 2 deg/s (%d)", widest);
	ran = calibrate("1", "0.3", first, &passed, &span, &off);
	ok(ran && passed <= 1, "--gyro-noise 0.3: the calibration fails (%d of 5 pass, %d readings not 0)", passed, off);
	ran = calibrate("1", "0", first, &passed, &span, &off);
	ok(ran && passed == 5 && off == 0, "--gyro-noise 0: every reading is 0 (%d not)", off);
	return tap_done();
}
