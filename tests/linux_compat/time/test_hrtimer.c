/*
 * test_hrtimer.c — hrtimers through the real RTOS tick: zero drift over a
 * million periods, never early and late by less than a tick (random REL and
 * ABS starts), FIFO among equal expiries, timers started and cancelled from
 * callbacks, self-cancellation, overruns after a long CPU lock.
 */
#include "tap.h"
#include "lx_core_test.h"
#include <linux/hrtimer.h>
#include <linux/completion.h>
#include <linux/delay.h>
#include <kernel.h>
#include <linux_compat/clock.h>
#include <sil.h>

#define TICK	((s64)LX_TICK_NS)

/* ---- zero drift ---- */

#define DRIFT_PERIODS	1000000
#define DRIFT_PERIOD_NS	300000     /* 1.5 ticks: every firing is rounded up */

static struct hrtimer drift_timer;
static s64 drift_first_expiry;
static long drift_count, drift_early, drift_late, drift_bad_overrun;
static s64 drift_last_expiry;

static enum hrtimer_restart drift_cb(struct hrtimer *t)
{
	s64 now = ktime_get();
	s64 expected = drift_first_expiry + (s64)drift_count * DRIFT_PERIOD_NS;

	if (hrtimer_get_expires(t) != expected || now < expected)
		drift_early++;
	if (now - expected >= TICK)
		drift_late++;
	drift_count++;
	if (drift_count == DRIFT_PERIODS) {
		drift_last_expiry = hrtimer_get_expires(t);
		return HRTIMER_NORESTART;
	}
	if (hrtimer_forward_now(t, ns_to_ktime(DRIFT_PERIOD_NS)) != 1)
		drift_bad_overrun++;
	return HRTIMER_RESTART;
}

static void drift_task(intptr_t exinf)
{
	(void)exinf;
	udelay(37);   /* start off the tick grid */
	hrtimer_init(&drift_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	drift_timer.function = drift_cb;
	drift_first_expiry = ktime_get() + DRIFT_PERIOD_NS;
	hrtimer_start(&drift_timer, ns_to_ktime(DRIFT_PERIOD_NS), HRTIMER_MODE_REL);
}

static void test_zero_drift(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, drift_task, 5, true) };

	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return;
	rtos_host_run_for((uint64_t)(DRIFT_PERIODS + 2) * DRIFT_PERIOD_NS);
	is_int(drift_count, DRIFT_PERIODS, "a million periods ran");
	is_int(drift_early, 0, "no firing before its expiry, every expiry on the original grid");
	is_int(drift_late, 0, "every firing less than one tick late");
	is_int(drift_bad_overrun, 0, "forward_now reports one period each time");
	is_int(drift_last_expiry - drift_first_expiry, (s64)(DRIFT_PERIODS - 1) * DRIFT_PERIOD_NS,
	       "zero drift: the millionth expiry is exactly 999999 periods after the first");
	ok(!hrtimer_active(&drift_timer), "timer inactive after NORESTART");
	rtos_host_shutdown();
}

/* ---- never early, random REL and ABS starts ---- */

#define RANDOM_STARTS	3000

static struct hrtimer rnd_timer;
static DECLARE_COMPLETION(rnd_done);
static s64 rnd_fired_at;
static long rnd_early, rnd_late, rnd_off_tick, rnd_runs, rnd_abs_runs;
static s64 rnd_max_late;

static enum hrtimer_restart rnd_cb(struct hrtimer *t)
{
	(void)t;
	rnd_fired_at = ktime_get();
	complete(&rnd_done);
	return HRTIMER_NORESTART;
}

static void random_task(intptr_t exinf)
{
	uint32_t seed = 0x2545F491U;
	int i;

	(void)exinf;
	hrtimer_setup(&rnd_timer, rnd_cb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	for (i = 0; i < RANDOM_STARTS; i++) {
		bool abs_mode = lxc_rand(&seed) & 1U;
		s64 delay = (s64)(lxc_rand(&seed) % 3000000U);   /* 0 .. 3 ms */
		s64 expiry;

		udelay(lxc_rand(&seed) % 199U);   /* start anywhere inside a tick */
		ndelay(lxc_rand(&seed) % 1000U);
		if (abs_mode) {
			expiry = ktime_get() + delay;
			hrtimer_start(&rnd_timer, expiry, HRTIMER_MODE_ABS);
			rnd_abs_runs++;
		} else {
			expiry = ktime_get() + delay;
			hrtimer_start(&rnd_timer, ns_to_ktime(delay), HRTIMER_MODE_REL);
		}
		wait_for_completion(&rnd_done);
		if (rnd_fired_at < expiry)
			rnd_early++;
		if (rnd_fired_at - expiry >= TICK)
			rnd_late++;
		if (rnd_fired_at - expiry > rnd_max_late)
			rnd_max_late = rnd_fired_at - expiry;
		if (rnd_fired_at % TICK != 0)
			rnd_off_tick++;
		rnd_runs++;
	}
}

static void test_never_early(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, random_task, 5, true) };

	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return;
	rtos_host_run_for((uint64_t)RANDOM_STARTS * 4000000U);
	is_int(rnd_runs, RANDOM_STARTS, "all random starts fired (woken by complete() from the callback)");
	ok(rnd_abs_runs > RANDOM_STARTS / 3, "both ABS (%ld) and REL starts were exercised", rnd_abs_runs);
	is_int(rnd_early, 0, "never early");
	is_int(rnd_late, 0, "never a full tick late (max %lld ns)", (long long)rnd_max_late);
	is_int(rnd_off_tick, 0, "callbacks run at tick boundaries (expiry rounded up to the tick)");
	rtos_host_shutdown();
}

/* ---- callbacks starting, cancelling and re-initialising timers ---- */

static struct hrtimer ta, tb, tc, td, fifo[3];
static char order_log[64];
static s64 a_fired, b_fired, c_fired;
static int cancel_other_ret = -5, self_try_ret = -5, self_cancel_ret = -5;
static int self_runs;
static char fifo_log[8];

static void log_char(char c)
{
	size_t n = strlen(order_log);

	if (n + 1 < sizeof(order_log)) {
		order_log[n] = c;
		order_log[n + 1] = '\0';
	}
}

static enum hrtimer_restart b_cb(struct hrtimer *t)
{
	(void)t;
	b_fired = ktime_get();
	log_char('B');
	return HRTIMER_NORESTART;
}

static enum hrtimer_restart c_cb(struct hrtimer *t)
{
	(void)t;
	c_fired = ktime_get();
	log_char('C');
	return HRTIMER_NORESTART;
}

static enum hrtimer_restart never_cb(struct hrtimer *t)
{
	(void)t;
	log_char('X');
	return HRTIMER_NORESTART;
}

/* A starts B 1 ms later, C at an absolute time already past, cancels D, re-inits itself. */
static enum hrtimer_restart a_cb(struct hrtimer *t)
{
	a_fired = ktime_get();
	log_char('A');
	hrtimer_init(&tb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);   /* as d_analog does */
	tb.function = b_cb;
	hrtimer_start(&tb, ms_to_ktime(1), HRTIMER_MODE_REL);
	hrtimer_setup(&tc, c_cb, CLOCK_MONOTONIC, HRTIMER_MODE_ABS);
	hrtimer_start(&tc, a_fired - 5000, HRTIMER_MODE_ABS);
	cancel_other_ret = hrtimer_cancel(&td);
	(void)t;
	return HRTIMER_NORESTART;
}

/* Restarts itself once with try_to_cancel (-1: running) then cancels itself. */
static enum hrtimer_restart self_cb(struct hrtimer *t)
{
	self_runs++;
	if (self_runs == 1) {
		self_try_ret = hrtimer_try_to_cancel(t);
		hrtimer_forward_now(t, us_to_ktime(500));
		return HRTIMER_RESTART;
	}
	rtos_host_expect_bugs(true);
	self_cancel_ret = hrtimer_cancel(t);
	rtos_host_expect_bugs(false);
	hrtimer_forward_now(t, us_to_ktime(500));
	return HRTIMER_RESTART;    /* ignored: the timer was cancelled */
}

static enum hrtimer_restart fifo_cb(struct hrtimer *t)
{
	size_t n = strlen(fifo_log);

	fifo_log[n] = (char)('0' + (t - fifo));
	fifo_log[n + 1] = '\0';
	return HRTIMER_NORESTART;
}

static void callbacks_task(intptr_t exinf)
{
	s64 at;
	int i;

	(void)exinf;
	hrtimer_setup(&ta, a_cb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimer_setup(&td, never_cb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimer_start(&td, ms_to_ktime(3), HRTIMER_MODE_REL);
	hrtimer_start(&ta, ms_to_ktime(2), HRTIMER_MODE_REL);
	ok(hrtimer_is_queued(&ta) && hrtimer_active(&ta), "a started timer is queued and active");
	at = ktime_get() + 10 * NSEC_PER_MSEC + 12345;
	for (i = 2; i >= 0; i--)
		hrtimer_setup(&fifo[i], fifo_cb, CLOCK_MONOTONIC, HRTIMER_MODE_ABS);
	hrtimer_start(&fifo[2], at, HRTIMER_MODE_ABS);
	hrtimer_start(&fifo[0], at, HRTIMER_MODE_ABS);
	hrtimer_start(&fifo[1], at, HRTIMER_MODE_ABS);
	hrtimer_setup(&tc, c_cb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	msleep(20);
	hrtimer_setup(&ta, self_cb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimer_start(&ta, us_to_ktime(500), HRTIMER_MODE_REL);
	msleep(5);
}

static void test_callbacks(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, callbacks_task, 5, true) };
	uint_t bugs;

	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return;
	rtos_host_run_for(40 * NSEC_PER_MSEC);
	is_str(order_log, "ACB", "A ran, C (already due) at the next tick, B a millisecond later, D never");
	ok(c_fired > a_fired && c_fired - a_fired <= TICK, "a past ABS expiry from a callback runs at the next tick");
	ok(b_fired - a_fired >= NSEC_PER_MSEC && b_fired - a_fired < NSEC_PER_MSEC + TICK,
	   "a timer started from another timer's callback fires 1 ms later (%lld ns)",
	   (long long)(b_fired - a_fired));
	is_int(cancel_other_ret, 1, "hrtimer_cancel of another queued timer from a callback returns 1");
	is_str(fifo_log, "201", "equal expiries fire in the order they were started");
	is_int(self_try_ret, -1, "hrtimer_try_to_cancel from its own callback returns -1");
	is_int(self_runs, 2, "a RESTART after try_to_cancel runs again; after hrtimer_cancel it does not");
	is_int(self_cancel_ret, 1, "hrtimer_cancel from its own callback returns 1 (it was active)");
	bugs = rtos_host_bug_count();
	is_int(bugs, 1, "self-cancellation with hrtimer_cancel is reported once");
	ok(strstr(rtos_host_last_bug(), "hrtimer_cancel would deadlock") != NULL &&
	   strstr(rtos_host_last_bug(), "own callback") != NULL,
	   "the report names the deadlock and the context: %s", rtos_host_last_bug());
	ok(!hrtimer_active(&ta), "the self-cancelled timer is inactive");
	rtos_host_shutdown();
}

/* ---- overruns after a long CPU lock ---- */

static struct hrtimer ov_timer;
static s64 ov_start;
static u64 ov_overruns[8];
static int ov_n;
static bool ov_grid_ok = true;

static enum hrtimer_restart ov_cb(struct hrtimer *t)
{
	u64 n = hrtimer_forward_now(t, ms_to_ktime(1));

	if (ov_n < 8)
		ov_overruns[ov_n++] = n;
	if ((hrtimer_get_expires(t) - ov_start) % NSEC_PER_MSEC != 0 || hrtimer_get_expires(t) <= ktime_get())
		ov_grid_ok = false;
	return ov_n < 8 ? HRTIMER_RESTART : HRTIMER_NORESTART;
}

static void overrun_task(intptr_t exinf)
{
	(void)exinf;
	hrtimer_setup(&ov_timer, ov_cb, CLOCK_MONOTONIC, HRTIMER_MODE_ABS);
	ov_start = ktime_get() + NSEC_PER_MSEC;
	hrtimer_start(&ov_timer, ov_start, HRTIMER_MODE_ABS);
	msleep(2);                  /* two normal periods */
	loc_cpu();
	sil_dly_nse(10500000);      /* 10.5 ms with every interrupt held off */
	unl_cpu();
}

static void test_overrun(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, overrun_task, 5, true) };
	int i, big = -1;

	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return;
	rtos_host_run_for(30 * NSEC_PER_MSEC);
	is_int(ov_n, 8, "the periodic timer ran 8 times");
	for (i = 0; i < ov_n; i++)
		if (ov_overruns[i] > 1)
			big = i;
	ok(big >= 0 && ov_overruns[big] >= 10 && ov_overruns[big] <= 12,
	   "after a 10.5 ms CPU lock forward_now reports the missed periods (%llu)",
	   big >= 0 ? (unsigned long long)ov_overruns[big] : 0ULL);
	ok(ov_grid_ok, "every forwarded expiry stays on the 1 ms grid and in the future");
	rtos_host_shutdown();
}

/* ---- pure arithmetic ---- */

static void test_forward_math(void)
{
	const ktime_t r = (ktime_t)hrtimer_resolution;   /* one tick */
	struct hrtimer t;

	hrtimer_init(&t, CLOCK_MONOTONIC, HRTIMER_MODE_ABS);
	hrtimer_set_expires(&t, 10 * r);
	is_u64(hrtimer_forward(&t, 10 * r - 1, r), 0, "forward before the expiry: 0 overruns");
	is_int(hrtimer_get_expires(&t), 10 * r, "...and the expiry is unchanged");
	is_u64(hrtimer_forward(&t, 10 * r, r), 1, "forward at the expiry: 1 overrun");
	is_int(hrtimer_get_expires(&t), 11 * r, "...expiry moved one interval");
	is_u64(hrtimer_forward(&t, 14 * r + r / 2, r), 4, "forward 3.5 intervals late: 4 intervals");
	is_int(hrtimer_get_expires(&t), 15 * r, "...expiry after now, on the grid");
	/* Linux (kernel/time/hrtimer.c): whole intervals until the expiry is after
	 * now, so now on the grid, whole intervals late, takes one more. */
	hrtimer_set_expires(&t, 10 * r);
	is_u64(hrtimer_forward(&t, 11 * r, r), 2, "forward exactly 1 interval late: 2 intervals");
	is_int(hrtimer_get_expires(&t), 12 * r, "...expiry one interval after now, not at now");
	is_u64(hrtimer_forward(&t, 15 * r, r), 4, "forward exactly 3 intervals late: 4 intervals");
	is_int(hrtimer_get_expires(&t), 16 * r, "...expiry one interval after now");
	hrtimer_set_expires(&t, 15 * r);
	/* Linux clamps an interval below hrtimer_resolution to it. */
	is_u64(hrtimer_forward(&t, 15 * r, 100), 1, "a 100 ns interval at the expiry: 1 overrun, not 1 per 100 ns");
	is_int(hrtimer_get_expires(&t), 16 * r, "...the expiry moved by hrtimer_resolution");
	is_u64(hrtimer_forward(&t, 18 * r, r / 4), 3, "a quarter-tick interval 2 ticks late: 3 (tick) intervals");
	is_int(ktime_set(2, 5), 2000000005LL, "ktime_set");
	is_int(ktime_to_us(ms_to_ktime(3)), 3000, "ms_to_ktime / ktime_to_us");
	is_int(ktime_to_ms(ktime_sub(ktime_set(1, 0), us_to_ktime(1500))), 998, "ktime_sub / ktime_to_ms");
	ok(ktime_before(1, 2) && ktime_after(3, 2) && ktime_compare(5, 5) == 0, "ktime comparisons");
	is_int(hrtimer_resolution, LX_TICK_NS, "hrtimer_resolution is the tick");
}

int main(void)
{
	tap_plan(44);
	test_forward_math();
	test_zero_drift();
	test_never_early();
	test_callbacks();
	test_overrun();
	return tap_done();
}
