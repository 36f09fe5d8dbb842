/*
 * test_access_end.c — a register access through a timed window ends as the
 * general path would at its edges: a pending interrupt waits through the
 * accesses a CPU lock or SIL lock covers and is taken at the unlock, a task an
 * ISR woke runs when the ISR returns (not at the ISR's accesses), a task whose
 * access reaches the run's deadline stops in it, and an event due exactly at
 * an access's end runs before the next access, and in an ISR whose own level
 * line and a line below it stay pending its accesses take neither, while a
 * line above it that an access raises is taken at that access's end.  All of it twice: through the
 * timed pair alone, and with the route cache on (a repeated access calls its
 * route directly, and must end the same way).
 */
#include "tap.h"
#include "rtos_test.h"
#include "kernel.h"
#include "sil.h"

#define US         1000ULL
#define ACCESS_NS  100U
#define IRQ_DEV    120U
#define IRQ_BELOW  121U   /* below the level line */
#define IRQ_ABOVE  122U   /* above it */
#define IRQ_LEVEL  123U

/* Registers whose writes act on the lines (the device's side, inside the access). */
#define REG_RAISE_ABOVE 5
#define REG_RAISE_BELOW 6
#define REG_LEVEL       7   /* its value is the level line's */

static uint32_t regs[16];   /* the fake device's registers, in the timed window */
static uint64_t isr_at[4];
static uint_t isr_count;
static uint64_t high_start, locked_end, sil_end, event_at_ns, read_after_event, poll_stop;
static bool routed;                     /* the timed pair caches a route for each access */
static unsigned timed_calls, route_calls;
/* The ISRs of the level-line step in the order they ran ('L' level, 'l' its
 * end, 'A' above, 'B' below), and when. */
static char isr_order[16];
static uint_t isr_order_len;
static uint64_t above_raised_end, above_at, level_end, below_at;

/* A register's route, either direction. */
struct reg_route {
	struct rtos_host_mmio_route base;
	volatile uint32_t *reg;
};
static struct reg_route read_routes[16], write_routes[16];

/* The device's side of a write to register reg. */
static void reg_written(size_t reg, uint32_t data)
{
	if (reg == REG_RAISE_ABOVE)
		rtos_host_irq_raise(IRQ_ABOVE);
	else if (reg == REG_RAISE_BELOW)
		rtos_host_irq_raise(IRQ_BELOW);
	else if (reg == REG_LEVEL)
		rtos_host_irq_set_level(IRQ_LEVEL, data != 0);
}

static uint32_t route_read(const struct rtos_host_mmio_route *rt)
{
	route_calls++;
	return *((const struct reg_route *)rt)->reg;
}

static void route_write(const struct rtos_host_mmio_route *rt, uint32_t data)
{
	route_calls++;
	*((const struct reg_route *)rt)->reg = data;
	reg_written((size_t)(((const struct reg_route *)rt)->reg - regs), data);
}

/* A timed read: the register's value, costing ACCESS_NS; its route cached if routed. */
static uint64_t read_timed(const volatile void *addr, uint_t width, void *ctx)
{
	(void)ctx;
	timed_calls++;
	if (routed)
		rtos_host_mmio_route_cache_fill(false, addr, width,
						&read_routes[(const volatile uint32_t *)addr - regs].base);
	return ((uint64_t)ACCESS_NS << 32) | *(const volatile uint32_t *)addr;
}

/* A timed write, costing ACCESS_NS; its route cached if routed. */
static uint32_t write_timed(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	(void)ctx;
	timed_calls++;
	if (routed)
		rtos_host_mmio_route_cache_fill(true, addr, width,
						&write_routes[(volatile uint32_t *)addr - regs].base);
	*(volatile uint32_t *)addr = data;
	reg_written((size_t)((volatile uint32_t *)addr - regs), data);
	return ACCESS_NS;
}

static bool claims(const volatile void *addr, void *ctx)
{
	(void)ctx;
	return (const volatile uint32_t *)addr >= regs && (const volatile uint32_t *)addr < regs + 16;
}

static uint32_t read_untimed(const volatile void *addr, uint_t width, void *ctx)
{
	return (uint32_t)read_timed(addr, width, ctx);
}

static void write_untimed(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	(void)write_timed(addr, width, data, ctx);
}

static const struct rtos_host_mmio_ops fake_device = {
	.claims = claims, .read = read_untimed, .write = write_untimed, .map = NULL, .ctx = NULL,
};

/* A device event: raises the device line. */
static void raise_line(void *arg)
{
	(void)arg;
	rtos_host_irq_raise(IRQ_DEV);
}

/* A device event: sets register 1, which the task reads right after it. */
static void set_reg(void *arg)
{
	(void)arg;
	event_at_ns = rtos_host_now();
	regs[1] = 7;
}

/* The device's ISR: the first time it wakes the high task and makes five accesses. */
static void isr_dev(intptr_t x)
{
	(void)x;
	if (isr_count < 4)
		isr_at[isr_count] = rtos_host_now();
	if (isr_count++ == 0) {
		iwup_tsk(2);
		for (int i = 0; i < 5; i++)
			(void)sil_rew_mem(&regs[0]);
	}
}

static void isr_log(char c)
{
	if (isr_order_len < sizeof(isr_order) - 1)
		isr_order[isr_order_len++] = c;
}

/* The level line's ISR: accesses with its own line and one below pending,
 * an access that raises one above, more accesses, then the level's release. */
static void isr_level(intptr_t x)
{
	(void)x;
	isr_log('L');
	for (int i = 0; i < 3; i++)
		(void)sil_rew_mem(&regs[0]);
	sil_wrw_mem(&regs[REG_RAISE_BELOW], 1);
	for (int i = 0; i < 3; i++)
		(void)sil_rew_mem(&regs[0]);
	sil_wrw_mem(&regs[REG_RAISE_ABOVE], 1);
	above_raised_end = rtos_host_now();
	for (int i = 0; i < 3; i++)
		(void)sil_rew_mem(&regs[0]);
	sil_wrw_mem(&regs[REG_LEVEL], 0);
	level_end = rtos_host_now();
	isr_log('l');
}

static void isr_above(intptr_t x)
{
	(void)x;
	isr_log('A');
	above_at = rtos_host_now();
}

static void isr_below(intptr_t x)
{
	(void)x;
	isr_log('B');
	below_at = rtos_host_now();
}

static void high_task(intptr_t x)
{
	(void)x;
	slp_tsk();
	high_start = rtos_host_now();
	slp_tsk();
}

static void low_task(intptr_t x)
{
	SIL_PRE_LOC;

	(void)x;
	/* 1: the ISR at 10 us wakes the high task */
	rtos_host_event_at(10 * US, raise_line, NULL);
	dly_tsk(1);

	/* 2: raised at 2.05 ms while the CPU is locked over ten accesses */
	rtos_host_event_at(rtos_host_now() + 50, raise_line, NULL);
	loc_cpu();
	for (int i = 0; i < 10; i++)
		sil_wrw_mem(&regs[2], (uint32_t)i);
	locked_end = rtos_host_now();
	unl_cpu();

	/* 3: the same under the SIL lock */
	rtos_host_event_at(rtos_host_now() + 50, raise_line, NULL);
	SIL_LOC_INT();
	for (int i = 0; i < 10; i++)
		(void)sil_rew_mem(&regs[3]);
	sil_end = rtos_host_now();
	SIL_UNL_INT();

	/* 4: an event due exactly at the end of an access runs before the next one */
	rtos_host_event_at(rtos_host_now() + ACCESS_NS, set_reg, NULL);
	(void)sil_rew_mem(&regs[1]);
	read_after_event = sil_rew_mem(&regs[1]);

	/* 5: a level line's ISR, its accesses made with lines pending it masks */
	sil_wrw_mem(&regs[REG_LEVEL], 1);

	/* 6: polling until the run's deadline */
	for (;;) {
		(void)sil_rew_mem(&regs[4]);
		poll_stop = rtos_host_now();
	}
}

static const struct rtos_task_cfg tasks[] = { RT_TASK(1, low_task, 8, true), RT_TASK(2, high_task, 2, true) };
static const struct rtos_int_cfg ints[] = {
	{ IRQ_DEV, TA_ENAINT, -2 }, { IRQ_BELOW, TA_ENAINT, -1 }, { IRQ_ABOVE, TA_ENAINT, -3 },
	{ IRQ_LEVEL, TA_ENAINT, -2 },
};
static const struct rtos_isr_cfg isrs[] = {
	{ TA_NULL, 0, IRQ_DEV, isr_dev, 1 }, { TA_NULL, 0, IRQ_BELOW, isr_below, 1 },
	{ TA_NULL, 0, IRQ_ABOVE, isr_above, 1 }, { TA_NULL, 0, IRQ_LEVEL, isr_level, 1 },
};
static const struct rtos_cfg cfg = {
	.name = "access_end", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

/* Boots, runs the accesses above for 3 ms and checks how they ended. */
static void run(bool with_routes)
{
	const char *how = with_routes ? "cached routes" : "timed pair";
	uint64_t unlock_at;

	routed = with_routes;
	isr_count = 0;
	isr_order_len = 0;
	memset(isr_order, 0, sizeof(isr_order));
	timed_calls = route_calls = 0;
	regs[1] = 0;
	is_int(rtos_host_boot(&cfg), E_OK, "boot (%s)", how);
	rtos_host_set_mmio_handler(&fake_device);
	rtos_host_set_mmio_window((uintptr_t)regs, sizeof(regs));
	rtos_host_set_mmio_timed(read_timed, write_timed);
	if (with_routes)
		rtos_host_set_mmio_route_cache(ACCESS_NS);
	rtos_host_run_for(3 * US * 1000);
	is_u64(isr_at[0], 10 * US, "the ISR runs at the event (%s)", how);
	is_u64(high_start, 10 * US + 5 * ACCESS_NS,
	       "the task it woke runs when it returns, after its five accesses (%s)", how);
	unlock_at = 1000 * US + 10 * ACCESS_NS;
	ok(locked_end == unlock_at && isr_at[1] == unlock_at,
	   "raised under loc_cpu, the interrupt waits through the accesses and is taken at unl_cpu (%s)", how);
	ok(sil_end == unlock_at + 10 * ACCESS_NS && isr_at[2] == sil_end,
	   "raised under the SIL lock, the same at SIL_UNL_INT (%s)", how);
	ok(event_at_ns == sil_end + ACCESS_NS && read_after_event == 7,
	   "an event due at an access's end runs before the next access (%s)", how);
	is_str(isr_order, "LAlB",
	       "in a level line's ISR, a line above an access raised nests, its own and one below wait (%s)", how);
	is_u64(above_at, above_raised_end, "the line above is taken at the end of the access that raised it (%s)",
	       how);
	is_u64(below_at, level_end, "the line below is taken when the ISR returns, the level released (%s)", how);
	is_u64(poll_stop, 3 * US * 1000 - ACCESS_NS,
	       "a task polling registers stops in the access that reaches the run's deadline (%s)", how);
	is_u64(rtos_host_now(), 3 * US * 1000, "the run ends at its deadline (%s)", how);
	if (with_routes)
		ok(timed_calls == 8 && route_calls > 1000,
		   "each register's first access in each direction took the timed pair, the others its route "
		   "(%u timed, %u routed)", timed_calls, route_calls);
	else
		ok(route_calls == 0 && timed_calls > 1000, "without the cache every access took the timed pair");
	rtos_host_set_mmio_handler(NULL);
	rtos_host_shutdown();
}

int main(void)
{
	tap_plan(24);
	for (int i = 0; i < 16; i++) {
		read_routes[i] = (struct reg_route){ { route_read, NULL }, &regs[i] };
		write_routes[i] = (struct reg_route){ { NULL, route_write }, &regs[i] };
	}
	run(false);
	run(true);
	return tap_done();
}
