/*
 * test_motor.c — EV3 motors through the registers a driver writes: speed
 * against duty and direction (eHRPWM1 and eCAP), brake against coast, the
 * tacho edges counted with LEGO's d_pwm.c direction rule against the shaft
 * angle both ways, the sleep when nothing moves, and the stall/encoder
 * faults; the H-bridge split against its definition, and a duty change
 * after the bridge GPIOs moved.
 */
#include <math.h>
#include <string.h>
#include "devtest.h"
#include "host_sim/trace.h"

static struct {
	int64_t count;
	uint64_t int_edges, dir_edges;
	unsigned int_pin, dir_pin;
	bool last_int;
} tacho;

/* Counts like d_pwm: on every INT edge, forward if INT equals the inverted DIR. */
static void int_watch(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	bool dir = hs_gpio_level(tacho.dir_pin);

	(void)ctx; (void)pin;
	if (st->level == tacho.last_int)
		return;
	tacho.last_int = st->level;
	tacho.int_edges++;
	tacho.count += (st->level == !dir) ? 1 : -1;
}

static void dir_watch(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	(void)ctx; (void)pin; (void)st;
	tacho.dir_edges++;
}

/* A physics model loading the motor on D every 1 ms, plainly or with the
 * next call promised (hs_motor_set_load_until). */
static struct owner {
	struct hs_motor *m;
	bool promise;
	unsigned steps, left;
	hs_event_t ev;
} owner;

static void owner_step(void *arg)
{
	uint64_t next = hs_now() + MS;
	double load = 0.15 * sin(owner.steps++ * 0.3);

	(void)arg;
	owner.ev = 0;
	if (owner.promise)
		hs_motor_set_load_until(owner.m, load, 1e-4, owner.left > 1 ? next : 0);
	else
		hs_motor_set_load(owner.m, load, 1e-4);
	if (--owner.left > 0)
		owner.ev = hs_event_at(next, owner_step, NULL);
}

/* The motor's state at three points of the owner's run: while it steps, after
 * its last call, after it withdrew a promise mid-run. */
struct owner_snap {
	double angle, speed_now, speed;
	int64_t counts;
};

static struct owner_snap owner_snap(void)
{
	return (struct owner_snap){ hs_motor_angle_deg(owner.m), hs_motor_speed_now_dps(owner.m),
				    hs_motor_speed_dps(owner.m), hs_motor_tacho_counts(owner.m) };
}

/* The owner's run; the duty changes between its calls (the segment an input
 * change starts ends at the owner's next call), the last time just before it
 * withdraws its promise. */
static void owner_run(bool promise, struct owner_snap snap[3])
{
	devtest_boot(1, NULL);
	devtest_pwm_setup();
	if (ev3_attach_motor(3, HS_MOTOR_LARGE, NULL) != E_OK)
		tap_bail_out("no motor on D");
	owner = (struct owner){ .m = ev3_output_motor(3), .promise = promise, .left = 300 };
	devtest_duty(3, 10000);
	devtest_bridge(3, 1);
	owner.ev = hs_event_at(hs_now() + MS / 4, owner_step, NULL);
	for (unsigned i = 0; i < 10; i++) {
		hs_sim_run_for(15 * MS);
		devtest_duty(3, (uint16_t)(6000 + 400 * i));
	}
	snap[0] = owner_snap();
	hs_sim_run_for(250 * MS);
	snap[1] = owner_snap();
	owner.left = 40;
	owner_step(NULL);
	hs_sim_run_for(20 * MS + MS / 4);
	devtest_duty(3, 8000);
	hs_sim_run_for(MS / 4);
	hs_event_cancel(&owner.ev);
	if (promise)
		hs_motor_end_load_promise(owner.m);
	hs_sim_run_for(100 * MS);
	snap[2] = owner_snap();
	hs_sim_shutdown();
}

/* The bridge's split as its definition reads (d_pwm.c's pins): each phase of
 * a PWM period, signal low then high, adds its fraction to the field it drives. */
static struct hbridge_drive bridge_reference(enum hbridge_input in0, enum hbridge_input in1, double pwm_low)
{
	struct hbridge_drive d = { 0, 0, 0 };
	double lo = pwm_low < 0 ? 0 : pwm_low > 1 ? 1 : pwm_low;
	double frac[2] = { lo, 1.0 - lo };

	for (int ph = 0; ph < 2; ph++) {
		bool a = in0 == HBRIDGE_HIGH || (in0 == HBRIDGE_PWM && ph == 1);
		bool b = in1 == HBRIDGE_HIGH || (in1 == HBRIDGE_PWM && ph == 1);

		if (a && b)
			d.brake += frac[ph];
		else if (a)
			d.fwd += frac[ph];
		else if (b)
			d.rev += frac[ph];
	}
	return d;
}

/* hbridge_resolve equals the reference bit for bit (signs of zero included)
 * for every input pair and duties in and out of range. */
static bool bridge_matches_reference(void)
{
	static const double lows[] = { -0.5, -0.0, 0.0, 0.1, 1.0 / 3.0, 0.5, 0.7, 0.999, 1.0, 1.5 };

	for (int in0 = HBRIDGE_LOW; in0 <= HBRIDGE_PWM; in0++)
		for (int in1 = HBRIDGE_LOW; in1 <= HBRIDGE_PWM; in1++)
			for (unsigned i = 0; i < sizeof(lows) / sizeof(lows[0]); i++) {
				struct hbridge_drive got = hbridge_resolve(in0, in1, lows[i]);
				struct hbridge_drive want = bridge_reference(in0, in1, lows[i]);

				if (memcmp(&got, &want, sizeof(got)) != 0)
					return false;
			}
	return true;
}

static double speed_after(unsigned port, int mode, uint16_t duty, uint64_t ns)
{
	devtest_duty(port, duty);
	devtest_bridge(port, mode);
	hs_sim_run_for(ns);
	return hs_motor_speed_dps(ev3_output_motor(port));
}

int main(void)
{
	struct hs_motor *m;
	double s25, s50, s75, s100, rev, a0, brake_speed, coast_speed;
	int64_t counted;

	tap_plan(34);
	ok(bridge_matches_reference(), "the bridge split of every input pair is its definition's, bit for bit");
	devtest_boot(1, NULL);
	devtest_pwm_setup();

	is_int(ev3_attach_motor(0, HS_MOTOR_LARGE, NULL), E_OK, "large motor on port A");
	is_int(ev3_attach_motor(4, HS_MOTOR_LARGE, NULL), E_ID, "port 4 is no output port");
	is_int(ev3_attach_motor(1, (enum hs_motor_kind)7, NULL), E_PAR, "unknown motor kind refused");
	m = ev3_output_motor(0);
	tacho.int_pin = ev3_output_pins[0].tacho_int;
	tacho.dir_pin = ev3_output_pins[0].tacho_dir;
	tacho.last_int = hs_gpio_level(tacho.int_pin);
	hs_gpio_watch(tacho.int_pin, int_watch, NULL);
	hs_gpio_watch(tacho.dir_pin, dir_watch, NULL);

	/* speed against duty, forward (LEGO's d_pwm.c: DIR0 high, DIR1 floating) */
	s25 = speed_after(0, 1, 2500, 500 * MS);
	s50 = speed_after(0, 1, 5000, 500 * MS);
	s75 = speed_after(0, 1, 7500, 500 * MS);
	s100 = speed_after(0, 1, 10000, 500 * MS);
	tap_diag("large motor at 9 V: 25%% %.0f, 50%% %.0f, 75%% %.0f, 100%% %.0f deg/s", s25, s50, s75, s100);
	in_range(s100, 1030, 1070, "full duty reaches the no-load speed (1050 deg/s)");
	ok(s25 > 0 && s25 < s50 && s50 < s75 && s75 < s100, "speed rises with duty");
	in_range((s75 - s50) / (s50 - s25), 0.95, 1.05, "speed is linear in duty above the friction");
	in_range(s25, 200, 260, "25%% duty minus dry friction");

	counted = tacho.count;
	a0 = hs_motor_angle_deg(m);
	in_range((double)counted - a0, -1.0, 1.0, "counts forward = shaft angle (%lld vs %.1f deg)",
		 (long long)counted, a0);
	ok(tacho.dir_edges >= tacho.int_edges - 1 && tacho.dir_edges <= tacho.int_edges + 1,
	   "DIR toggles once per INT edge (quadrature)");

	/* reverse */
	rev = speed_after(0, -1, 10000, 800 * MS);
	in_range(rev, -1070, -1030, "reverse (DIR0 floating, DIR1 high) turns backwards");
	in_range((double)tacho.count - hs_motor_angle_deg(m), -1.0, 1.0,
		 "counts after reversing still equal the angle (%lld vs %.1f)", (long long)tacho.count,
		 hs_motor_angle_deg(m));
	ok(tacho.count < counted, "the count went down while reversing");
	is_int(hs_motor_tacho_counts(m), tacho.count, "model's own count matches the pins");

	/* brake against coast from full speed */
	speed_after(0, 1, 10000, 300 * MS);
	brake_speed = speed_after(0, 2, 10000, 30 * MS);
	speed_after(0, 1, 10000, 300 * MS);
	coast_speed = speed_after(0, 0, 10000, 30 * MS);
	tap_diag("30 ms after full speed: braked %.0f, coasting %.0f deg/s", brake_speed, coast_speed);
	ok(brake_speed < coast_speed, "braking stops faster than coasting");
	hs_sim_run_for(3000 * MS);
	is_int((int64_t)hs_motor_speed_dps(m), 0, "coasting motor comes to rest (dry friction)");
	{
		uint64_t edges = tacho.int_edges;

		hs_sim_run_for(1000 * MS);
		is_int(tacho.int_edges, edges, "a resting motor makes no edges");
	}

	/* medium motor on an eCAP port */
	is_int(ev3_attach_motor(2, HS_MOTOR_MEDIUM, NULL), E_OK, "medium motor on port C (eCAP0)");
	{
		double med = speed_after(2, 1, 10000, 500 * MS);
		double med_half = speed_after(2, -1, 5000, 500 * MS);

		in_range(med, 1520, 1600, "medium at full duty ~1560 deg/s (%.0f)", med);
		ok(med_half < 0 && med_half > -med / 2, "medium reverse at half duty, below half speed (%.0f)",
		   med_half);
	}

	/* a duty change after the bridge GPIOs moved drives with their new levels */
	{
		struct hbridge_drive d, want;

		devtest_bridge(0, -1);
		devtest_duty(0, 2500);
		hs_sim_run_for(MS);
		d = hs_motor_drive(m);
		want = hbridge_resolve(HBRIDGE_PWM, HBRIDGE_HIGH, hs_pwm_low_fraction(ev3_output_pwm[0]));
		ok(memcmp(&d, &want, sizeof(d)) == 0 && d.rev > 0 && d.fwd == 0,
		   "duty after a bridge change: the reverse split (fwd %.3f rev %.3f brake %.3f)", d.fwd, d.rev,
		   d.brake);
		devtest_bridge(0, 1);
		devtest_duty(0, 10000);
	}

	/* load slows it; a stall fault locks it and stops the edges */
	hs_motor_set_load(m, 0.2, 0);
	s50 = speed_after(0, 1, 10000, 500 * MS);
	in_range(s50, 450, 560, "half the stall torque as load halves the speed (%.0f)", s50);
	hs_motor_set_load(m, 0, 0);
	/* inside a step after a duty change the exact speed is between the step's
	 * ends, and is what re-applying the load then publishes on speed_dps */
	{
		struct hs_signal *sig = hs_trace_find("motorA", "speed_dps");
		double start, mid, again;

		hs_sim_run_for(50 * MS);
		devtest_duty(0, 3000);
		start = hs_signal_real(sig);
		hs_sim_run_for(MS / 3);
		mid = hs_motor_speed_now_dps(m);
		again = hs_motor_speed_now_dps(m);
		ok(sig && mid < start && mid > 0 && mid == again,
		   "speed now inside a step: slowing from %.1f, %.3f deg/s", start, mid);
		hs_motor_set_load(m, 0, 0);
		ok(hs_signal_real(sig) == mid, "re-applying the load publishes that speed");
		devtest_duty(0, 10000);
	}
	{
		struct ev3_fault f = { EV3_FAULT_MOTOR_STALL, 0, 0, 200 * MS };
		uint64_t t = hs_now() + 100 * MS, edges;

		is_int(ev3_fault_at(t, &f), E_OK, "stall scheduled");
		hs_sim_run_until(t + 50 * MS);
		edges = tacho.int_edges;
		hs_sim_run_for(100 * MS);
		is_int(tacho.int_edges, edges, "stalled shaft: no edges");
		ok(hs_motor_speed_now_dps(m) == 0.0, "stalled shaft: speed now 0");
		hs_sim_run_for(200 * MS);
		ok(tacho.int_edges > edges + 50, "edges again after the stall ends");
	}
	/* encoder stuck: the shaft turns, the pins do not */
	{
		struct ev3_fault f = { EV3_FAULT_ENCODER_STUCK, 0, 0, 100 * MS };
		uint64_t t = hs_now() + 10 * MS, edges;
		double a;

		ev3_fault_at(t, &f);
		hs_sim_run_until(t + 1);
		edges = tacho.int_edges;
		a = hs_motor_angle_deg(m);
		hs_sim_run_for(50 * MS);
		ok(tacho.int_edges == edges && hs_motor_angle_deg(m) > a + 30, "stuck encoder: shaft moves, pins frozen");
		hs_sim_run_for(60 * MS);
		ok(tacho.int_edges > edges + 50 && hs_motor_tacho_counts(m) == tacho.count,
		   "released: the pins catch up, edge by edge, to the model's count");
	}
	hs_sim_shutdown();

	/* a load's owner stepping with the motor gets the physics of plain loads */
	{
		struct owner_snap plain[3], promised[3];
		static const char *const when[3] = { "while it steps", "after its last call",
						     "after it withdrew its promise" };

		owner_run(false, plain);
		owner_run(true, promised);
		for (int i = 0; i < 3; i++)
			ok(plain[i].angle == promised[i].angle && plain[i].speed_now == promised[i].speed_now &&
			   plain[i].speed == promised[i].speed && plain[i].counts == promised[i].counts,
			   "promised loads %s: the same angle (%.3f deg), speeds and counts", when[i],
			   promised[i].angle);
		ok(promised[2].angle > promised[1].angle + 30, "the motor steps on its own after the promise");
	}
	return tap_done();
}
