/*
 * test_timer_list.c — jiffies, timer_list (timer_setup, mod_timer, del_timer,
 * add_timer, timer_pending, from_timer), conversions, busy delays and sleeps.
 */
#include "tap.h"
#include "lx_core_test.h"
#include <linux/timer.h>
#include <linux/jiffies.h>
#include <linux/delay.h>
#include <linux/ktime.h>
#include <linux/spinlock.h>
#include <kernel.h>
#include <linux_compat/clock.h>

struct my_dev {
	int value;
	struct timer_list timer;
};

static struct my_dev dev;
static struct timer_list t2;
static unsigned long fired_jiffies, armed_expiry, t2_fired_jiffies;
static bool fired_in_interrupt, from_timer_ok;
static int fired_count, t2_count, mod_ret[2], del_ret[2];
static s64 udelay_ns, msleep_ns, usleep_ns, mdelay_ns;
static unsigned long j_start;
static bool bh_held_off;
static DEFINE_SPINLOCK(bh_lock);

static void dev_timer_fn(struct timer_list *t)
{
	struct my_dev *d = from_timer(d, t, timer);

	from_timer_ok = d == &dev && d->value == 42;
	fired_jiffies = jiffies;
	fired_in_interrupt = in_interrupt();
	fired_count++;
}

static void t2_fn(struct timer_list *t)
{
	(void)t;
	t2_fired_jiffies = jiffies;
	t2_count++;
}

static void main_task(intptr_t exinf)
{
	s64 t0;

	(void)exinf;
	j_start = jiffies;
	dev.value = 42;
	timer_setup(&dev.timer, dev_timer_fn, 0);
	armed_expiry = jiffies + msecs_to_jiffies(5);
	mod_ret[0] = mod_timer(&dev.timer, armed_expiry);
	mod_ret[1] = mod_timer(&dev.timer, armed_expiry);
	msleep(10);

	timer_setup(&t2, t2_fn, 0);
	t2.expires = jiffies + 3;
	add_timer(&t2);
	del_ret[0] = del_timer(&t2);
	del_ret[1] = del_timer(&t2);
	msleep(5);

	/* spin_lock_bh holds timer_list callbacks off. */
	mod_timer(&t2, jiffies + 1);
	spin_lock_bh(&bh_lock);
	mdelay(3);
	bh_held_off = t2_count == 0;
	spin_unlock_bh(&bh_lock);
	msleep(1);

	t0 = ktime_get();
	udelay(123);
	udelay_ns = ktime_get() - t0;
	t0 = ktime_get();
	mdelay(2);
	mdelay_ns = ktime_get() - t0;
	t0 = ktime_get();
	msleep(3);
	msleep_ns = ktime_get() - t0;
	udelay(50);
	t0 = ktime_get();
	usleep_range(300, 400);
	usleep_ns = ktime_get() - t0;
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 5, true) };

	tap_plan(20);
	is_int(HZ, 1000, "HZ is 1000 (a jiffy is a millisecond)");
	is_int(msecs_to_jiffies(25), 25, "msecs_to_jiffies");
	is_int(jiffies_to_msecs(7), 7, "jiffies_to_msecs");
	is_int(usecs_to_jiffies(1500), 2, "usecs_to_jiffies rounds up");
	ok(time_after(INITIAL_JIFFIES + 10UL, INITIAL_JIFFIES) && time_before((unsigned long)-5, 3UL),
	   "time_after/time_before across the wrap");
	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return tap_done();
	rtos_host_run_for(40 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	is_int(j_start, INITIAL_JIFFIES, "jiffies start at INITIAL_JIFFIES (wraps 5 minutes after boot)");
	is_int(mod_ret[0], 0, "mod_timer on an idle timer returns 0");
	is_int(mod_ret[1], 1, "mod_timer on a pending timer returns 1");
	is_int(fired_count, 1, "the timer fired once");
	ok(fired_jiffies == armed_expiry, "at its expiry jiffy, not before (%lu vs %lu)",
	   fired_jiffies - INITIAL_JIFFIES, armed_expiry - INITIAL_JIFFIES);
	ok(fired_in_interrupt && from_timer_ok, "in interrupt context; from_timer finds the device");
	ok(del_ret[0] == 1 && del_ret[1] == 0, "del_timer: 1 when pending, then 0");
	ok(bh_held_off, "timer_list callbacks wait while bottom halves are disabled");
	is_int(t2_count, 1, "...and run after local_bh_enable");
	is_int(udelay_ns, 123000, "udelay(123) spends exactly 123 us of virtual CPU time");
	is_int(mdelay_ns, 2000000, "mdelay(2) spends 2 ms");
	ok(msleep_ns >= 3 * NSEC_PER_MSEC && msleep_ns <= 3 * NSEC_PER_MSEC + (s64)LX_TICK_NS,
	   "msleep(3) sleeps 3 ms, rounded up to the tick (%lld ns)", (long long)msleep_ns);
	ok(usleep_ns >= 300000 && usleep_ns < 300000 + (s64)LX_TICK_NS,
	   "usleep_range(300, 400) sleeps at least 300 us, less than a tick more (%lld ns)",
	   (long long)usleep_ns);
	ok(t2_fired_jiffies != 0, "a re-armed timer fired");
	ok(!timer_pending(&dev.timer), "timer_pending is false after firing");
	return tap_done();
}
