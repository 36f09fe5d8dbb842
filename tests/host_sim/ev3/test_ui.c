/*
 * test_ui.c — the brick buttons and LEDs (ev3_ui.h): button pins follow the
 * user (now, at scenario times, with seeded bounce), their edges raise the
 * GPIO bank interrupt status, LED colours and traces follow the SoC's pins,
 * the pins are muxed to GPIO at boot, bad arguments are refused.
 */
#include <string.h>
#include "devtest.h"
#include "host_sim/syscfg.h"
#include "host_sim/trace.h"
#include "host_sim/devices/ev3_ui.h"

static const struct ev3_ui_pins *pins = &ev3_ui_pins;

/* INTSTAT bit of a pin (write-1-to-clear). */
static bool intstat(unsigned pin)
{
	return (rd32(gpio_pair(pin) + 0x24U) & gpio_bit(pin)) != 0;
}

static void test_boot_state(void)
{
	bool all_low = true, muxed = true;

	for (unsigned b = 0; b < EV3_UI_BUTTONS; b++)
		all_low &= !gpio_in(pins->button[b]) && !ev3_ui_button_held((enum ev3_ui_button)b);
	ok(all_low, "released buttons read low");
	/* PINMUX(2b+1) holds bits 8..15 of bank b (b >= 2), PINMUX(2b+2) bits 0..7; GPIO = 8. */
	muxed &= hs_syscfg_pinmux_field(14, 28U - 4U * 6U) == 8U;    /* GP6_6 */
	muxed &= hs_syscfg_pinmux_field(13, 28U - 4U * 2U) == 8U;    /* GP6_10 */
	muxed &= hs_syscfg_pinmux_field(14, 28U - 4U * 7U) == 8U;    /* GP6_7 */
	muxed &= hs_syscfg_pinmux_field(13, 28U - 4U * 6U) == 8U;    /* GP6_14 */
	/* GP1_13 (ENTER): bank 1 bits 8..15 have no known mux field here (gpio.c) */
	ok(muxed, "button and LED pins muxed to GPIO at boot");
	is_int(ev3_ui_led_color(EV3_UI_LED_LEFT), EV3_UI_LED_OFF, "left LED off at boot");
	is_int(ev3_ui_led_color(EV3_UI_LED_RIGHT), EV3_UI_LED_OFF, "right LED off at boot");
}

static void test_press_release(void)
{
	unsigned pin = pins->button[EV3_UI_BUTTON_ENTER];
	struct hs_signal *sig = hs_trace_find("ui", "btn_enter");

	/* Both-edge detection as d_ui sets it up; the bank interrupt stays disabled (BINTEN 0). */
	wr32(gpio_pair(pin) + 0x14U, gpio_bit(pin));
	wr32(gpio_pair(pin) + 0x1CU, gpio_bit(pin));
	is_int(ev3_ui_button_set(EV3_UI_BUTTON_ENTER, true), E_OK, "press ENTER");
	ok(gpio_in(pin) && ev3_ui_button_held(EV3_UI_BUTTON_ENTER), "pressed: pin high");
	ok(intstat(pin), "rising edge latched in INTSTAT");
	wr32(gpio_pair(pin) + 0x24U, gpio_bit(pin));
	ok(sig && hs_signal_value(sig) == 1, "trace ui.btn_enter = 1");
	is_int(ev3_ui_button_set(EV3_UI_BUTTON_ENTER, true), E_OK, "pressing again changes nothing");
	ok(!intstat(pin), "no edge for a repeated press");
	ev3_ui_button_set(EV3_UI_BUTTON_ENTER, false);
	ok(!gpio_in(pin) && intstat(pin), "released: pin low, falling edge latched");
	ok(sig && hs_signal_value(sig) == 0, "trace ui.btn_enter = 0");
	is_int(ev3_ui_contact_changes(EV3_UI_BUTTON_ENTER), 2, "two contact changes");
	ok(!gpio_in(pins->button[EV3_UI_BUTTON_UP]), "other buttons untouched");
}

static void test_scheduled(void)
{
	uint64_t t0 = hs_now() + 10 * MS;
	unsigned pin = pins->button[EV3_UI_BUTTON_BACK];

	is_int(ev3_ui_click_at(t0, EV3_UI_BUTTON_BACK, 30 * MS), E_OK, "click BACK at t0 for 30 ms");
	hs_sim_run_until(t0 - 1);
	ok(!gpio_in(pin), "not yet pressed 1 ns before t0");
	hs_sim_run_until(t0);
	ok(gpio_in(pin), "pressed at t0");
	hs_sim_run_until(t0 + 30 * MS - 1);
	ok(gpio_in(pin), "still pressed just before the release");
	hs_sim_run_until(t0 + 30 * MS);
	ok(!gpio_in(pin), "released at t0 + 30 ms");
}

/* Contact change times of one bounced press and release. */
static unsigned bounce_run(uint64_t seed, uint64_t *times, unsigned max)
{
	unsigned pin = pins->button[EV3_UI_BUTTON_UP], n = 0;
	bool level = false;

	devtest_boot(seed, NULL);
	ev3_ui_set_bounce(5000);
	ev3_ui_button_set(EV3_UI_BUTTON_UP, true);
	for (unsigned us = 0; us < 40000; us += 10) {
		if (us == 20000)
			ev3_ui_button_set(EV3_UI_BUTTON_UP, false);
		if (gpio_in(pin) != level) {
			level = !level;
			if (n < max)
				times[n] = hs_now();
			n++;
		}
		hs_sim_run_for(10000);
	}
	n = gpio_in(pin) ? n + 1000 : n;    /* must end released */
	hs_sim_shutdown();
	return n;
}

static void test_bounce(void)
{
	uint64_t a[32], b[32];
	unsigned na, nb;

	na = bounce_run(5, a, 32);
	nb = bounce_run(5, b, 32);
	in_range(na, 6, 14, "press and release bounce (extra toggles counted, ends released)");
	ok(na == nb && memcmp(a, b, sizeof(a[0]) * (na < 32 ? na : 32)) == 0,
	   "same seed: same bounce times");
	ok(a[na - 1] - a[0] > 20 * MS && a[na - 1] - a[0] < 28 * MS, "the release bounce ends within ~5 ms");
}

static void test_leds(void)
{
	struct hs_signal *left = hs_trace_find("ui", "led_left");
	struct hs_signal *right = hs_trace_find("ui", "led_right");

	gpio_out(pins->red[EV3_UI_LED_LEFT], 1);
	is_int(ev3_ui_led_color(EV3_UI_LED_LEFT), EV3_UI_LED_RED, "left red pin high: red");
	is_int(ev3_ui_led_color(EV3_UI_LED_RIGHT), EV3_UI_LED_OFF, "right still off");
	gpio_out(pins->green[EV3_UI_LED_LEFT], 1);
	is_int(ev3_ui_led_color(EV3_UI_LED_LEFT), EV3_UI_LED_ORANGE, "red + green: orange");
	ok(left && hs_signal_value(left) == EV3_UI_LED_ORANGE, "trace ui.led_left = orange");
	gpio_out(pins->red[EV3_UI_LED_LEFT], 0);
	is_int(ev3_ui_led_color(EV3_UI_LED_LEFT), EV3_UI_LED_GREEN, "red pin low: green");
	gpio_float(pins->green[EV3_UI_LED_LEFT]);
	is_int(ev3_ui_led_color(EV3_UI_LED_LEFT), EV3_UI_LED_OFF, "a floating pin lights nothing");
	gpio_out(pins->green[EV3_UI_LED_RIGHT], 1);
	is_int(ev3_ui_led_color(EV3_UI_LED_RIGHT), EV3_UI_LED_GREEN, "right green");
	ok(right && hs_signal_value(right) == EV3_UI_LED_GREEN, "trace ui.led_right = green");
	is_int(ev3_ui_led_changes(EV3_UI_LED_LEFT), 4, "left LED: four colour changes");
	/* the pins by number: red GP6_12/GP6_13, green GP6_7/GP6_14 (EV3RT's brick
	 * driver and LEGO's d_ui pin table) */
	gpio_out(pins->green[EV3_UI_LED_RIGHT], 0);
	gpio_out(HS_GPIO(6, 13), 1);
	is_int(ev3_ui_led_color(EV3_UI_LED_LEFT), EV3_UI_LED_RED, "GP6_13 high: the left LED is red");
	gpio_out(HS_GPIO(6, 13), 0);
	gpio_out(HS_GPIO(6, 7), 1);
	is_int(ev3_ui_led_color(EV3_UI_LED_LEFT), EV3_UI_LED_GREEN, "GP6_7 high: the left LED is green");
	gpio_out(HS_GPIO(6, 7), 0);
	gpio_out(HS_GPIO(6, 12), 1);
	is_int(ev3_ui_led_color(EV3_UI_LED_RIGHT), EV3_UI_LED_RED, "GP6_12 high: the right LED is red");
	gpio_out(HS_GPIO(6, 12), 0);
	gpio_out(HS_GPIO(6, 14), 1);
	is_int(ev3_ui_led_color(EV3_UI_LED_RIGHT), EV3_UI_LED_GREEN, "GP6_14 high: the right LED is green");
	gpio_out(HS_GPIO(6, 14), 0);
}

static void test_errors(void)
{
	is_int(ev3_ui_button_set(EV3_UI_BUTTONS, true), E_ID, "bad button: E_ID");
	is_int(ev3_ui_button_at(hs_now(), (enum ev3_ui_button)-1, true), E_ID, "negative button: E_ID");
	is_int(ev3_ui_button_at(hs_now() - 1, EV3_UI_BUTTON_UP, true), E_PAR, "time in the past: E_PAR");
	is_int(ev3_ui_click_at(hs_now(), EV3_UI_BUTTON_UP, 0), E_PAR, "zero hold: E_PAR");
	is_int(ev3_ui_set_bounce(EV3_UI_MAX_BOUNCE_US + 1), E_PAR, "bounce too long: E_PAR");
	is_int(ev3_ui_led_color(EV3_UI_LEDS), EV3_UI_LED_OFF, "bad LED reads off");
}

int main(void)
{
	tap_plan(42);
	devtest_boot(1, NULL);
	hs_sim_run_for(MS);
	test_boot_state();
	test_press_release();
	test_scheduled();
	test_leds();
	test_errors();
	hs_sim_shutdown();
	is_int(ev3_ui_button_set(EV3_UI_BUTTON_UP, true), E_OBJ, "no board: E_OBJ");
	test_bounce();
	return tap_done();
}
