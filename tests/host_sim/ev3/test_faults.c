/*
 * test_faults.c — seeded fault injection at scenario times (UART bit
 * errors, dropped and duplicated bytes, unplug/replug, noisy encoder) and
 * determinism: the same seed gives a byte-identical VCD, another seed not.
 */
#define _XOPEN_SOURCE 700
#include <stdio.h>
#include <string.h>
#include "uarttest.h"
#include "text_files_test.h"
#include "host_sim/devices/uart16550.h"

static struct host h;

struct outcome {
	unsigned nlog;
	uint64_t log_t[16];
	bool log_ok;
	uint32_t flipped, dropped, duplicated;
	uint64_t glitches;
	enum uart_sensor_state during_unplug, after_replug;
	unsigned bytes;
	unsigned framing;
};

static void run(uint64_t seed, const char *vcd, struct outcome *o)
{
	static const struct ev3_fault faults[] = {
		{ EV3_FAULT_ENCODER_NOISE, 0, 300.0, 300 * MS },
		{ EV3_FAULT_UART_BIT_ERRORS, 0, 0.3, 400 * MS },
		{ EV3_FAULT_UART_DROP, 0, 0.2, 300 * MS },
		{ EV3_FAULT_UART_DUPLICATE, 0, 0.2, 300 * MS },
		{ EV3_FAULT_UNPLUG, 0, 0, 300 * MS },
	};
	static const uint64_t at[] = { 200 * MS, 700 * MS, 1100 * MS, 1100 * MS, 2000 * MS };

	memset(o, 0, sizeof(*o));
	devtest_boot(seed, vcd);
	devtest_pwm_setup();
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	devtest_duty(0, 6000);
	devtest_bridge(0, 1);
	host_init(&h, 0);
	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL);
	for (unsigned i = 0; i < sizeof(faults) / sizeof(faults[0]); i++)
		if (ev3_fault_at(at[i], &faults[i]) != E_OK)
			tap_bail_out("fault_at refused a valid fault");
	host_run(&h, 2100 * MS);
	o->during_unplug = uart_sensor_get_state(ev3_input_uart_sensor(0));
	host_run(&h, 250 * MS);
	o->after_replug = uart_sensor_get_state(ev3_input_uart_sensor(0));
	host_run(&h, 400 * MS);
	o->nlog = ev3_fault_log_count();
	o->log_ok = true;
	for (unsigned i = 0; i < o->nlog && i < 16; i++) {
		const struct ev3_fault_record *r = ev3_fault_log(i);
		bool found = false;

		o->log_t[i] = r->t_ns;
		for (unsigned k = 0; k < sizeof(faults) / sizeof(faults[0]); k++)
			if (faults[k].kind == r->kind &&
			    r->t_ns == (r->start ? at[k] : at[k] + faults[k].duration_ns))
				found = true;
		o->log_ok &= found;
	}
	ev3_fault_uart_counts(0, &o->flipped, &o->dropped, &o->duplicated);
	o->glitches = hs_motor_glitches(ev3_output_motor(0));
	o->bytes = h.n;
	o->framing = hs_uart_get_stats(ev3_input_uart(0))->framing_errors;
	hs_sim_shutdown();
}

static bool same_file(const char *a, const char *b, long *size)
{
	FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
	bool same = fa && fb;
	int ca, cb;

	*size = 0;
	while (same) {
		ca = fgetc(fa);
		cb = fgetc(fb);
		if (ca != cb)
			same = false;
		if (ca == EOF)
			break;
		(*size)++;
	}
	if (fa)
		fclose(fa);
	if (fb)
		fclose(fb);
	return same;
}

int main(void)
{
	struct outcome a, b, c;
	long size = 0;
	char dir[] = "/tmp/test_faults.XXXXXX", va[64], vb[64], vc[64];

	tap_plan(14);
	tf_make_scratch_dir(dir);
	snprintf(va, sizeof(va), "%s/a.vcd", dir);
	snprintf(vb, sizeof(vb), "%s/b.vcd", dir);
	snprintf(vc, sizeof(vc), "%s/c.vcd", dir);
	run(5, va, &a);
	is_int(a.nlog, 10, "five faults started and ended");
	ok(a.log_ok, "each at its scheduled virtual time");
	ok(a.flipped > 0, "bit errors flipped bytes (%u)", a.flipped);
	ok(a.dropped > 0, "bytes were dropped (%u)", a.dropped);
	ok(a.duplicated > 0, "bytes were duplicated (%u)", a.duplicated);
	ok(a.glitches > 30 && a.glitches < 200, "noisy encoder: ~90 glitches in 300 ms (%llu)",
	   (unsigned long long)a.glitches);
	is_int(a.during_unplug, UART_SENSOR_OFF, "unplugged sensor is off");
	is_int(a.after_replug, UART_SENSOR_AUTOID, "replugged sensor powers up again (pin 6 low)");

	run(5, vb, &b);
	ok(a.flipped == b.flipped && a.dropped == b.dropped && a.duplicated == b.duplicated &&
	   a.glitches == b.glitches && a.bytes == b.bytes, "same seed, same faults and bytes");
	{
		bool same = same_file(va, vb, &size);

		ok(same && size > 1000, "same seed: byte-identical VCD (%ld bytes)", size);
	}

	run(6, vc, &c);
	ok(c.log_ok && c.nlog == 10, "another seed: faults at the same times");
	ok(c.glitches != a.glitches || c.flipped != a.flipped || c.dropped != a.dropped,
	   "another seed draws other faults");
	ok(!same_file(va, vc, &size), "another seed: a different VCD");

	{
		struct ev3_fault bad = { EV3_FAULT_MOTOR_STALL, 4, 0, 0 };

		devtest_boot(1, NULL);
		ok(ev3_fault_at(hs_now() + MS, &bad) == E_ID, "fault on port 4 of the outputs refused");
		hs_sim_shutdown();
	}
	tf_remove_tree(dir);
	return tap_done();
}
