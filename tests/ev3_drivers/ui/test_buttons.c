/*
 * test_buttons.c — d_ui's buttons on host_sim through ui_hack: both edges
 * reach pressed[] only after debounce_ms of stability, bounce and glitches
 * make no extra presses or clicks, a release after a press queues one click
 * (button, held time, seq) in order, the queue keeps 16 and counts the rest
 * as dropped, and waits for a click end with the click, the timeout or
 * rel_wai; two waiters share the clicks.
 */
#include "ui_test.h"

static const struct lms_ui_click no_click;

/* Takes the oldest click without waiting. */
static ER poll_click(struct lms_ui_click *c)
{
	*c = no_click;
	return ui_svc_wait_click(c, TMO_POL);
}

/* BACK is held down when the brick powers on. */
static void hold_back(void)
{
	ev3_ui_button_set(EV3_UI_BUTTON_BACK, true);
}

static void boot_state(void)
{
	struct lms_ui_click c;
	bool none = true;

	for (unsigned b = 0; b < LMS_UI_BUTTONS; b++)
		none &= uit_pressed(b) == (b == LMS_UI_BUTTON_BACK);
	ok(none, "only BACK, held since power-on, reads pressed");
	is_int(uit_u32(&uit_shm->presses[LMS_UI_BUTTON_BACK]), 0, "without a press counted");
	ev3_ui_button_set(EV3_UI_BUTTON_BACK, false);
	dly_tsk(UIT_DEBOUNCE_MS + 5);
	ok(uit_pressed(LMS_UI_BUTTON_BACK) == 0 && poll_click(&c) == E_TMOUT,
	   "its release: not pressed, and no click (its press was not seen)");
	is_int(uit_shm->led, LMS_UI_LED_OFF, "LEDs off at boot");
	is_int(uit_u32(&uit_shm->clicks), 0, "no clicks yet");
}

static void clean_click(void)
{
	struct lms_ui_click c;

	ev3_ui_button_set(EV3_UI_BUTTON_ENTER, true);
	dly_tsk(UIT_DEBOUNCE_MS - 5);
	is_int(uit_pressed(LMS_UI_BUTTON_ENTER), 0, "pressed: not yet counted within debounce");
	dly_tsk(7);
	is_int(uit_pressed(LMS_UI_BUTTON_ENTER), 1, "counted once stable for debounce_ms");
	is_int(uit_u32(&uit_shm->presses[LMS_UI_BUTTON_ENTER]), 1, "one press");
	is_int(poll_click(&c), E_TMOUT, "a press alone is no click");
	dly_tsk(100 - UIT_DEBOUNCE_MS - 2);
	ev3_ui_button_set(EV3_UI_BUTTON_ENTER, false);
	dly_tsk(UIT_DEBOUNCE_MS - 5);
	is_int(uit_pressed(LMS_UI_BUTTON_ENTER), 1, "released: still pressed within debounce");
	dly_tsk(7);
	is_int(uit_pressed(LMS_UI_BUTTON_ENTER), 0, "falling edge counted");
	is_int(poll_click(&c), E_OK, "the release queued a click");
	ok(c.button == LMS_UI_BUTTON_ENTER && c.seq == 1 && c.reserved == 0,
	   "ENTER, seq 1 (%u, %u)", c.button, (unsigned)c.seq);
	in_range(c.held_ms, 99, 101, "held 100 ms (edge to edge)");
	is_int(poll_click(&c), E_TMOUT, "exactly one click");
}

static void glitch(void)
{
	struct lms_ui_click c;
	uint32_t bounces = uit_u32(&uit_shm->bounces);

	ev3_ui_button_set(EV3_UI_BUTTON_LEFT, true);
	dly_tsk(5);
	ev3_ui_button_set(EV3_UI_BUTTON_LEFT, false);
	dly_tsk(50);
	is_int(uit_u32(&uit_shm->presses[LMS_UI_BUTTON_LEFT]), 0, "a 5 ms glitch is no press");
	is_int(poll_click(&c), E_TMOUT, "and no click");
	ok(uit_u32(&uit_shm->bounces) > bounces, "counted as a bounce");
}

/* Press and release UP with 5 ms contact bounce; pressed[] must change once each way,
 * debounce_ms after the contact's last edge. */
static void bounced_click(void)
{
	struct hs_signal *contact = hs_trace_find("ui", "btn_up");
	struct lms_ui_click c;
	uint64_t settled = 0;
	unsigned changes = 0, ms;
	uint8_t last = 0;

	ev3_ui_set_bounce(5000);
	ev3_ui_button_set(EV3_UI_BUTTON_UP, true);
	for (ms = 0; ms < 60; ms++) {
		dly_tsk(1);
		if (uit_pressed(LMS_UI_BUTTON_UP) != last) {
			last = uit_pressed(LMS_UI_BUTTON_UP);
			changes++;
			settled = rtos_host_now();
		}
	}
	ok(ev3_ui_contact_changes(EV3_UI_BUTTON_UP) >= 3, "the contact bounced (%u changes)",
	   (unsigned)ev3_ui_contact_changes(EV3_UI_BUTTON_UP));
	ok(changes == 1 && last == 1, "pressed[] changed once (%u)", changes);
	in_range((settled - hs_signal_last_change(contact)) / 100000U, UIT_DEBOUNCE_MS * 10,
		 UIT_DEBOUNCE_MS * 10 + 12, "settled debounce_ms after the last bounce (x0.1 ms)");
	ev3_ui_button_set(EV3_UI_BUTTON_UP, false);
	dly_tsk(60);
	is_int(uit_pressed(LMS_UI_BUTTON_UP), 0, "released after its bounce");
	is_int(uit_u32(&uit_shm->presses[LMS_UI_BUTTON_UP]), 1, "one press");
	is_int(poll_click(&c), E_OK, "one click");
	ok(c.button == LMS_UI_BUTTON_UP && c.seq == 2, "UP, seq 2");
	is_int(poll_click(&c), E_TMOUT, "no second click from the bounce");
	ev3_ui_set_bounce(0);
}

static void two_buttons(void)
{
	struct lms_ui_click a, b;
	uint64_t t = rtos_host_now() + UIT_MS;

	ev3_ui_click_at(t, EV3_UI_BUTTON_RIGHT, 60 * UIT_MS);
	ev3_ui_click_at(t, EV3_UI_BUTTON_DOWN, 30 * UIT_MS);
	dly_tsk(UIT_DEBOUNCE_MS + 3);
	ok(uit_pressed(LMS_UI_BUTTON_RIGHT) && uit_pressed(LMS_UI_BUTTON_DOWN), "both held together");
	dly_tsk(80);
	is_int(poll_click(&a), E_OK, "first click");
	is_int(poll_click(&b), E_OK, "second click");
	ok(a.button == LMS_UI_BUTTON_DOWN && b.button == LMS_UI_BUTTON_RIGHT && b.seq == a.seq + 1,
	   "in release order: DOWN then RIGHT");
	ok(a.held_ms == 30 && b.held_ms == 60, "held 30 and 60 ms (%u, %u)", a.held_ms, b.held_ms);
}

static void overflow(void)
{
	struct lms_ui_click c;
	uint32_t first = uit_u32(&uit_shm->clicks) + 1;
	uint64_t t = rtos_host_now() + UIT_MS;
	unsigned n = 0;
	bool in_order = true;

	for (unsigned i = 0; i < LMS_UI_CLICK_QUEUE + 2; i++)
		ev3_ui_click_at(t + i * 60 * UIT_MS, EV3_UI_BUTTON_BACK, 30 * UIT_MS);
	dly_tsk((LMS_UI_CLICK_QUEUE + 2) * 60 + 40);
	is_int(uit_u32(&uit_shm->clicks), first + LMS_UI_CLICK_QUEUE + 1, "18 clicks happened");
	is_int(uit_u32(&uit_shm->dropped), 2, "2 dropped: the queue holds 16");
	while (poll_click(&c) == E_OK) {
		in_order &= c.seq == first + n && c.button == LMS_UI_BUTTON_BACK;
		n++;
	}
	is_int(n, LMS_UI_CLICK_QUEUE, "16 clicks read");
	ok(in_order, "the oldest 16, in order");
}

static void timeouts(void)
{
	struct lms_ui_click c;
	uint64_t t0 = uit_now_ms();

	is_int(ui_svc_wait_click(&c, 50), E_TMOUT, "wait 50 ms without a click: E_TMOUT");
	in_range(uit_now_ms() - t0, 50, 51, "after 50 ms");
	ev3_ui_click_at(rtos_host_now() + 30 * UIT_MS, EV3_UI_BUTTON_ENTER, 50 * UIT_MS);
	t0 = uit_now_ms();
	c = no_click;
	is_int(ui_svc_wait_click(&c, 200), E_OK, "a click within the timeout");
	ok(c.button == LMS_UI_BUTTON_ENTER && c.held_ms == 50, "ENTER, held 50 ms");
	in_range(uit_now_ms() - t0, 30 + 50 + UIT_DEBOUNCE_MS, 30 + 50 + UIT_DEBOUNCE_MS + 1,
		 "delivered debounce_ms after the release");
	ev3_ui_click_at(rtos_host_now() + 500 * UIT_MS, EV3_UI_BUTTON_DOWN, 50 * UIT_MS);
	is_int(ui_svc_wait_click(&c, TMO_FEVR), E_OK, "TMO_FEVR waits for the click");
	is_int(c.button, LMS_UI_BUTTON_DOWN, "DOWN");
}

static volatile ER helper_ercd;
static struct lms_ui_click helper_click;

static void helper_wait(void)
{
	struct lms_ui_click c = no_click;

	helper_ercd = E_SYS;
	helper_ercd = ui_svc_wait_click(&c, TMO_FEVR);
	helper_click = c;
}

static void release_and_share(void)
{
	struct lms_ui_click c;

	is_int(uit_start_helper(helper_wait), E_OK, "a second task waits forever");
	dly_tsk(10);
	is_int(helper_ercd, E_SYS, "still waiting");
	is_int(rel_wai(UIT_HELPER_ID), E_OK, "rel_wai ends its wait");
	dly_tsk(1);
	is_int(helper_ercd, E_RLWAI, "the wait returned E_RLWAI");
	ev3_ui_click_at(rtos_host_now() + UIT_MS, EV3_UI_BUTTON_LEFT, 50 * UIT_MS);
	dly_tsk(100);
	is_int(poll_click(&c), E_OK, "the released waiter left nothing behind: a click arrives");

	/* Two waiters: the helper (higher priority) takes the first click, we the second. */
	uit_start_helper(helper_wait);
	ev3_ui_click_at(rtos_host_now() + UIT_MS, EV3_UI_BUTTON_UP, 50 * UIT_MS);
	ev3_ui_click_at(rtos_host_now() + 200 * UIT_MS, EV3_UI_BUTTON_BACK, 50 * UIT_MS);
	c = no_click;
	is_int(ui_svc_wait_click(&c, 1000), E_OK, "two waiters: ours got a click");
	ok(helper_ercd == E_OK && helper_click.button == LMS_UI_BUTTON_UP &&
	   c.button == LMS_UI_BUTTON_BACK && c.seq == helper_click.seq + 1,
	   "the helper got UP, we got BACK: each click once");
}

static void body(void)
{
	boot_state();
	clean_click();
	glitch();
	bounced_click();
	two_buttons();
	overflow();
	timeouts();
	release_and_share();
}

int main(void)
{
	uit_domain = 1;		/* the service calls from a user domain, as an application */
	uit_at_power_on = hold_back;
	tap_plan(1 + 5 + 10 + 3 + 8 + 5 + 4 + 7 + 7);
	ok(uit_run(body, 3), "scenario ran to its end");
	return tap_done();
}
