/*
 * brick.c — the EV3 brick API: LEDs and buttons over d_ui (ui_hack).
 *
 * LED colours are one service call (a pattern byte written to d_ui).  A
 * button's state is a plain read of the pressed[] byte d_ui keeps in its
 * shared page (debounced by the driver).  Click handlers run in the API's
 * button task (EV3_BUTTON_TSKID, in EV3_BUTTON_TASK_DOMAIN): it waits in
 * d_ui for the next click (UI_FN_WAIT_CLICK) and calls the handler registered
 * for that button in task context — never in the GPIO interrupt, and with
 * the rights of its protection domain, not privileged.
 */
#include <string.h>
#include "ev3api_routines.h"
#include "ev3api_brick.h"
#include "api_internal.h"
#include "ui_hack.h"

/* How long the button task waits before asking again while d_ui is not loaded. */
#define BUTTON_RETRY_MS 100U

/* d_ui's index (LEGO's order) of each API button. */
static const uint8_t ui_index_of[TNUM_BUTTON] = {
	[LEFT_BUTTON] = LMS_UI_BUTTON_LEFT,   [RIGHT_BUTTON] = LMS_UI_BUTTON_RIGHT,
	[UP_BUTTON] = LMS_UI_BUTTON_UP,       [DOWN_BUTTON] = LMS_UI_BUTTON_DOWN,
	[ENTER_BUTTON] = LMS_UI_BUTTON_ENTER, [BACK_BUTTON] = LMS_UI_BUTTON_BACK,
};

/* d_ui's pattern byte of each colour. */
static const uint8_t pattern_of[TNUM_LED_COLOR] = {
	[LED_OFF] = LMS_UI_LED_OFF, [LED_RED] = LMS_UI_LED_RED,
	[LED_GREEN] = LMS_UI_LED_GREEN, [LED_ORANGE] = LMS_UI_LED_ORANGE,
};

struct click_handler {
	ISR handler;
	intptr_t exinf;
};

/* By d_ui's button index; a handler and its exinf change together under EV3_BUTTON_SEMID. */
static struct click_handler click_handlers[LMS_UI_BUTTONS];
static const struct lms_ui *ui_shm;

void api_brick_boot(void)
{
	memset(click_handlers, 0, sizeof(click_handlers));
	ui_shm = NULL;
}

ER ev3lx_led_set_color(ledcolor_t color)
{
	ER ercd = api_may_wait();

	if (ercd != E_OK)
		return ercd;
	if ((unsigned)color >= TNUM_LED_COLOR)
		return E_PAR;
	return ui_svc_led(pattern_of[color]);
}

ER ev3lx_button_is_pressed(button_t button, bool *p_pressed)
{
	ER ercd = api_may_read();

	if (ercd != E_OK)
		return ercd;
	if ((unsigned)button >= TNUM_BUTTON)
		return E_ID;
	ercd = API_CHECK_OUT(p_pressed);
	if (ercd != E_OK)
		return ercd;
	if (ui_shm == NULL) {
		const struct lms_ui *map = NULL;

		ercd = api_may_wait();	/* the first reading maps the memory: a service call */
		if (ercd == E_OK)
			ercd = ui_svc_map(&map);
		if (ercd != E_OK)
			return ercd;
		ui_shm = map;
	}
	*p_pressed = *(const volatile uint8_t *)&ui_shm->pressed[ui_index_of[button]] != 0;
	return E_OK;
}

ER ev3lx_button_set_on_clicked(button_t button, ISR handler, intptr_t exinf)
{
	struct click_handler *h;
	ER ercd;

	ercd = api_may_wait();
	if (ercd != E_OK)
		return ercd;
	if ((unsigned)button >= TNUM_BUTTON)
		return E_ID;
	h = &click_handlers[ui_index_of[button]];
	ercd = wai_sem(EV3_BUTTON_SEMID);
	if (ercd != E_OK)
		return ercd;
	h->handler = handler;
	h->exinf = handler ? exinf : 0;
	sig_sem(EV3_BUTTON_SEMID);
	return E_OK;
}

/* Calls the handler of d_ui button index (if any), outside the lock: it may register handlers. */
static void dispatch_click(unsigned index)
{
	struct click_handler h = { NULL, 0 };

	if (index >= LMS_UI_BUTTONS || wai_sem(EV3_BUTTON_SEMID) != E_OK)
		return;
	h = click_handlers[index];
	sig_sem(EV3_BUTTON_SEMID);
	if (h.handler)
		h.handler(h.exinf);
}

/*
 * The button task: takes clicks off d_ui's queue and runs their handlers.
 * rel_wai(EV3_BUTTON_TSKID) ends it cleanly (it leaves the driver's wait
 * queue, then returns: dormant); act_tsk starts it again.
 */
void api_button_task(intptr_t exinf)
{
	struct lms_ui_click click;
	ER ercd;

	(void)exinf;
	for (;;) {
		ercd = ui_svc_wait_click(&click, TMO_FEVR);
		if (ercd == E_OK)
			dispatch_click(click.button);
		else if (ercd == E_RLWAI)
			return;
		else if (dly_tsk(BUTTON_RETRY_MS) == E_RLWAI)	/* d_ui not loaded (yet) */
			return;
	}
}
