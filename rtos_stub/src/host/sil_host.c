/*
 * sil_host.c — the host System Interface Layer: the all-interrupt lock,
 * register accesses routed to the installed MMIO handler, and busy delays
 * that spend virtual CPU time.
 */
#include "sil.h"
#include "kernel_impl.h"

static const struct rtos_host_mmio_ops *mmio_ops;
static uintptr_t mmio_window_start;
static uintptr_t mmio_window_len;     /* 0: ask claims */
static rtos_host_mmio_read_timed_fn mmio_read_timed;      /* NULL: the handler's read */
static rtos_host_mmio_write_timed_fn mmio_write_timed;
/* The common case in one place: the window, when the handler has a timed pair
 * (len 0 otherwise), so that an access tests one range and makes one call. */
static struct {
	uintptr_t start;
	uintptr_t len;
	rtos_host_mmio_read_timed_fn read;
	rtos_host_mmio_write_timed_fn write;
	void *ctx;
} timed_win;

/*
 * The route cache (rtos_host_set_mmio_route_cache): the handler's routes for
 * recent accesses, by address, width and direction.  Drivers access a handful
 * of registers over and over (a poll loop, an ISR's status and data), and a
 * hit goes from the accessor straight to the route.  A slot matches an access
 * only if both its address and its width are the access's, and only checked
 * accesses in the window are filled in (rtos_host_mmio_route_cache_fill), so a
 * hit needs no width, alignment or window test.  An empty slot holds an
 * address whose slot is another one (ROUTE_EMPTY_ADDR), so no access matches
 * it.
 */
#define ROUTE_CACHE_BITS 7U
#define ROUTE_CACHE_SLOTS (1U << ROUTE_CACHE_BITS)
/* Addresses, routes and widths in arrays, so that one base and the slot's
 * index address all three. */
struct route_cache {
	uintptr_t addr[ROUTE_CACHE_SLOTS];
	const struct rtos_host_mmio_route *route[ROUTE_CACHE_SLOTS];
	uint_t width[ROUTE_CACHE_SLOTS];
};
/* An empty slot's address: address 0 is in slot 0 (0 times anything is 0),
 * address 1 in slot 79 (0x9E3779B1 >> 25), so neither is looked up in the
 * slot that holds it. */
#define ROUTE_EMPTY_ADDR(slot) ((slot) == 0U ? 1U : 0U)
static struct route_cache read_routes = { .addr = { [0] = ROUTE_EMPTY_ADDR(0U) } };
static struct route_cache write_routes = { .addr = { [0] = ROUTE_EMPTY_ADDR(0U) } };
static bool route_cache_on;
static uint32_t route_ns;       /* what an access through a cached route costs */

/* The slot of address addr: a multiplicative hash of its low 32 bits, whose
 * top bits depend on every address bit (registers at the same offset in
 * different modules should not collide), in one multiply and shift. */
static inline unsigned route_slot(const volatile void *addr)
{
	return ((uint32_t)(uintptr_t)addr * 0x9E3779B1U) >> (32U - ROUTE_CACHE_BITS);
}

/* Empties both route caches. */
static void route_cache_clear(void)
{
	for (unsigned i = 0; i < ROUTE_CACHE_SLOTS; i++) {
		read_routes.addr[i] = write_routes.addr[i] = ROUTE_EMPTY_ADDR(i);
		read_routes.width[i] = write_routes.width[i] = 0;
		read_routes.route[i] = write_routes.route[i] = NULL;
	}
}

/* True if slot of c holds a width-byte access at mem (then its route is set). */
static inline bool route_hit(const struct route_cache *c, unsigned slot, const volatile void *mem, uint_t width)
{
	return c->addr[slot] == (uintptr_t)mem && c->width[slot] == width;
}

/* True if the installed handler serves mem. */
static inline bool mmio_claimed(const struct rtos_host_mmio_ops *ops, const volatile void *mem)
{
	if (ops == NULL)
		return false;
	if (mmio_window_len != 0)
		return (uintptr_t)mem - mmio_window_start < mmio_window_len;
	return ops->claims(mem, ops->ctx);
}

/* Masks all interrupts (nesting-safe); returns the previous lock depth. */
uint_t sil_host_loc_int(void)
{
	return cpu.sil_lock++;
}

/* Restores the lock depth sil_host_loc_int returned; at depth 0 pending interrupts
 * run, then a dispatch held off by the lock happens (dispatch_if_needed does
 * nothing unless another task is to run or the kernel has exited: no call). */
void sil_host_unl_int(uint_t saved)
{
	cpu.sil_lock = saved;
	if (saved == 0) {
		irq_dispatch_pending();
		if (schedtsk != runtsk || kernel_exited)
			dispatch_if_needed();
	}
}

/* After a device access: interrupts it raised are taken, then a switch to a task it readied;
 * a task at the run deadline hands the CPU to the harness (each access costs virtual time, so
 * a task that only polls registers must still stop where rtos_host_run_* ends). */
static inline void access_done(void)
{
	cpu.irq_defer--;
	irq_dispatch_pending();
	if (schedtsk != runtsk)
		dispatch_if_needed();
	if (cpu.kind == EXEC_TASK && cpu.isr_depth == 0 && cpu.irq_defer == 0 &&
	    run_active && now_ns >= run_deadline)
		pause_to_harness();
}

/* Spends the time a timed handler returned for an access (inside it, so
 * never at task level): the common case, no event due before its end, is one
 * addition, as in rtos_host_consume. */
static inline void access_spend(uint32_t ns)
{
	/* ns == 0 takes the first branch unless an event is due now: adding
	 * nothing is harmless, and only a call for nothing must be avoided. */
	if (ns < event_next_time() - now_ns && kernel_booted)
		now_ns += ns;
	else if (ns != 0)
		rtos_host_consume(ns);
}

/* The end of a timed-window access that cost ns and read v, as access_spend then
 * access_done, out of line: when time reaches an event or the run's deadline, or
 * an interrupt is pending, or another task is to run. */
static __attribute__((noinline)) uint32_t access_end_slow(uint32_t ns, uint32_t v)
{
	access_spend(ns);
	access_done();
	return v;
}

/* access_end_slow for an access through a cached route, which costs route_ns
 * (loaded here, so that the fast path need not keep it). */
static __attribute__((noinline)) uint32_t route_end_slow(uint32_t v)
{
	access_spend(route_ns);
	access_done();
	return v;
}

/* access_spend(ns) then access_done() for a timed-window access that read v;
 * returns v.  The common case, in which neither does more than advance the
 * clock and undo the deferral, takes no call and needs no frame.  routed: the
 * access went through a cached route, and ns is route_ns. */
static inline __attribute__((always_inline)) uint32_t access_end(uint32_t ns, uint32_t v, bool routed)
{
	uint64_t end = now_ns + ns;

	/* Cases in which access_spend adds ns (no event due before the end: then
	 * ns < event_next_time() - now_ns, its test; quiet_until is 0 before boot)
	 * and access_done then finds no interrupt to take (none pending, or
	 * irq_dispatch_pending held off by a lock or an enclosing access or event,
	 * or in an ISR by the pending lines' priorities: an ISR's accesses while
	 * its own level line or one below it is pending), no task to switch to
	 * (none, or not from a task) and no deadline reached (quiet_until is also
	 * the run's).  irq_best_pri's rescan mark is below every mask: the slow
	 * path looks. */
	if (end < quiet_until &&
	    (irq_pending_lines == 0 || cpu.locked || cpu.sil_lock != 0 || cpu.irq_defer != 1 ||
	     (irq_best_pri >= cpu.ipm && cpu.isr_depth != 0)) &&
	    (schedtsk == runtsk || cpu.kind != EXEC_TASK || cpu.isr_depth != 0)) {
		now_ns = end;
		cpu.irq_defer--;
		return v;
	}
	return routed ? route_end_slow(v) : access_end_slow(ns, v);
}

/* True for a width of 1, 2 or 4 that mem is aligned to (width_bug reports the others). */
static inline bool width_fast_ok(const volatile void *mem, uint_t width)
{
	uint_t below = width - 1U;      /* 0, 1 or 3 for an allowed width, also its alignment mask */

	/* below <= 3 leaves 1 to 4, and no bit shared with width leaves powers of two */
	return below <= 3U && (((uintptr_t)mem | width) & below) == 0;
}

/* Reports a register access whose width or alignment width_fast_ok refused. */
static __attribute__((noinline, cold)) void width_bug(const char *fn, const volatile void *mem, uint_t width)
{
	if (width != 1U && width != 2U && width != 4U)
		rtos_host_bug("sil", "%s: access width %u (only 1, 2, 4)", fn, width);
	else
		rtos_host_bug("sil", "%s: misaligned %u-byte register access (ARM926 would rotate the data)",
			      fn, width);
}

/* sil_host_read outside the timed window: the handler if it claims mem, else memory. */
static __attribute__((noinline)) uint32_t read_other(const volatile void *mem, uint_t width)
{
	const struct rtos_host_mmio_ops *ops = mmio_ops;
	uint32_t v;

	if (mmio_claimed(ops, mem)) {
		cpu.irq_defer++;
		if (mmio_read_timed != NULL) {
			uint64_t cost_value = mmio_read_timed(mem, width, ops->ctx);

			v = (uint32_t)cost_value;
			access_spend((uint32_t)(cost_value >> 32));
		} else
			v = ops->read(mem, width, ops->ctx);
		access_done();
		return v;
	}
	switch (width) {
	case 1:
		return *(const volatile uint8_t *)mem;
	case 2:
		return *(const volatile uint16_t *)mem;
	default:
		return *(const volatile uint32_t *)mem;
	}
}

/* sil_host_read of an access the route cache does not know: checked, then the
 * timed window's read or read_other. */
static __attribute__((noinline)) uint32_t read_uncached(const volatile void *mem, uint_t width)
{
	uint64_t cost_value;

	if (!width_fast_ok(mem, width)) {
		width_bug("sil_host_read", mem, width);
		return 0;
	}
	if ((uintptr_t)mem - timed_win.start >= timed_win.len)
		return read_other(mem, width);
	cpu.irq_defer++;
	cost_value = timed_win.read(mem, width, timed_win.ctx);
	return access_end((uint32_t)(cost_value >> 32), (uint32_t)cost_value, false);
}

/* Reads a register of exact width: from the MMIO handler if it claims the address, else memory. */
uint32_t sil_host_read(const volatile void *mem, uint_t width)
{
	unsigned slot = route_slot(mem);
	const struct rtos_host_mmio_route *rt;

	if (!route_hit(&read_routes, slot, mem, width))
		return read_uncached(mem, width);
	rt = read_routes.route[slot];
	cpu.irq_defer++;
	return access_end(route_ns, rt->read(rt), true);
}

/* sil_host_write outside the timed window: to the handler if it claims mem, else memory. */
static __attribute__((noinline)) void write_other(volatile void *mem, uint_t width, uint32_t data)
{
	const struct rtos_host_mmio_ops *ops = mmio_ops;

	if (mmio_claimed(ops, mem)) {
		cpu.irq_defer++;
		if (mmio_write_timed != NULL)
			access_spend(mmio_write_timed(mem, width, data, ops->ctx));
		else
			ops->write(mem, width, data, ops->ctx);
		access_done();
		return;
	}
	switch (width) {
	case 1:
		*(volatile uint8_t *)mem = (uint8_t)data;
		break;
	case 2:
		*(volatile uint16_t *)mem = (uint16_t)data;
		break;
	default:
		*(volatile uint32_t *)mem = data;
		break;
	}
}

/* sil_host_write of an access the route cache does not know: checked, then the
 * timed window's write or write_other. */
static __attribute__((noinline)) void write_uncached(volatile void *mem, uint_t width, uint32_t data)
{
	if (!width_fast_ok(mem, width)) {
		width_bug("sil_host_write", mem, width);
		return;
	}
	if ((uintptr_t)mem - timed_win.start >= timed_win.len) {
		write_other(mem, width, data);
		return;
	}
	cpu.irq_defer++;
	access_end(timed_win.write(mem, width, data, timed_win.ctx), 0, false);
}

/* Writes a register of exact width: to the MMIO handler if it claims the address, else memory. */
void sil_host_write(volatile void *mem, uint_t width, uint32_t data)
{
	unsigned slot = route_slot(mem);
	const struct rtos_host_mmio_route *rt;

	if (!route_hit(&write_routes, slot, mem, width)) {
		write_uncached(mem, width, data);
		return;
	}
	rt = write_routes.route[slot];
	cpu.irq_defer++;
	rt->write(rt, data);
	access_end(route_ns, 0, true);
}

/* Recomputes timed_win from the handler, its window and its timed pair; the
 * route cache is off until the handler turns it on again. */
static void timed_win_update(void)
{
	bool on = mmio_ops != NULL && mmio_window_len != 0 && mmio_read_timed != NULL;

	timed_win.start = on ? mmio_window_start : 0;
	timed_win.len = on ? mmio_window_len : 0;
	timed_win.read = mmio_read_timed;
	timed_win.write = mmio_write_timed;
	timed_win.ctx = on ? mmio_ops->ctx : NULL;
	route_cache_on = false;
	route_cache_clear();
}

/* Installs the MMIO handler (NULL: plain memory, no device windows). */
void rtos_host_set_mmio_handler(const struct rtos_host_mmio_ops *ops)
{
	if (ops != NULL && (ops->claims == NULL || ops->read == NULL || ops->write == NULL)) {
		rtos_host_bug("sil", "rtos_host_set_mmio_handler: claims, read and write are required");
		return;
	}
	mmio_ops = ops;
	mmio_window_start = 0;
	mmio_window_len = 0;
	mmio_read_timed = NULL;
	mmio_write_timed = NULL;
	timed_win_update();
}

/* Routes [start, start + len) to the installed handler without asking claims. */
void rtos_host_set_mmio_window(uintptr_t start, uintptr_t len)
{
	if (mmio_ops == NULL) {
		rtos_host_bug("sil", "rtos_host_set_mmio_window without a handler");
		return;
	}
	if (len != 0 && start + len - 1U < start) {
		rtos_host_bug("sil", "rtos_host_set_mmio_window: range wraps around");
		return;
	}
	mmio_window_start = start;
	mmio_window_len = len;
	timed_win_update();
}

/* Routes the handler's accesses to read and write, which return their cost. */
void rtos_host_set_mmio_timed(rtos_host_mmio_read_timed_fn read, rtos_host_mmio_write_timed_fn write)
{
	if (mmio_ops == NULL) {
		rtos_host_bug("sil", "rtos_host_set_mmio_timed without a handler");
		return;
	}
	if ((read == NULL) != (write == NULL)) {
		rtos_host_bug("sil", "rtos_host_set_mmio_timed: read and write, or neither");
		return;
	}
	mmio_read_timed = read;
	mmio_write_timed = write;
	timed_win_update();
}

/* Turns the route cache on, emptied; its accesses cost access_ns. */
void rtos_host_set_mmio_route_cache(uint32_t access_ns)
{
	if (timed_win.len == 0) {
		rtos_host_bug("sil", "rtos_host_set_mmio_route_cache without a window and timed pair");
		return;
	}
	route_ns = access_ns;
	route_cache_on = true;
	route_cache_clear();
}

/* Caches rt for width-byte accesses at addr in the direction write. */
void rtos_host_mmio_route_cache_fill(bool write, const volatile void *addr, uint_t width,
				     const struct rtos_host_mmio_route *rt)
{
	struct route_cache *c = write ? &write_routes : &read_routes;
	unsigned slot = route_slot(addr);

	if (!route_cache_on)
		return;
	if (rt == NULL || (write ? rt->write == NULL : rt->read == NULL) ||
	    !width_fast_ok(addr, width) || (uintptr_t)addr - timed_win.start >= timed_win.len) {
		rtos_host_bug("sil", "rtos_host_mmio_route_cache_fill: %s of %u bytes at %p is not an access to cache",
			      write ? "write" : "read", width, (const void *)addr);
		return;
	}
	c->addr[slot] = (uintptr_t)addr;
	c->width[slot] = width;
	c->route[slot] = rt;
}

void rtos_host_mmio_route_cache_clear(void)
{
	route_cache_clear();
}

/* The handler's window for [phys, phys+size), or NULL if none is modelled. */
void *rtos_host_map_io(uintptr_t phys, SIZE size)
{
	if (mmio_ops == NULL || mmio_ops->map == NULL)
		return NULL;
	return mmio_ops->map(phys, size, mmio_ops->ctx);
}

/* Busy-waits dlytim ns: the calling context spends that much virtual CPU time. */
void sil_dly_nse(ulong_t dlytim)
{
	rtos_host_consume(dlytim);
}
