/*
 * app.c — notify: what an EV3RT 1.x (TOPPERS/HRP3) app does with time.
 *
 * Its cyclic handlers and alarm notify instead of calling a handler
 * (app.cfg): one activates the LED task every 0.5 s, one signals a
 * semaphore every 100 ms once main_task starts it, one sets an eventflag
 * every 250 ms, one sends a sample every 50 ms to a queue of one element
 * (nobody receives, so every send after the first fails and its error
 * notification counts it), one counts every 500 us.  main_task measures
 * HRP3's time: tslp_tsk, dly_tsk below a millisecond, get_tim (64-bit
 * microseconds), fch_hrt, the alarm, twai_sem's timeout, and logs it all.
 */
#include "ev3api.h"
#include "app.h"

intptr_t count_ticks;
intptr_t send_errors;
static int blinks;

/* Activated by BLINK_CYC: toggles the LED. */
void blink_task(intptr_t exinf)
{
	blinks++;
	ev3_led_set_color(blinks % 2 ? LED_GREEN : LED_OFF);
}

/* Microseconds between two get_tim readings. */
static unsigned long since(SYSTIM from)
{
	SYSTIM now;

	SVC_PERROR(get_tim(&now));
	return (unsigned long)(now - from);
}

void main_task(intptr_t exinf)
{
	SYSTIM start, t;
	HRTCNT h;
	FLGPTN ptn = 0;
	intptr_t sample = 0;
	int ticks = 0;
	ER ercd;

	syslog(LOG_NOTICE, "notify: SYSTIM is %u bytes, TMO_FEVR 0x%lx, TMAX_RELTIM %lu",
	       (unsigned)sizeof(SYSTIM), (unsigned long)TMO_FEVR, (unsigned long)TMAX_RELTIM);
	SVC_PERROR(get_tim(&start));

	t = start;
	ercd = tslp_tsk(500U * 1000U);
	syslog(LOG_NOTICE, "notify: tslp_tsk(500 ms) %s after %lu us", itron_strerror(ercd), since(t));

	h = fch_hrt();
	SVC_PERROR(dly_tsk(1500U));
	syslog(LOG_NOTICE, "notify: dly_tsk(1500 us) took %lu us", (unsigned long)(fch_hrt() - h));

	SVC_PERROR(get_tim(&t));
	SVC_PERROR(sta_cyc(TICK_CYC));
	while (ticks < 10 && wai_sem(TICK_SEM) == E_OK)
		ticks++;
	SVC_PERROR(stp_cyc(TICK_CYC));
	syslog(LOG_NOTICE, "notify: %d ticks in %lu ms", ticks, since(t) / 1000U);

	SVC_PERROR(clr_flg(QUARTER_FLG, 0));
	ercd = twai_flg(QUARTER_FLG, 0x01U, TWF_ORW, &ptn, 300U * 1000U);
	syslog(LOG_NOTICE, "notify: flag %s, pattern 0x%x", itron_strerror(ercd), (unsigned)ptn);

	SVC_PERROR(get_tim(&t));
	SVC_PERROR(sta_alm(WAKE_ALM, 200U * 1000U));
	SVC_PERROR(slp_tsk());
	syslog(LOG_NOTICE, "notify: woken by the alarm after %lu ms", since(t) / 1000U);

	SVC_PERROR(get_tim(&t));
	ercd = twai_sem(TICK_SEM, 50U * 1000U);
	syslog(LOG_NOTICE, "notify: twai_sem(50 ms) %s after %lu ms", itron_strerror(ercd), since(t) / 1000U);

	SVC_PERROR(dly_tsk(1000U * 1000U));
	SVC_PERROR(get_tim(&t));
	SVC_PERROR(prcv_dtq(SAMPLE_DTQ, &sample));
	syslog(LOG_NOTICE, "notify: at %lu ms: sample %d, %d sends failed, %d counts, %d blinks",
	       (unsigned long)((t - start) / 1000U), (int)sample, (int)send_errors, (int)count_ticks, blinks);
}
