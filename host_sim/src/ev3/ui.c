/*
 * ui.c — the brick's six buttons and two bicolour LEDs on their GPIO
 * pins (ev3_ui.h).
 *
 * A button is a contact from its pin to 3.3 V with a pull-down: released
 * the pin is pulled low, pressed it is driven high.  With bounce configured,
 * every change is followed by an even number of extra contact toggles at
 * seeded random intervals, about bounce_us in all, ending at the new state.
 * An LED colour is lit while the SoC drives its pin high; the model watches
 * the four pins and traces the colour of each LED.
 */
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/regs.h"
#include "host_sim/rng.h"
#include "host_sim/trace.h"
#include "host_sim/devices/ev3_ui.h"


const struct ev3_ui_pins ev3_ui_pins = {
	.button = {
		[EV3_UI_BUTTON_UP] = HS_GPIO(7, 15), [EV3_UI_BUTTON_ENTER] = HS_GPIO(1, 13),
		[EV3_UI_BUTTON_DOWN] = HS_GPIO(7, 14), [EV3_UI_BUTTON_RIGHT] = HS_GPIO(7, 12),
		[EV3_UI_BUTTON_LEFT] = HS_GPIO(6, 6), [EV3_UI_BUTTON_BACK] = HS_GPIO(6, 10),
	},
	/* Red GP6_12 and GP6_13, green GP6_7 and GP6_14: EV3RT's brick driver
	 * (ev3rt-git/ev3rt-hrp2, target/ev3_gcc/drivers/brick/src/brick_dri.c,
	 * MISCCMD_SET_LED) and LEGO's d_ui pin table (mindboards/ev3sources,
	 * lms2012/d_ui, EP2_UiLedPin: right red, right green, left red, left green). */
	.red = { [EV3_UI_LED_LEFT] = HS_GPIO(6, 13), [EV3_UI_LED_RIGHT] = HS_GPIO(6, 12) },
	.green = { [EV3_UI_LED_LEFT] = HS_GPIO(6, 7), [EV3_UI_LED_RIGHT] = HS_GPIO(6, 14) },
};

static const char *const button_signal[EV3_UI_BUTTONS] = {
	"btn_up", "btn_enter", "btn_down", "btn_right", "btn_left", "btn_back",
};

struct button {
	bool held;                  /* what the user does */
	bool contact;               /* what the pin sees (bounces) */
	unsigned bounce_total;      /* extra toggles of the current change */
	unsigned bounce_left;       /* of which still to come */
	hs_event_t bounce_ev;
	uint32_t changes;
	struct hs_signal *sig;
};

struct led {
	enum ev3_ui_color color;
	uint32_t changes;
	struct hs_signal *sig;
};

/* A button change scheduled at a scenario time. */
struct button_job {
	enum ev3_ui_button button;
	bool pressed;
	hs_event_t ev;
	struct button_job *next;
};

static struct {
	bool ready;
	uint32_t bounce_us;
	struct button buttons[EV3_UI_BUTTONS];
	struct led leds[EV3_UI_LEDS];
	int watches[2 * EV3_UI_LEDS];
	struct hs_rng rng;
	struct button_job *jobs;
} ui;

/* ---- buttons ---- */

static void contact_apply(enum ev3_ui_button b)
{
	struct button *bt = &ui.buttons[b];

	hs_gpio_drive(ev3_ui_pins.button[b], bt->contact ? HS_EXT_HIGH : HS_EXT_PULL_DOWN);
	hs_trace_set(bt->sig, bt->contact);
}

static void contact_set(enum ev3_ui_button b, bool contact)
{
	struct button *bt = &ui.buttons[b];

	if (bt->contact == contact)
		return;
	bt->contact = contact;
	bt->changes++;
	contact_apply(b);
}

/* The gap before the next bounce toggle: about bounce_us spread over the toggles. */
static uint64_t bounce_gap_ns(unsigned toggles)
{
	uint64_t mean_ns = (uint64_t)ui.bounce_us * 1000U / toggles;

	return mean_ns / 2U + hs_rng_below(&ui.rng, (uint32_t)mean_ns + 1U);
}

static void bounce_due(void *arg)
{
	enum ev3_ui_button b = (enum ev3_ui_button)(uintptr_t)arg;
	struct button *bt = &ui.buttons[b];

	bt->bounce_ev = 0;
	if (!bt->bounce_left)
		return;
	bt->bounce_left--;
	contact_set(b, bt->bounce_left ? !bt->contact : bt->held);
	if (bt->bounce_left)
		bt->bounce_ev = hs_event_after(bounce_gap_ns(bt->bounce_total), bounce_due, arg);
}

ER ev3_ui_set_bounce(uint32_t bounce_us)
{
	if (!ui.ready)
		return E_OBJ;
	if (bounce_us > EV3_UI_MAX_BOUNCE_US)
		return E_PAR;
	ui.bounce_us = bounce_us;
	return E_OK;
}

ER ev3_ui_button_set(enum ev3_ui_button button, bool pressed)
{
	struct button *bt;

	if (!ui.ready)
		return E_OBJ;
	if ((unsigned)button >= EV3_UI_BUTTONS)
		return E_ID;
	bt = &ui.buttons[button];
	if (bt->held == pressed)
		return E_OK;
	bt->held = pressed;
	hs_event_cancel(&bt->bounce_ev);
	bt->bounce_left = 0;
	contact_set(button, pressed);
	if (ui.bounce_us) {
		bt->bounce_total = bt->bounce_left = 2U * (1U + hs_rng_below(&ui.rng, 3));
		bt->bounce_ev = hs_event_after(bounce_gap_ns(bt->bounce_total), bounce_due,
					       (void *)(uintptr_t)button);
	}
	return E_OK;
}

static void job_free(struct button_job *j)
{
	struct button_job **pp = &ui.jobs;

	while (*pp && *pp != j)
		pp = &(*pp)->next;
	if (*pp)
		*pp = j->next;
	free(j);
}

static void job_due(void *arg)
{
	struct button_job *j = arg;

	j->ev = 0;
	(void)ev3_ui_button_set(j->button, j->pressed);
	job_free(j);
}

ER ev3_ui_button_at(uint64_t t_ns, enum ev3_ui_button button, bool pressed)
{
	struct button_job *j;

	if (!ui.ready)
		return E_OBJ;
	if ((unsigned)button >= EV3_UI_BUTTONS)
		return E_ID;
	if (t_ns < hs_now())
		return E_PAR;
	j = calloc(1, sizeof(*j));
	if (!j)
		return E_NOMEM;
	j->button = button;
	j->pressed = pressed;
	j->next = ui.jobs;
	ui.jobs = j;
	j->ev = hs_event_at(t_ns, job_due, j);
	return E_OK;
}

ER ev3_ui_click_at(uint64_t t_ns, enum ev3_ui_button button, uint64_t hold_ns)
{
	ER ercd;

	if (!ui.ready)
		return E_OBJ;
	if ((unsigned)button >= EV3_UI_BUTTONS)
		return E_ID;
	if (hold_ns == 0 || t_ns < hs_now())
		return E_PAR;
	ercd = ev3_ui_button_at(t_ns, button, true);
	return ercd == E_OK ? ev3_ui_button_at(t_ns + hold_ns, button, false) : ercd;
}

bool ev3_ui_button_held(enum ev3_ui_button button)
{
	return (unsigned)button < EV3_UI_BUTTONS && ui.buttons[button].held;
}

uint32_t ev3_ui_contact_changes(enum ev3_ui_button button)
{
	return (unsigned)button < EV3_UI_BUTTONS ? ui.buttons[button].changes : 0;
}

/* ---- LEDs ---- */

static bool lit(unsigned pin)
{
	bool level;

	return hs_gpio_soc_output(pin, &level) && level;
}

/* One of the LED pins changed: recompute both LEDs. */
static void led_pin_changed(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	(void)ctx; (void)pin; (void)st;
	for (unsigned i = 0; i < EV3_UI_LEDS; i++) {
		struct led *l = &ui.leds[i];
		unsigned red = lit(ev3_ui_pins.red[i]) ? EV3_UI_LED_RED : 0U;
		unsigned green = lit(ev3_ui_pins.green[i]) ? EV3_UI_LED_GREEN : 0U;
		enum ev3_ui_color c = (enum ev3_ui_color)(red | green);

		if (c != l->color) {
			l->color = c;
			l->changes++;
		}
		hs_trace_set(l->sig, (uint64_t)l->color);
	}
}

enum ev3_ui_color ev3_ui_led_color(enum ev3_ui_led led)
{
	return (unsigned)led < EV3_UI_LEDS ? ui.leds[led].color : EV3_UI_LED_OFF;
}

uint32_t ev3_ui_led_changes(enum ev3_ui_led led)
{
	return (unsigned)led < EV3_UI_LEDS ? ui.leds[led].changes : 0;
}

/* ---- the board device ---- */

static ER ui_create(const struct hs_board_cfg *cfg, void **ctx)
{
	static const char *const led_signal[EV3_UI_LEDS] = { "led_left", "led_right" };
	bool board_code = !(cfg && cfg->cold_reset);
	unsigned w = 0;

	memset(&ui, 0, sizeof(ui));
	hs_rng_stream(&ui.rng, "ui.buttons");
	for (unsigned b = 0; b < EV3_UI_BUTTONS; b++) {
		if (board_code)
			hs_gpio_mux_as_gpio(ev3_ui_pins.button[b]);
		ui.buttons[b].sig = hs_trace_signal("ui", button_signal[b], 1);
		contact_apply((enum ev3_ui_button)b);
	}
	for (unsigned i = 0; i < EV3_UI_LEDS; i++) {
		const unsigned pins[2] = { ev3_ui_pins.red[i], ev3_ui_pins.green[i] };

		ui.leds[i].sig = hs_trace_signal("ui", led_signal[i], 2);
		hs_trace_set(ui.leds[i].sig, EV3_UI_LED_OFF);
		for (unsigned k = 0; k < 2; k++) {
			if (board_code)
				hs_gpio_mux_as_gpio(pins[k]);
			ui.watches[w] = hs_gpio_watch(pins[k], led_pin_changed, NULL);
			if (!ui.watches[w++])
				return E_NOMEM;
		}
	}
	ui.ready = true;
	*ctx = &ui;
	return E_OK;
}

static void ui_destroy(void *ctx)
{
	(void)ctx;
	for (unsigned i = 0; i < 2U * EV3_UI_LEDS; i++)
		hs_gpio_unwatch(ui.watches[i]);
	for (unsigned b = 0; b < EV3_UI_BUTTONS; b++)
		hs_event_cancel(&ui.buttons[b].bounce_ev);
	while (ui.jobs) {
		hs_event_cancel(&ui.jobs->ev);
		job_free(ui.jobs);
	}
	ui.ready = false;
}

const struct hs_device ev3_ui_device = { "EV3_UI", ui_create, NULL, ui_destroy };
