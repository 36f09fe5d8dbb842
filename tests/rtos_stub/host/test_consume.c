/*
 * test_consume.c — CPU time in virtual time: rtos_host_consume in a task
 * that is preempted (it finishes its time later), ISRs nesting during
 * consumption, a run deadline in the middle of a task's consumption, consume
 * from the harness, sil_dly_nse; device events (cancel, order) and MMIO
 * routing through the installed handler.
 */
#include "tap.h"
#include "kernel.h"
#include "sil.h"
#include "rtos_test.h"

#define US 1000ULL
#define IRQ_DEV 120U

static uint64_t low_done, high_start, high_done, dly_end;
static uint32_t dev_regs[16];      /* registers of a fake device (MMIO tests) */
static int isr_runs;

static void isr_dev(intptr_t x)
{
	isr_runs++;
	rt_log("isr@%llu", (unsigned long long)(rtos_host_now() / US));
	rtos_host_consume(10 * US);
	iwup_tsk(2);
}

static void raise_event(void *arg)
{
	rtos_host_irq_raise(IRQ_DEV);
}

static void low_task(intptr_t x)
{
	rtos_host_consume(1000 * US);
	low_done = rtos_host_now();
	sil_dly_nse(2500);
	dly_end = rtos_host_now();
}

static void high_task(intptr_t x)
{
	slp_tsk();
	high_start = rtos_host_now();
	rtos_host_consume(200 * US);
	high_done = rtos_host_now();
	slp_tsk();
	rt_log("high");
}

static void poll_task(intptr_t x)
{
	(void)sil_rew_mem(&dev_regs[15]);
	rt_log("poll-done");
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, low_task, 8, 1024, TDOM_KERNEL, "low" },
	{ 2, TA_ACT, 0, high_task, 2, 1024, TDOM_KERNEL, "high" },
	{ 3, TA_NULL, 0, poll_task, 6, 1024, TDOM_KERNEL, "poll" },
};
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg cfg = {
	.name = "consume", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

/* ---- MMIO ---- */
static uint32_t plain[4];
static uint32_t last_write_val;
static uint_t last_width, reads;
static char map_window[32];

static bool dev_claims(const volatile void *addr, void *ctx)
{
	return (const volatile char *)addr >= (const volatile char *)dev_regs &&
	       (const volatile char *)addr < (const volatile char *)(dev_regs + 16);
}

static void wake_event(void *arg)
{
	rt_log("wake-event");
	iwup_tsk(2);
}

static uint32_t dev_read(const volatile void *addr, uint_t width, void *ctx)
{
	reads++;
	last_width = width;
	if (addr == &dev_regs[15]) {
		/* a slow register: the bus stalls 2 us, meanwhile an event readies a task */
		rtos_host_event_at(rtos_host_now() + 1000, wake_event, NULL);
		rt_log("read(");
		rtos_host_consume(2000);
		rt_log(")read");
	}
	return 0xabcd0000U | (uint32_t)((const volatile char *)addr - (const volatile char *)dev_regs);
}

static void dev_write(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	last_width = width;
	last_write_val = data;
	rt_log("write(");
	rtos_host_irq_raise(IRQ_DEV);   /* the interrupt is taken after the access completes */
	rt_log(")write");
}

static void *dev_map(uintptr_t phys, SIZE size, void *ctx)
{
	return phys == 0x01c42000U && size <= sizeof(map_window) ? map_window : NULL;
}

static const struct rtos_host_mmio_ops ops = { dev_claims, dev_read, dev_write, dev_map, NULL };

static void act_poll(void *arg)
{
	iact_tsk(3);
}

static int ev_order[4];
static int nev;
static void order_event(void *arg)
{
	ev_order[nev++] = (int)(intptr_t)arg;
}

int main(void)
{
	rtos_host_event_t cancelled;
	char expect_log[64];
	uint64_t t_access;

	tap_plan(17);
	rt_log_reset();
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_event_at(300 * US, raise_event, NULL);
	rtos_host_run_for(500 * US);
	/* at 500 us the low task is paused mid-consume, 100 us + 200 us done */
	is_u64(rtos_host_now(), 500 * US, "run_for stops at its deadline while a task consumes");
	ok(low_done == 0 && high_done == 0 && high_start == 310 * US,
	   "the ISR at 300 us (10 us) woke the high task, which preempted the consuming low task");
	rtos_host_run_for(2 * 1000 * US);
	is_u64(high_done, 510 * US, "the high task's 200 us consume spans the run deadline");
	is_u64(low_done, 1210 * US, "the low task finishes its 1000 us after the 210 us it was preempted");
	is_u64(dly_end, 1210 * US + 2500, "sil_dly_nse spends virtual time");

	/* consume from the harness: events and ISRs fire, tasks do not run */
	rtos_host_boot(&cfg);
	low_done = high_start = high_done = dly_end = 0;
	isr_runs = 0;
	rtos_host_event_at(50 * US, raise_event, NULL);
	rtos_host_consume(100 * US);
	/* the ISR's 10 us do not count towards the harness's 100 us */
	ok(rtos_host_now() == 110 * US && isr_runs == 1 && high_start == 0 && low_done == 0,
	   "consume from the harness: time passes, the ISR nests (its time on top), tasks wait");
	rtos_host_run_for(10 * US);
	ok(high_start == 110 * US, "the woken task runs once the harness runs the system");

	/* device events: order at equal times, cancel */
	nev = 0;
	rtos_host_event_at(rtos_host_now() + 5, order_event, (void *)1);
	cancelled = rtos_host_event_at(rtos_host_now() + 5, order_event, (void *)2);
	rtos_host_event_at(rtos_host_now() + 5, order_event, (void *)3);
	rtos_host_event_at(rtos_host_now() + 4, order_event, (void *)0);
	rtos_host_event_cancel(cancelled);
	rtos_host_event_cancel(cancelled);
	rtos_host_run_for(10);
	ok(nev == 3 && ev_order[0] == 0 && ev_order[1] == 1 && ev_order[2] == 3,
	   "events run by time, then in scheduling order; a cancelled one never runs");
	rtos_host_event_at(rtos_host_now() + 50 * 1000 * US, order_event, (void *)9);
	ok(!rtos_host_run_until_idle(1000 * US), "run_until_idle: not idle while a device event is pending");
	ok(rtos_host_run_until_idle(100 * 1000 * US) && nev == 4, "run_until_idle: idle after the last event");

	/* MMIO routing */
	rt_log_reset();
	snprintf(expect_log, sizeof(expect_log), "write( )write isr@%llu after",
		 (unsigned long long)(rtos_host_now() / US));
	rtos_host_set_mmio_handler(&ops);
	sil_wrw_mem(&dev_regs[2], 0x12345678U);
	rt_log("after");
	ok(last_write_val == 0x12345678U && last_width == 4 && dev_regs[2] == 0,
	   "a claimed write goes to the handler with its width, not to memory");
	is_str(rt_log_text(), expect_log, "an interrupt raised by a register access is taken after it");
	ok(sil_reh_mem((const uint16_t *)&dev_regs[1]) == (uint16_t)(0xabcd0000U | 4) && last_width == 2 && reads == 1,
	   "a claimed read returns the handler's value at the access width");
	sil_wrb_mem((uint8_t *)&plain[1] + 1, 0x5a);
	ok(plain[1] == 0x5a00U && sil_rew_mem(&plain[1]) == 0x5a00U && reads == 1,
	   "unclaimed addresses are plain memory of the exact width");
	ok(rtos_host_map_io(0x01c42000U, 16) == map_window && rtos_host_map_io(0x01c43000U, 16) == NULL,
	   "rtos_host_map_io asks the handler's map()");
	rt_log_reset();
	reads = 0;
		rtos_host_shutdown();
	rtos_host_boot(&cfg);
	rtos_host_run_for(300 * US);          /* high ran and sleeps again, low consumes */
	rt_log_reset();
	t_access = rtos_host_now();
	high_start = 0;
	rtos_host_event_at(t_access, act_poll, NULL);
	rtos_host_run_for(10 * US);
	ok(strcmp(rt_log_text(), "read( wake-event )read") == 0 && high_start == t_access + 2000,
	   "a task readied during a register access runs when the access completes, not in the middle");
	tap_diag("log \"%s\", high started %llu ns after the access began", rt_log_text(),
		 (unsigned long long)(high_start - t_access));
	rtos_host_set_mmio_handler(NULL);
	rtos_host_shutdown();
	return tap_done();
}
