/*
 * test_leds.c — d_ui's LED patterns on host_sim's LED pins through
 * ui_hack: steady colours on both LEDs at once, flash (500/500 ms) and
 * pulse (100 on, 100 off, 100 on, 700 off) timing on the pins, a steady
 * pattern stopping the blinking, bad patterns refused with nothing changed.
 */
#include "ui_test.h"

static bool both(enum ev3_ui_color c)
{
	return ev3_ui_led_color(EV3_UI_LED_LEFT) == c && ev3_ui_led_color(EV3_UI_LED_RIGHT) == c;
}

static void steady(void)
{
	static const struct { uint8_t pattern; enum ev3_ui_color color; const char *name; } rows[] = {
		{ LMS_UI_LED_GREEN, EV3_UI_LED_GREEN, "green" },
		{ LMS_UI_LED_RED, EV3_UI_LED_RED, "red" },
		{ LMS_UI_LED_ORANGE, EV3_UI_LED_ORANGE, "orange (red + green)" },
		{ LMS_UI_LED_OFF, EV3_UI_LED_OFF, "off" },
	};

	for (unsigned i = 0; i < sizeof(rows) / sizeof(rows[0]); i++) {
		is_int(ui_svc_led(rows[i].pattern), E_OK, "pattern '%c'", rows[i].pattern);
		ok(both(rows[i].color), "both LEDs %s", rows[i].name);
		is_int(uit_shm->led, rows[i].pattern, "shared page shows '%c'", rows[i].pattern);
	}
}

/* Samples the left LED every ms for ms; the lit (non-off) pattern as a bit string.
 * The sampler's service calls cost no CPU time here, so that dly_tsk(1) from a
 * tick boundary is 1 ms and sample i is taken at i ms. */
static void sample(char *bits, unsigned ms, enum ev3_ui_color lit_color, bool *colour_ok)
{
	struct rtos_host_cpu_cost cost, free_calls = { 0, 0, false, 0 };

	rtos_host_get_cpu_cost(&cost);
	rtos_host_set_cpu_cost(&free_calls);
	for (unsigned i = 0; i < ms; i++) {
		enum ev3_ui_color c = ev3_ui_led_color(EV3_UI_LED_LEFT);

		bits[i] = c == EV3_UI_LED_OFF ? '0' : '1';
		if (c != EV3_UI_LED_OFF && c != lit_color)
			*colour_ok = false;
		if (c != ev3_ui_led_color(EV3_UI_LED_RIGHT))
			*colour_ok = false;
		dly_tsk(1);
	}
	bits[ms] = 0;
	rtos_host_set_cpu_cost(&cost);
}

/* Number of '1'->'0' and '0'->'1' changes, and the length of each run. */
static unsigned runs(const char *bits, unsigned *len, unsigned max)
{
	unsigned n = 0, run = 1;

	for (unsigned i = 1; bits[i]; i++) {
		if (bits[i] == bits[i - 1]) {
			run++;
			continue;
		}
		if (n < max)
			len[n] = run;
		n++;
		run = 1;
	}
	return n;
}

static void flash_and_pulse(void)
{
	static char bits[2001];
	unsigned len[32], n, changes;
	bool colour_ok = true, lens_ok = true;

	is_int(ui_svc_led(LMS_UI_LED_GREEN_FLASH), E_OK, "green flash");
	sample(bits, 2000, EV3_UI_LED_GREEN, &colour_ok);
	ok(colour_ok, "green on both LEDs when lit");
	n = runs(bits, len, 32);
	ok(n == 3 || n == 4, "on/off runs in 2 s: %u changes", n);
	for (unsigned i = 1; i < n && i < 32; i++)
		lens_ok &= len[i] >= 499 && len[i] <= 501;
	ok(bits[0] == '1' && lens_ok, "500 ms on, 500 ms off (%u, %u)", len[0], len[1]);

	colour_ok = true;
	lens_ok = true;
	is_int(ui_svc_led(LMS_UI_LED_RED_PULSE), E_OK, "red pulse");
	sample(bits, 2000, EV3_UI_LED_RED, &colour_ok);
	ok(colour_ok, "red on both LEDs when lit");
	n = runs(bits, len, 32);
	ok(n >= 6 && n <= 8, "two blinks a second: %u changes in 2 s", n);
	/* runs: on 100, off 100, on 100, off 700, ... */
	for (unsigned i = 0; i + 1 < n && i < 32; i++) {
		unsigned want = (i % 4) == 3 ? 700 : 100;

		lens_ok &= len[i] + 1 >= want && len[i] <= want + 1;
	}
	ok(bits[0] == '1' && lens_ok, "100 on, 100 off, 100 on, 700 off (%u %u %u %u)",
	   len[0], len[1], len[2], len[3]);

	is_int(ui_svc_led(LMS_UI_LED_ORANGE), E_OK, "orange steady");
	changes = ev3_ui_led_changes(EV3_UI_LED_LEFT);
	dly_tsk(2000);
	ok(both(EV3_UI_LED_ORANGE) && ev3_ui_led_changes(EV3_UI_LED_LEFT) == changes,
	   "a steady pattern stops the blinking");
}

static void bad_patterns(void)
{
	static const intptr_t bad[] = { '/', ':', 'A', 0, 1, -1, 0x130, INTPTR_MAX };
	bool all = true;

	for (unsigned i = 0; i < sizeof(bad) / sizeof(bad[0]); i++)
		all &= cal_svc(UI_FN_LED, bad[i], 0, 0, 0, 0) == E_PAR;
	ok(all, "patterns outside '0'..'9' (and wider values) are E_PAR");
	ok(both(EV3_UI_LED_ORANGE) && uit_shm->led == LMS_UI_LED_ORANGE, "and change nothing");
}

static void body(void)
{
	steady();
	flash_and_pulse();
	bad_patterns();
}

int main(void)
{
	uit_domain = 2;
	tap_plan(1 + 12 + 10 + 2);
	ok(uit_run(body, 4), "scenario ran to its end");
	return tap_done();
}
