/*
 * bench_timers.c — the timer queues' scaling row of `make bench`: the cost
 * of the 200 us tick (lx_tick_isr) that runs one due hrtimer while N
 * hrtimers are armed, and one due timer_list timer per jiffy while N
 * timer_list timers are armed, for N = 1, 16, 256 (one run each).  One
 * hrtimer fires every tick and one timer_list timer every jiffy, each
 * re-arming itself; the other N - 1 of each wait far in the future at
 * distinct expiries, so every re-arm is queued among them.  No driver is
 * loaded: linux_compat alone on the host kernel.  Like bench_arm, the
 * program measures nothing itself: insn_count counts lx_tick_isr's calls
 * between bench_window_open and bench_window_close in QEMU's log.
 *
 *   bench_timers N tick_ms [both|hrtimer|timer_list|none]
 *
 * The third argument keeps only one of the two periodic timers (or neither):
 * the difference between such a run's ticks and the idle run's is what one
 * due timer of that kind costs (make bench's per-timer rows).
 *
 * Prints "timers <N> <hrtimer runs> <timer_list runs>", the runs inside the
 * counted window.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <linux/hrtimer.h>
#include <linux/timer.h>
#include <linux/jiffies.h>
#include <linux/ktime.h>
#include "rtos_host.h"
#include <linux_compat/config.h>

#define MAX_TIMERS  256U
#define TICK_NS     200000LL
#define FAR_NS      1000000000000LL      /* 1000 s */
#define FAR_JIFFIES 1000000UL

static struct hrtimer hrtimers[MAX_TIMERS];
static struct timer_list timers[MAX_TIMERS];
static unsigned n_timers = 1, tick_ms = 20;
static bool periodic_hrtimer = true, periodic_timer_list = true;
static unsigned long hr_runs, tl_runs;
static volatile bool finished;
static unsigned long window_hr_runs, window_tl_runs;

noinline void bench_window_open(void);
noinline void bench_window_open(void)
{
	__asm__ volatile("" ::: "memory");
}

noinline void bench_window_close(void);
noinline void bench_window_close(void)
{
	__asm__ volatile("" ::: "memory");
}

/* The due hrtimer: every tick, forwarded on its grid. */
static enum hrtimer_restart every_tick(struct hrtimer *t)
{
	hr_runs++;
	hrtimer_forward_now(t, ns_to_ktime(TICK_NS));
	return HRTIMER_RESTART;
}

/* Never due during the run. */
static enum hrtimer_restart far_hrtimer(struct hrtimer *t)
{
	(void)t;
	return HRTIMER_NORESTART;
}

/* The due timer_list timer: every jiffy. */
static void every_jiffy(struct timer_list *t)
{
	tl_runs++;
	mod_timer(t, jiffies + 1);
}

static void far_timer(struct timer_list *t)
{
	(void)t;
}

static void bench_task(intptr_t exinf)
{
	ktime_t now = ktime_get();

	(void)exinf;
	for (unsigned i = 1; i < n_timers; i++) {
		hrtimer_init(&hrtimers[i], CLOCK_MONOTONIC, HRTIMER_MODE_ABS);
		hrtimers[i].function = far_hrtimer;
		hrtimer_start(&hrtimers[i], ktime_add_ns(now, FAR_NS + (s64)i * 1000000), HRTIMER_MODE_ABS);
		timer_setup(&timers[i], far_timer, 0);
		mod_timer(&timers[i], jiffies + FAR_JIFFIES + i);
	}
	hrtimer_init(&hrtimers[0], CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimers[0].function = every_tick;
	if (periodic_hrtimer)
		hrtimer_start(&hrtimers[0], ns_to_ktime(TICK_NS), HRTIMER_MODE_REL);
	timer_setup(&timers[0], every_jiffy, 0);
	if (periodic_timer_list)
		mod_timer(&timers[0], jiffies + 1);
	dly_tsk(2);                             /* settle: the periodic timers running */

	hr_runs = tl_runs = 0;
	bench_window_open();
	dly_tsk(tick_ms);
	bench_window_close();
	window_hr_runs = hr_runs;
	window_tl_runs = tl_runs;

	hrtimer_cancel(&hrtimers[0]);
	del_timer_sync(&timers[0]);
	for (unsigned i = 1; i < n_timers; i++) {
		hrtimer_cancel(&hrtimers[i]);
		del_timer_sync(&timers[i]);
	}
	finished = true;
}

int main(int argc, char **argv)
{
	static const struct rtos_task_cfg task = {
		1, TA_ACT, 0, bench_task, 8, 64 * 1024, TDOM_KERNEL, "bench_timers",
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, NULL };
	static const struct rtos_cfg cfg = { .name = "bench_timers", .tasks = &task, .ntasks = 1, .includes = includes };

	if (argc > 1)
		n_timers = (unsigned)strtoul(argv[1], NULL, 10);
	if (argc > 2)
		tick_ms = (unsigned)strtoul(argv[2], NULL, 10);
	if (argc > 3) {
		periodic_hrtimer = !strcmp(argv[3], "both") || !strcmp(argv[3], "hrtimer");
		periodic_timer_list = !strcmp(argv[3], "both") || !strcmp(argv[3], "timer_list");
	}
	if (n_timers == 0 || n_timers > MAX_TIMERS || tick_ms == 0 ||
	    (argc > 3 && !periodic_hrtimer && !periodic_timer_list && strcmp(argv[3], "none"))) {
		fprintf(stderr, "usage: bench_timers N(1..%u) tick_ms [both|hrtimer|timer_list|none]\n",
			MAX_TIMERS);
		return 2;
	}
	if (rtos_host_boot(&cfg) != E_OK) {
		fprintf(stderr, "bench_timers: boot failed: %s\n", rtos_host_boot_error());
		return 1;
	}
	rtos_host_run_for((uint64_t)(tick_ms + 20U) * 1000000ULL);
	rtos_host_shutdown();
	if (!finished) {
		fprintf(stderr, "bench_timers: the task did not finish\n");
		return 1;
	}
	printf("timers %u %lu %lu\n", n_timers, window_hr_runs, window_tl_runs);
	return 0;
}
