/*
 * interrupt.c — interrupt lines (CFG_INT), ISRs (ATT_ISR) and delivery.
 *
 * A line is pending while an edge is latched or its level is asserted.  It is
 * delivered when it is enabled, the CPU is not locked, no SIL lock is held,
 * no device event or MMIO access is in progress, and its priority is higher
 * (more negative) than the current interrupt priority.  Delivery is a nested
 * function call on the current stack; on return from the outermost ISR in a
 * task, the dispatcher runs.
 */
#include <stdlib.h>
#include <string.h>

#include "kernel_impl.h"

/* Deliveries of one asserted level line at one virtual time before it is called a storm. */
#define IRQ_STORM_LIMIT 10000U

struct isr_entry {
	ISR      isr;
	intptr_t exinf;
	PRI      isrpri;
};

struct irq_line {
	bool     configured;
	bool     enabled;
	bool     edge;        /* latched edge not yet delivered */
	bool     level;       /* level request asserted */
	PRI      pri;
	struct isr_entry *isrs;
	uint_t   nisrs;
	uint64_t storm_time;
	uint_t   storm_count;
};

#define IRQ_WORDS ((TMAX_INTNO + 64U) / 64U)

struct cpu_state cpu;
static struct irq_line lines[TMAX_INTNO + 1];
static uint64_t pending_bits[IRQ_WORDS];
uint_t irq_pending_lines;
PRI irq_best_pri = IRQ_BEST_NONE;
static INTNO irq_best_line;   /* the line of irq_best_pri, when that is a priority */

/* Sets the pending bit of line n, which has just got a request; if it was clear,
 * the line may come before the best one. */
static inline void pend_set(INTNO n)
{
	uint64_t bit = 1ULL << (n % 64U);
	uint64_t *word = &pending_bits[n / 64U];
	const struct irq_line *l = &lines[n];

	if (*word & bit)
		return;
	*word |= bit;
	irq_pending_lines++;
	/* a rescan (the lowest value) stays one; none (the highest) gives way to any line */
	if (l->enabled && irq_best_pri != IRQ_BEST_RESCAN &&
	    (l->pri < irq_best_pri || (l->pri == irq_best_pri && n < irq_best_line))) {
		irq_best_pri = l->pri;
		irq_best_line = n;
	}
}

/* Clears the pending bit of line n, which had it, now that it has neither edge nor level. */
static inline void pend_clear_set_bit(INTNO n)
{
	pending_bits[n / 64U] &= ~(1ULL << (n % 64U));
	irq_pending_lines--;
	if (irq_pending_lines == 0)
		irq_best_pri = IRQ_BEST_NONE;
	else if (irq_best_pri != IRQ_BEST_NONE && n == irq_best_line)
		irq_best_pri = IRQ_BEST_RESCAN;
}

/* Clears the pending bit of line n if it has neither edge nor level any more. */
static inline void pend_drop(INTNO n)
{
	if (!lines[n].edge && !lines[n].level && (pending_bits[n / 64U] & (1ULL << (n % 64U))))
		pend_clear_set_bit(n);
}

/* Finds the best line again (IRQ_BEST_RESCAN): the first pending enabled one in
 * (priority, number) order. */
static __attribute__((noinline)) void best_rescan(void)
{
	irq_best_pri = IRQ_BEST_NONE;
	for (uint_t w = 0; w < IRQ_WORDS; w++) {
		uint64_t bits = pending_bits[w];

		while (bits) {
			INTNO n = w * 64U + (INTNO)__builtin_ctzll(bits);

			bits &= bits - 1;
			if (lines[n].enabled && lines[n].pri < irq_best_pri) {
				irq_best_pri = lines[n].pri;
				irq_best_line = n;
			}
		}
	}
}

/* The priority of the best line (IRQ_BEST_NONE if none), looked for again if needed. */
static inline PRI best_pri(void)
{
	if (irq_best_pri == IRQ_BEST_RESCAN)
		best_rescan();
	return irq_best_pri;
}

/* Runs one handler body in non-task context kind; a CPU lock left behind is released. */
void run_handler(enum exec_kind kind, ID id, void (*fn)(intptr_t), intptr_t exinf)
{
	enum exec_kind saved_kind = cpu.kind;
	ID saved_id = cpu.exec_id;

	cpu.kind = kind;
	cpu.exec_id = id;
	if (trace_on())
		rtos_host_trace("kernel", "%s %d", kind == EXEC_CYC ? "cyclic" : "alarm", (int)id);
	observe_handler(kind == EXEC_CYC ? RTOS_HOST_HANDLER_CYC : RTOS_HOST_HANDLER_ALM, (unsigned)id, true);
	fn(exinf);
	observe_handler(kind == EXEC_CYC ? RTOS_HOST_HANDLER_CYC : RTOS_HOST_HANDLER_ALM, (unsigned)id, false);
	cpu.locked = false;
	cpu.kind = saved_kind;
	cpu.exec_id = saved_id;
}

/* Runs the ISRs of line n, none or several, in isrpri order, in its ISR context.
 * Out of line: line_run then keeps fewer registers across its calls. */
static __attribute__((noinline)) void isrs_run_all(const struct irq_line *l, INTNO n)
{
	for (const struct isr_entry *e = l->isrs, *end = e + l->nisrs; e != end;) {
		e->isr(e->exinf);
		cpu.locked = false;   /* TOPPERS releases a CPU lock an ISR returns with */
		if (++e == end)
			break;        /* line_run's restore sets kind and exec_id */
		cpu.kind = EXEC_ISR;
		cpu.exec_id = (ID)n;
	}
}

/* Takes pending line n's request for its delivery (an edge is consumed, a
 * level stays); false if a level line storms (then disabled, not delivered). */
static inline __attribute__((always_inline)) bool line_take(INTNO n)
{
	struct irq_line *l = &lines[n];

	if (l->level) {
		if (l->storm_time == now_ns && ++l->storm_count > IRQ_STORM_LIMIT) {
			l->enabled = false;
			irq_best_pri = IRQ_BEST_RESCAN;
			rtos_host_bug("irq storm", "line %u is level-asserted and was delivered %u times at "
				      "the same virtual time (its ISR does not clear the source); line disabled",
				      n, IRQ_STORM_LIMIT);
			return false;
		}
		if (l->storm_time != now_ns) {
			l->storm_time = now_ns;
			l->storm_count = 1;
		}
	}
	l->edge = false;
	if (!l->level)
		pend_clear_set_bit(n);
	return true;
}

/* Serves line n, its request taken: the kernel tick work (INTNO_TICK), then
 * its ISRs in isrpri order, in its ISR context. */
static inline __attribute__((always_inline)) void line_serve(INTNO n)
{
	const struct irq_line *l = &lines[n];
	enum exec_kind saved_kind = cpu.kind;
	ID saved_id = cpu.exec_id;
	PRI saved_ipm = cpu.ipm;

	cpu.kind = EXEC_ISR;
	cpu.exec_id = (ID)n;
	cpu.ipm = l->pri;
	cpu.isr_depth++;
	if (trace_on())
		rtos_host_trace("kernel", "isr %u enter", n);
	observe_handler(RTOS_HOST_HANDLER_ISR, n, true);
	if (n == INTNO_TICK)
		tick_handler();
	if (l->nisrs == 1) {
		/* most lines have one ISR (the tick, a GPIO bank, a UART): no list walk */
		l->isrs[0].isr(l->isrs[0].exinf);
		cpu.locked = false;
	} else {
		isrs_run_all(l, n);
	}
	observe_handler(RTOS_HOST_HANDLER_ISR, n, false);
	if (trace_on())
		rtos_host_trace("kernel", "isr %u exit", n);
	cpu.isr_depth--;
	cpu.ipm = saved_ipm;
	cpu.kind = saved_kind;
	cpu.exec_id = saved_id;
}

/* Delivers pending line n.  Out of line, like irq_run_tick: the delivery
 * loop around them then saves no registers of its own. */
static __attribute__((noinline)) void irq_run(INTNO n)
{
	if (line_take(n))
		line_serve(n);
}

/* Serves the tick line (line_serve with its number a constant: 5000 times a virtual second). */
static __attribute__((noinline)) void irq_serve_tick(void)
{
	line_serve(INTNO_TICK);
}

/* Delivers the pending tick line. */
static __attribute__((noinline)) void irq_run_tick(void)
{
	if (line_take(INTNO_TICK))
		irq_serve_tick();
}

/* True if some line could be delivered in the current CPU state. */
bool irq_deliverable(void)
{
	return irq_pending_lines != 0 && !cpu.locked && cpu.sil_lock == 0 && cpu.irq_defer == 0 &&
	       best_pri() < cpu.ipm;
}

/* Delivers the pending lines the CPU accepts now, best first, until none is
 * left or a lock stops it (an ISR that returned with one), then dispatches
 * from a task's level.  from_line: a line was just served, so whether any is
 * left and the lock are looked at first.  (With no line pending irq_best_pri
 * is IRQ_BEST_NONE, above every mask: best_pri() would stop the loop too,
 * only later.) */
static inline __attribute__((always_inline)) void deliver_loop(bool from_line)
{
	if (!from_line || (irq_pending_lines != 0 && !cpu.locked && cpu.sil_lock == 0)) {
		while (best_pri() < cpu.ipm) {
			if (irq_best_line == INTNO_TICK)
				irq_run_tick();
			else
				irq_run(irq_best_line);
			if (irq_pending_lines == 0 || cpu.locked || cpu.sil_lock != 0)
				break;
		}
	}
	if (cpu.isr_depth == 0 && (schedtsk != runtsk || kernel_exited))   /* dispatch_if_needed's first test */
		dispatch_if_needed();
}

/* Delivers the pending interrupts the CPU accepts now, nested on the current stack
 * (irq_dispatch_pending's work once it found a line pending and no lock or deferral). */
void irq_deliver_pending(void)
{
	if (paused_task != NULL)
		return;
	deliver_loop(false);
}

/* ---- Configuration (boot) ---- */

/* Configures a line (CFG_INT row already checked). */
ER irq_configure(INTNO intno, ATR intatr, PRI intpri)
{
	struct irq_line *l = &lines[intno];

	l->configured = true;
	l->pri = intpri;
	l->enabled = (intatr & TA_ENAINT) != 0;
	irq_best_pri = irq_pending_lines ? IRQ_BEST_RESCAN : IRQ_BEST_NONE;
	return E_OK;
}

/* True if the line has a CFG_INT. */
bool irq_configured(INTNO intno)
{
	return intno <= TMAX_INTNO && lines[intno].configured;
}

/* Attaches an ISR (row already checked), keeping the line's ISRs in isrpri order. */
ER irq_attach(const struct rtos_isr_cfg *isr)
{
	struct irq_line *l = &lines[isr->intno];
	struct isr_entry *n = realloc(l->isrs, (l->nisrs + 1) * sizeof(*n));
	uint_t pos;

	if (n == NULL)
		return E_NOMEM;
	l->isrs = n;
	for (pos = l->nisrs; pos > 0 && l->isrs[pos - 1].isrpri > isr->isrpri; pos--)
		l->isrs[pos] = l->isrs[pos - 1];
	l->isrs[pos].isr = isr->isr;
	l->isrs[pos].exinf = isr->exinf;
	l->isrs[pos].isrpri = isr->isrpri;
	l->nisrs++;
	if (isr->intno == INTNO_TICK)
		tick_set_every(true);
	return E_OK;
}

/* Forgets every line and the CPU state (boot/shutdown). */
void irq_reset(void)
{
	for (INTNO n = 0; n <= TMAX_INTNO; n++)
		free(lines[n].isrs);
	memset(lines, 0, sizeof(lines));
	memset(pending_bits, 0, sizeof(pending_bits));
	irq_pending_lines = 0;
	irq_best_pri = IRQ_BEST_NONE;
	memset(&cpu, 0, sizeof(cpu));
	cpu.kind = EXEC_IDLE;
}

/* ---- Service calls ---- */

/* E_PAR for a number out of range, E_OBJ for an unconfigured line. */
static ER line_check(INTNO intno)
{
	if (intno > TMAX_INTNO)
		return E_PAR;
	if (!lines[intno].configured)
		return E_OBJ;
	return E_OK;
}

/* Masks one interrupt line (any context, CPU unlocked). */
ER dis_int(INTNO intno)
{
	ER ercd;

	svc_charge();
	if (cpu.locked)
		return svc_result("dis_int", E_CTX);
	if ((ercd = line_check(intno)) != E_OK)
		return svc_result("dis_int", ercd);
	lines[intno].enabled = false;
	irq_best_pri = irq_pending_lines ? IRQ_BEST_RESCAN : IRQ_BEST_NONE;
	return E_OK;
}

/* Unmasks one interrupt line; a pending request above the current priority is taken now. */
ER ena_int(INTNO intno)
{
	ER ercd;

	svc_charge();
	if (cpu.locked)
		return svc_result("ena_int", E_CTX);
	if ((ercd = line_check(intno)) != E_OK)
		return svc_result("ena_int", ercd);
	lines[intno].enabled = true;
	irq_best_pri = irq_pending_lines ? IRQ_BEST_RESCAN : IRQ_BEST_NONE;
	irq_dispatch_pending();
	return E_OK;
}

/* ---- Harness side: the hardware's interrupt requests ---- */

/* Reports a bad line number from the hardware side. */
static bool harness_line_ok(const char *fn, INTNO intno)
{
	if (intno > TMAX_INTNO) {
		rtos_host_bug("irq", "%s: interrupt number %u out of range 0..%u", fn, intno, TMAX_INTNO);
		return false;
	}
	return true;
}

/* Latches an edge on line n (in range) and delivers what the CPU accepts now. */
static inline __attribute__((always_inline)) void edge_raise(INTNO n)
{
	lines[n].edge = true;
	pend_set(n);
	irq_dispatch_pending();
}

/* Latches an edge on the line: delivered once, when enabled and unmasked. */
void rtos_host_irq_raise(INTNO intno)
{
	if (!harness_line_ok("rtos_host_irq_raise", intno))
		return;
	edge_raise(intno);
}

/* Latches the tick line's edge (the kernel timer's expiry) and delivers what the CPU accepts now. */
void irq_raise_tick(void)
{
	const struct irq_line *l = &lines[INTNO_TICK];

	/* Usually nothing else is pending and the CPU takes the tick at once: its
	 * edge would be latched and taken again (no line pending is the state
	 * before and after), so it is served directly, then the loop goes on as
	 * after any line. */
	if (irq_pending_lines != 0 || cpu.irq_defer != 0 || cpu.sil_lock != 0 || cpu.locked ||
	    paused_task != NULL || !l->enabled || l->pri >= cpu.ipm) {
		edge_raise(INTNO_TICK);
		return;
	}
	irq_serve_tick();
	deliver_loop(true);
}

/* Sets a level-sensitive request; delivered (again) while asserted. */
void rtos_host_irq_set_level(INTNO intno, bool asserted)
{
	if (!harness_line_ok("rtos_host_irq_set_level", intno))
		return;
	lines[intno].level = asserted;
	if (asserted) {
		pend_set(intno);
		irq_dispatch_pending();
	} else {
		pend_drop(intno);
	}
}

/* Device event: arg encodes the line and the change (0 edge, 1 level low, 2 level high). */
static void irq_change_event(void *arg)
{
	uintptr_t v = (uintptr_t)arg;
	INTNO intno = (INTNO)(v >> 2);

	if ((v & 3U) == 0)
		rtos_host_irq_raise(intno);
	else
		rtos_host_irq_set_level(intno, (v & 3U) == 2);
}

/* Latches an edge on the line at absolute virtual time t_ns. */
rtos_host_event_t rtos_host_irq_raise_at(uint64_t t_ns, INTNO intno)
{
	if (!harness_line_ok("rtos_host_irq_raise_at", intno))
		return 0;
	return rtos_host_event_at(t_ns, irq_change_event, (void *)((uintptr_t)intno << 2));
}

/* Sets or clears a level request at absolute virtual time t_ns. */
rtos_host_event_t rtos_host_irq_set_level_at(uint64_t t_ns, INTNO intno, bool asserted)
{
	if (!harness_line_ok("rtos_host_irq_set_level_at", intno))
		return 0;
	return rtos_host_event_at(t_ns, irq_change_event,
				  (void *)(((uintptr_t)intno << 2) | (asserted ? 2U : 1U)));
}

/* Forgets a latched edge that was not delivered yet. */
void rtos_host_irq_clear(INTNO intno)
{
	if (!harness_line_ok("rtos_host_irq_clear", intno))
		return;
	lines[intno].edge = false;
	pend_drop(intno);
}

/* True while an edge is latched or the level asserted. */
bool rtos_host_irq_pending(INTNO intno)
{
	return intno <= TMAX_INTNO && (lines[intno].edge || lines[intno].level);
}

/* True if the line is configured and enabled. */
bool rtos_host_irq_enabled(INTNO intno)
{
	return intno <= TMAX_INTNO && lines[intno].configured && lines[intno].enabled;
}

/* CFG_INT priority of the line, 0 if unconfigured. */
PRI rtos_host_irq_priority(INTNO intno)
{
	return irq_configured(intno) ? lines[intno].pri : 0;
}

/* Interrupt nesting depth of the running code. */
uint_t rtos_host_irq_depth(void)
{
	return cpu.isr_depth;
}
