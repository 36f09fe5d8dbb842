/*
 * test_brick_api.c — the brick API end to end on host_sim: LED colours reach
 * the LED pins, ev3lx_button_is_pressed follows the button model (debounced,
 * every button mapped), click handlers run in the API's button task — task
 * context, its ID, its user domain's rights, never in the interrupt — with
 * their exinf, can be replaced, removed and re-registered from a handler;
 * the button task stops on rel_wai and restarts without losing a click;
 * every error code.
 */
#include "ev3api_routines.h"
#include "api_test.h"
#include "host_sim/devices/ev3_ui.h"

#define CLICK_WAIT_MS 120      /* a 50 ms click, debounce, the task's turn */

static int kernel_only;        /* outside every user domain */

/* The model's button behind each API button. */
static const enum ev3_ui_button model_of[TNUM_BUTTON] = {
	[LEFT_BUTTON] = EV3_UI_BUTTON_LEFT, [RIGHT_BUTTON] = EV3_UI_BUTTON_RIGHT,
	[UP_BUTTON] = EV3_UI_BUTTON_UP, [DOWN_BUTTON] = EV3_UI_BUTTON_DOWN,
	[ENTER_BUTTON] = EV3_UI_BUTTON_ENTER, [BACK_BUTTON] = EV3_UI_BUTTON_BACK,
};

/* What the handler saw, per call. */
static struct {
	unsigned calls;
	intptr_t exinf;
	bool task_context;
	ID tid;
	bool stack_ok, kernel_refused;
} seen;

static void on_click(intptr_t exinf)
{
	int on_stack = 0;
	ID tid = TSK_NONE;

	seen.calls++;
	seen.exinf = exinf;
	seen.task_context = !sns_ctx();
	seen.tid = get_tid(&tid) == E_OK ? tid : TSK_NONE;
	seen.stack_ok = prb_mem(&on_stack, sizeof(on_stack), TSK_SELF, TPM_WRITE) == E_OK;
	seen.kernel_refused = prb_mem(&kernel_only, sizeof(kernel_only), TSK_SELF, TPM_WRITE) != E_OK;
}

static unsigned chained_calls;

/* A handler that registers another one (no lock is held while handlers run). */
static void on_back_register_left(intptr_t exinf)
{
	(void)exinf;
	chained_calls++;
	ev3lx_button_set_on_clicked(LEFT_BUTTON, on_click, 77);
}

static void click(button_t b)
{
	ev3_ui_click_at(rtos_host_now() + AT_MS, model_of[b], 50 * AT_MS);
	dly_tsk(CLICK_WAIT_MS);
}

static void leds(void)
{
	static const struct { ledcolor_t api; enum ev3_ui_color model; const char *name; } rows[] = {
		{ LED_RED, EV3_UI_LED_RED, "red" }, { LED_GREEN, EV3_UI_LED_GREEN, "green" },
		{ LED_ORANGE, EV3_UI_LED_ORANGE, "orange" }, { LED_OFF, EV3_UI_LED_OFF, "off" },
	};

	for (unsigned i = 0; i < 4; i++) {
		is_int(ev3lx_led_set_color(rows[i].api), E_OK, "ev3lx_led_set_color %s", rows[i].name);
		ok(ev3_ui_led_color(EV3_UI_LED_LEFT) == rows[i].model &&
		   ev3_ui_led_color(EV3_UI_LED_RIGHT) == rows[i].model, "both LEDs %s on the pins", rows[i].name);
	}
	is_int(ev3lx_led_set_color(TNUM_LED_COLOR), E_PAR, "colour TNUM_LED_COLOR: E_PAR");
	is_int(ev3lx_led_set_color((ledcolor_t)-1), E_PAR, "colour -1: E_PAR");
	ok(ev3_ui_led_color(EV3_UI_LED_LEFT) == EV3_UI_LED_OFF, "and nothing changed");
}

static void pressed(void)
{
	bool p = true, mapping = true, released = true;

	is_int(ev3lx_button_is_pressed(ENTER_BUTTON, &p), E_OK, "is_pressed");
	ok(!p, "nothing pressed at first");
	for (unsigned b = 0; b < TNUM_BUTTON; b++) {
		ev3_ui_button_set(model_of[b], true);
		dly_tsk(30);
		for (unsigned o = 0; o < TNUM_BUTTON; o++) {
			ev3lx_button_is_pressed((button_t)o, &p);
			mapping &= p == (o == b);
		}
		ev3_ui_button_set(model_of[b], false);
		dly_tsk(30);
		ev3lx_button_is_pressed((button_t)b, &p);
		released &= !p;
	}
	ok(mapping, "each button, and only it, reads pressed while held");
	ok(released, "and released after");
	ev3_ui_button_set(EV3_UI_BUTTON_UP, true);
	dly_tsk(5);
	ev3lx_button_is_pressed(UP_BUTTON, &p);
	ok(!p, "a press younger than the debounce time is not reported yet");
	ev3_ui_button_set(EV3_UI_BUTTON_UP, false);
	dly_tsk(30);
	is_int(ev3lx_button_is_pressed(TNUM_BUTTON, &p), E_ID, "button TNUM_BUTTON: E_ID");
	is_int(ev3lx_button_is_pressed((button_t)-1, &p), E_ID, "button -1: E_ID");
	is_int(ev3lx_button_is_pressed(LEFT_BUTTON, NULL), E_MACV, "NULL: E_MACV");
	is_int(ev3lx_button_is_pressed(LEFT_BUTTON, (bool *)&kernel_only), E_MACV,
	       "memory outside the task's domain: E_MACV");
}

static ER irq_ercd;

static void from_irq(void *arg)
{
	(void)arg;
	irq_ercd = ev3lx_button_set_on_clicked(UP_BUTTON, on_click, 1);
}

static void handlers(void)
{
	is_int(ev3lx_button_set_on_clicked(ENTER_BUTTON, on_click, 42), E_OK, "set_on_clicked ENTER");
	click(ENTER_BUTTON);
	is_int(seen.calls, 1, "one click, one call");
	is_int(seen.exinf, 42, "with its exinf");
	ok(seen.task_context, "in task context (sns_ctx() false)");
	is_int(seen.tid, EV3_BUTTON_TSKID, "in the API's button task (ID %d)", EV3_BUTTON_TSKID);
	ok(seen.stack_ok && seen.kernel_refused,
	   "with its user domain's rights: its stack yes, kernel memory no");
	click(UP_BUTTON);
	is_int(seen.calls, 1, "a button without a handler calls nothing");
	ev3_ui_button_set(EV3_UI_BUTTON_ENTER, true);
	dly_tsk(CLICK_WAIT_MS);
	is_int(seen.calls, 1, "a press alone calls nothing");
	ev3_ui_button_set(EV3_UI_BUTTON_ENTER, false);
	dly_tsk(CLICK_WAIT_MS);
	is_int(seen.calls, 2, "its release does");

	ev3lx_button_set_on_clicked(ENTER_BUTTON, on_click, 43);
	click(ENTER_BUTTON);
	ok(seen.calls == 3 && seen.exinf == 43, "a new registration replaces the old");
	is_int(ev3lx_button_set_on_clicked(ENTER_BUTTON, NULL, 0), E_OK, "NULL removes it");
	click(ENTER_BUTTON);
	is_int(seen.calls, 3, "and the click calls nothing");

	ev3lx_button_set_on_clicked(BACK_BUTTON, on_back_register_left, 0);
	click(BACK_BUTTON);
	click(LEFT_BUTTON);
	ok(chained_calls == 1 && seen.calls == 4 && seen.exinf == 77,
	   "a handler may register handlers");

	is_int(ev3lx_button_set_on_clicked(TNUM_BUTTON, on_click, 0), E_ID, "button TNUM_BUTTON: E_ID");
	is_int(ev3lx_button_set_on_clicked((button_t)-1, on_click, 0), E_ID, "button -1: E_ID");
	hs_sim_at(rtos_host_now() + AT_MS, from_irq, NULL);
	dly_tsk(2);
	is_int(irq_ercd, E_CTX, "from an interrupt: E_CTX");
	click(UP_BUTTON);
	is_int(seen.calls, 4, "and nothing registered");
}

static void stop_and_restart(void)
{
	ev3lx_button_set_on_clicked(RIGHT_BUTTON, on_click, 5);
	is_int(rel_wai(EV3_BUTTON_TSKID), E_OK, "rel_wai stops the button task");
	click(RIGHT_BUTTON);
	is_int(seen.calls, 4, "no handler runs while it is stopped");
	is_int(act_tsk(EV3_BUTTON_TSKID), E_OK, "act_tsk starts it again");
	dly_tsk(5);
	ok(seen.calls == 5 && seen.exinf == 5, "the click queued meanwhile is handled: none lost");
	click(RIGHT_BUTTON);
	is_int(seen.calls, 6, "and new clicks too");
}

static void body(void)
{
	leds();
	pressed();
	handlers();
	stop_and_restart();
}

int main(void)
{
	tap_plan(11 + 9 + 17 + 5 + 1);
	ok(at_run(NULL, body, 11, 60), "the brick application finished");
	return tap_done();
}
