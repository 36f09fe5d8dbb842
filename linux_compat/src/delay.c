/*
 * delay.c — busy delays (sil_dly_nse) and task sleeps (dly_tsk, hrtimer).
 */
#include <linux/delay.h>
#include <linux/hrtimer.h>
#include <linux/kernel.h>
#include <linux_compat/clock.h>
#include <linux_compat/context.h>
#include <linux_compat/sched.h>
#include <kernel.h>
#include <sil.h>

/* Busy-waits nsecs ns in chunks sil_dly_nse takes on 32-bit targets. */
static void busy_ns(uint64_t nsecs)
{
	const ulong_t chunk = 1000000000UL;   /* 1 s per call keeps ulong_t in range */

	while (nsecs > chunk) {
		sil_dly_nse(chunk);
		nsecs -= chunk;
	}
	if (nsecs > 0)
		sil_dly_nse((ulong_t)nsecs);
}

/* Busy-waits usecs us. */
void udelay(unsigned long usecs)
{
	busy_ns((uint64_t)usecs * 1000U);
}

/* Busy-waits nsecs ns. */
void ndelay(unsigned long nsecs)
{
	busy_ns(nsecs);
}

/* Busy-waits msecs ms. */
void mdelay(unsigned long msecs)
{
	busy_ns((uint64_t)msecs * 1000000U);
}

/* Sleeps msecs ms with dly_tsk; returns the ms left if released early. */
static unsigned long sleep_ms(unsigned int msecs, const char *what, const char *file, int line)
{
	uint64_t deadline;
	ER er;

	if (!lx_might_sleep_check(what, file, line)) {
		mdelay(msecs);
		return 0;
	}
	deadline = lx_clock_now_ns() + (uint64_t)msecs * 1000000U;
	er = dly_tsk((RELTIM)msecs);
	if (er == E_RLWAI) {
		uint64_t now = lx_clock_now_ns();

		return now < deadline ? (unsigned long)((deadline - now + 999999U) / 1000000U) : 0;
	}
	return 0;
}

/* Sleeps at least msecs ms. */
void lx_msleep_at(unsigned int msecs, const char *file, int line)
{
	(void)sleep_ms(msecs, "msleep()", file, line);
}

/* Sleeps; the ms left if released early. */
unsigned long lx_msleep_interruptible_at(unsigned int msecs, const char *file, int line)
{
	return sleep_ms(msecs, "msleep_interruptible()", file, line);
}

struct hr_sleeper {
	struct hrtimer timer;
	struct lx_waiter waiter;
};

/* Wakes the task sleeping on the timer. */
static enum hrtimer_restart sleeper_wake(struct hrtimer *timer)
{
	struct hr_sleeper *s = container_of(timer, struct hr_sleeper, timer);
	ID tskid = s->waiter.tskid;

	s->waiter.woken = true;
	lx_wake_task(tskid);
	return HRTIMER_NORESTART;
}

/* Sleeps min us on an hrtimer (max is the slack Linux may use; not needed here). */
void lx_usleep_range_at(unsigned long min, unsigned long max, const char *file, int line)
{
	struct hr_sleeper s;

	(void)max;
	if (!lx_might_sleep_check("usleep_range()", file, line)) {
		udelay(min);
		return;
	}
	lx_waiter_init(&s.waiter);
	hrtimer_setup(&s.timer, sleeper_wake, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimer_start(&s.timer, us_to_ktime(min), HRTIMER_MODE_REL);
	while (lx_waiter_sleep(&s.waiter, U64_MAX) != 0)
		;
	(void)hrtimer_cancel(&s.timer);
}

void (msleep)(unsigned int msecs)
{
	lx_msleep_at(msecs, NULL, 0);
}

unsigned long (msleep_interruptible)(unsigned int msecs)
{
	return lx_msleep_interruptible_at(msecs, NULL, 0);
}

void (usleep_range)(unsigned long min, unsigned long max)
{
	lx_usleep_range_at(min, max, NULL, 0);
}

void (ssleep)(unsigned int seconds)
{
	lx_msleep_at(seconds * 1000U, NULL, 0);
}

/* Sleeps or busy-waits usecs, as suits the length (Linux's fsleep). */
void fsleep(unsigned long usecs)
{
	if (usecs <= 10)
		udelay(usecs);
	else if (usecs <= 20000)
		lx_usleep_range_at(usecs, 2 * usecs, NULL, 0);
	else
		lx_msleep_at((unsigned int)DIV_ROUND_UP(usecs, 1000), NULL, 0);
}
