/*
 * test_motor_steer_loop.c — a two-motor robot driven the way EV3RT
 * applications drive one: ev3_motor_steer called from a 4 ms control loop.
 * The robot (two large motors, each carrying half of a 0.6 kg chassis on
 * 56 mm wheels) must move forward as fast as after a single call with the
 * same arguments, straight and in a curve, and keep moving when the loop
 * steers a little left and right in turn, as a line follower does; the same
 * for ev3_motor_set_power on each wheel from the loop.  A blocking rotate
 * waits for the whole step, its slow approach to the end included, and
 * (as with LEGO's motor driver, which EV3RT runs) counts its degrees from
 * where the last ev3_motor_stop found the wheel, coasting included.
 */
#include <math.h>
#include "api_test.h"

#define LEFT          EV3_PORT_A
#define RIGHT         EV3_PORT_B
#define LOOP_MS       4U
#define WHEEL_R_M     0.028
#define HALF_MASS_KG  0.30
#define ROLLING_CRR   0.02
#define GRAVITY       9.81
#define PI            3.14159265358979323846

/* Each wheel carries half the chassis: its inertia seen at the shaft and the rolling resistance. */
static void attach(void)
{
	for (unsigned port = 0; port < 2; port++) {
		struct hs_motor *m;

		ev3_attach_motor(port, HS_MOTOR_LARGE, NULL);
		m = ev3_output_motor(port);
		hs_motor_set_load(m, ROLLING_CRR * HALF_MASS_KG * GRAVITY * WHEEL_R_M,
				   HALF_MASS_KG * WHEEL_R_M * WHEEL_R_M);
	}
}

static double wheel_deg(unsigned port)
{
	return hs_motor_angle_deg(ev3_output_motor(port));
}

static bool by_power;   /* drive with ev3_motor_set_power per wheel instead of steering */
static double left_stopped_at;  /* where the left wheel was when it was last told to stop */

/* Wheel speeds (deg/s) over ms, steering every LOOP_MS if loop, else once before. */
static void drive(bool loop, int speed, int turn, bool wiggle, unsigned ms, double dps[2])
{
	double l0 = wheel_deg(LEFT), r0 = wheel_deg(RIGHT);
	uint64_t t0 = at_now_ms();
	unsigned n = 0;

	while (at_now_ms() - t0 < ms) {
		if ((loop || n == 0) && by_power) {
			ev3_motor_set_power(LEFT, speed);
			ev3_motor_set_power(RIGHT, speed);
		} else if (loop || n == 0) {
			ev3_motor_steer(LEFT, RIGHT, speed, wiggle && (n & 1) ? -turn : turn);
		}
		n++;
		dly_tsk(LOOP_MS);
	}
	dps[0] = (wheel_deg(LEFT) - l0) * 1000.0 / (double)(at_now_ms() - t0);
	dps[1] = (wheel_deg(RIGHT) - r0) * 1000.0 / (double)(at_now_ms() - t0);
}

/* Mean wheel speeds in the second second of a run; then the robot coasts to rest. */
static void run(bool loop, int speed, int turn, bool wiggle, double dps[2])
{
	drive(loop, speed, turn, wiggle, 1000, dps);
	drive(loop, speed, turn, wiggle, 1000, dps);
	ev3_motor_stop(LEFT, false);
	left_stopped_at = wheel_deg(LEFT);
	ev3_motor_stop(RIGHT, false);
	dly_tsk(1500);
}

static double forward_mm_s(const double dps[2])
{
	return (dps[0] + dps[1]) / 2 * PI / 180 * WHEEL_R_M * 1000;
}

static void body(void)
{
	double once[2], loop[2], wiggle[2];

	is_int(ev3_motor_config(LEFT, LARGE_MOTOR), E_OK, "left motor: large on A");
	is_int(ev3_motor_config(RIGHT, LARGE_MOTOR), E_OK, "right motor: large on B");

	run(false, 40, 0, false, once);
	run(true, 40, 0, false, loop);
	tap_diag("straight: once %.0f/%.0f deg/s, every 4 ms %.0f/%.0f deg/s", once[0], once[1],
		 loop[0], loop[1]);
	ok(forward_mm_s(once) > 150, "one call drives the robot forward (%.0f mm/s)", forward_mm_s(once));
	ok(fabs(forward_mm_s(loop) - forward_mm_s(once)) <= 0.03 * forward_mm_s(once),
	   "steering every 4 ms: %.0f mm/s, as one call (%.0f mm/s, +-3%%)", forward_mm_s(loop),
	   forward_mm_s(once));
	ok(fabs(loop[0] - loop[1]) <= 0.02 * fabs(loop[0]), "and straight (%.0f vs %.0f deg/s)",
	   loop[0], loop[1]);

	run(false, 40, 50, false, once);
	run(true, 40, 50, false, loop);
	tap_diag("turn 50: once %.0f/%.0f deg/s, every 4 ms %.0f/%.0f deg/s", once[0], once[1],
		 loop[0], loop[1]);
	ok(fabs(loop[0] - once[0]) <= 0.03 * fabs(once[0]) &&
	   fabs(loop[1] - once[1]) <= 0.03 * fabs(once[0]),
	   "a curve steered every 4 ms keeps both wheel speeds of one call (%.0f/%.0f vs %.0f/%.0f)",
	   loop[0], loop[1], once[0], once[1]);

	/* Left and right in turn: each wheel is master and slave by turns, so the
	 * robot goes as fast as in a steady curve of that turn. */
	run(false, 40, 10, false, once);
	run(true, 40, 10, true, wiggle);
	ok(fabs(forward_mm_s(wiggle) - forward_mm_s(once)) <= 0.05 * forward_mm_s(once),
	   "steering 10 left and right in turn every 4 ms: %.0f mm/s forward, as a steady turn 10 "
	   "(%.0f mm/s, +-5%%)", forward_mm_s(wiggle), forward_mm_s(once));

	by_power = true;
	run(false, 40, 0, false, once);
	run(true, 40, 0, false, loop);
	ok(forward_mm_s(once) > 150 &&
	   fabs(forward_mm_s(loop) - forward_mm_s(once)) <= 0.03 * forward_mm_s(once),
	   "set_power 40 on both wheels every 4 ms: %.0f mm/s, as once (%.0f mm/s, +-3%%)",
	   forward_mm_s(loop), forward_mm_s(once));

	/* A blocking rotate waits for the whole step, its approach to the end included;
	 * its degrees count from the stop before it (the wheel coasted on from there). */
	for (int speed = 100; speed >= 10; speed -= 45) {
		double l0 = left_stopped_at;
		uint64_t t0 = at_now_ms();
		ER ercd = ev3_motor_rotate(LEFT, 1080, speed, true);

		ok(ercd == E_OK && fabs(wheel_deg(LEFT) - l0 - 1080) <= 2,
		   "rotate 1080 deg at speed %d, blocking: %d after %u ms, at %.1f deg from the stop",
		   speed, (int)ercd, (unsigned)(at_now_ms() - t0), wheel_deg(LEFT) - l0);
		ev3_motor_stop(LEFT, false);
		left_stopped_at = wheel_deg(LEFT);
		dly_tsk(500);
	}
}

int main(void)
{
	tap_plan(12);
	ok(at_run(attach, body, 1, 60), "the application finished");
	return tap_done();
}
