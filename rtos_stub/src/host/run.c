/*
 * run.c — the harness main loop and CPU-time consumption.
 *
 * The harness runs on the OS thread's own stack, which is also the idle
 * context: when a task is ready it switches to the highest-priority one;
 * otherwise it advances virtual time to the next event and processes it.
 * Nothing is stepped per nanosecond.
 */
#include <stdlib.h>

#include "kernel_impl.h"

bool run_active;
uint64_t run_deadline;
struct tcb *paused_task;
bool kernel_exited;

/* From the harness: runs the highest-priority ready task until the CPU is idle again. */
static void harness_dispatch(void)
{
	struct tcb *to = schedtsk;

	runtsk = to;
	cpu.kind = EXEC_TASK;
	cpu.exec_id = to->id;
	observe_running(to);
	if (trace_on())
		rtos_host_trace("kernel", "dispatch %s", to->cfg->name ? to->cfg->name : "?");
	co_switch(&harness_co, &to->co, false);
}

/* From the harness: resumes the task paused at the previous run deadline. */
static void harness_resume(void)
{
	struct tcb *t = paused_task;

	paused_task = NULL;
	runtsk = t;
	cpu.kind = EXEC_TASK;
	cpu.exec_id = t->id;
	co_switch(&harness_co, &t->co, false);
}

/* From a task inside rtos_host_consume: hands the CPU to the harness at the run deadline. */
void pause_to_harness(void)
{
	struct tcb *t = runtsk;

	paused_task = t;
	runtsk = NULL;
	cpu.kind = EXEC_IDLE;
	cpu.exec_id = 0;
	co_switch(&t->co, &harness_co, false);
}

/* From a task after ext_ker: leaves for the harness for good (the task is never resumed). */
static __attribute__((noreturn)) void task_leave_for_exit(void)
{
	struct tcb *t = runtsk;

	cpu.locked = false;
	cpu.dsp_disabled = false;
	runtsk = NULL;
	cpu.kind = EXEC_IDLE;
	cpu.exec_id = 0;
	co_switch(&t->co, &harness_co, true);
	abort();
}

/* Ends the kernel: nothing runs until the next boot; rtos_host_shutdown then runs
 * the ATT_TER routines.  From a task it does not return; from a handler it
 * returns and the system stops when the CPU next reaches a task or the harness. */
ER ext_ker(void)
{
	if (!kernel_booted)
		return svc_result("ext_ker", E_CTX);
	kernel_exited = true;
	if (trace_on())
		rtos_host_trace("kernel", "ext_ker from %s", rtos_host_context_name());
	if (cpu.kind == EXEC_TASK && cpu.isr_depth == 0 && cpu.irq_defer == 0)
		task_leave_for_exit();
	return E_OK;
}

/* True after ext_ker (until the next boot). */
bool rtos_host_exited(void)
{
	return kernel_exited;
}

/* True if nothing but time events is left to do. */
static bool idle_reached(void)
{
	return schedtsk == NULL && paused_task == NULL && event_user_count() == 0 && !irq_deliverable();
}

/* Reports harness calls before boot or from inside the kernel. */
static bool harness_may_run(const char *fn)
{
	if (!kernel_booted) {
		rtos_host_bug("harness", "%s before rtos_host_boot", fn);
		return false;
	}
	if (kernel_exited)
		return false;	/* ext_ker: the system has ended, time stands still */
	if (run_active || cpu.kind != EXEC_IDLE || cpu.isr_depth != 0) {
		rtos_host_bug("harness", "%s called from inside the kernel (%s)", fn, rtos_host_context_name());
		return false;
	}
	return true;
}

/* Runs tasks, events and interrupts up to virtual time t; true if stopped at idle.
 * Inlined into each caller with until_idle a constant, so that the runs of the
 * harness (an iteration per event) do not test it. */
static inline __attribute__((always_inline)) bool run_loop(uint64_t t, bool until_idle)
{
	bool idle = false;

	run_active = true;
	run_deadline = t;
	event_set_run_bound(t);
	stall_watch_start();
	for (;;) {
		uint64_t next;

		if (kernel_exited)
			break;
		if (paused_task != NULL) {
			if (now_ns >= t)
				break;
			harness_resume();
			continue;
		}
		irq_dispatch_pending();
		if (schedtsk != NULL) {
			harness_dispatch();
			continue;
		}
		if (until_idle && idle_reached()) {
			idle = true;
			break;
		}
		next = event_next_time();
		if (next > t) {
			if (now_ns < t)
				now_ns = t;
			event_time_settled();
			break;
		}
		now_ns = next;
		event_run_next();
	}
	run_active = false;        /* the stall watch's next tick sees it and disarms its timer */
	event_set_run_bound(UINT64_MAX);
	return idle;
}

/* Runs the system until virtual time now + ns. */
void rtos_host_run_for(uint64_t ns)
{
	if (harness_may_run("rtos_host_run_for"))
		run_loop(ns > UINT64_MAX - now_ns ? UINT64_MAX : now_ns + ns, false);
}

/* Runs the system until absolute virtual time t_ns. */
void rtos_host_run_until(uint64_t t_ns)
{
	if (harness_may_run("rtos_host_run_until"))
		run_loop(t_ns, false);
}

/* Runs until no task is ready and no device event is pending, or for at most max_ns. */
bool rtos_host_run_until_idle(uint64_t max_ns)
{
	if (!harness_may_run("rtos_host_run_until_idle"))
		return false;
	return run_loop(max_ns > UINT64_MAX - now_ns ? UINT64_MAX : now_ns + max_ns, true);
}

/* True if the running code may be suspended or preempted while it consumes
 * time: a task outside any ISR and register access. */
static inline bool consume_at_task_level(void)
{
	/* Inside a register access (irq_defer) the access completes before any switch. */
	return cpu.kind == EXEC_TASK && cpu.isr_depth == 0 && cpu.irq_defer == 0;
}

/* True while the clock is before until; UINT64_MAX is "no bound" and, a
 * constant after inlining, costs consume's loop no compare. */
static inline __attribute__((always_inline)) bool before_until(uint64_t until)
{
	return until == UINT64_MAX || now_ns < until;
}

/*
 * The busy loop under rtos_host_consume and rtos_host_spin_until: the caller
 * runs until it has spun cpu_ns of its own time (if budgeted) or the clock
 * reaches until, whichever comes first.  Events fire meanwhile; at task level
 * interrupts and higher-priority tasks preempt it — their time counts toward
 * until, not toward cpu_ns — and it is suspended to the harness at the run's
 * deadline.  Returns the CPU time spun.  Inlined into each caller with
 * constant budgeted and (for consume) until, so that the bound a caller does
 * not use folds away (consume is on every service call's path, the spin on
 * every byte of a polled serial write).
 */
static inline __attribute__((always_inline)) uint64_t busy_loop(bool budgeted, uint64_t cpu_ns, uint64_t until)
{
	uint64_t spun = 0;
	bool task_level = consume_at_task_level();

	while ((!budgeted || spun < cpu_ns) && before_until(until)) {
		uint64_t limit, next;

		if (task_level) {
			irq_dispatch_pending();
			if (kernel_exited)
				task_leave_for_exit();
			if (schedtsk != runtsk)   /* dispatch_if_needed's first test, without the call */
				dispatch_if_needed();
			if (!before_until(until))   /* preempted past it: the poll finds it passed */
				break;
		}
		limit = until;
		if (budgeted && cpu_ns - spun < limit - now_ns)
			limit = now_ns + (cpu_ns - spun);
		next = event_next_time();
		/* At task level the run's deadline stops the time too; quiet_until is
		 * the earlier of it and the next event, so an event that is quiet_until
		 * comes no later than the deadline. */
		if (next <= limit && (!task_level || next == quiet_until)) {
			spun += next - now_ns;
			now_ns = next;
			event_run_next();
			continue;
		}
		/* Only a task can be suspended: ISRs and the harness share the thread's stack. */
		if (task_level && run_active && run_deadline < limit)
			limit = run_deadline > now_ns ? run_deadline : now_ns;
		spun += limit - now_ns;
		now_ns = limit;
		event_time_settled();
		if ((!budgeted || spun < cpu_ns) && before_until(until))
			pause_to_harness();
	}
	return spun;
}

/* rtos_host_consume when an event falls due, a task consumes, or before boot. */
static __attribute__((noinline)) void consume_slow(uint64_t ns)
{
	if (!kernel_booted) {
		rtos_host_bug("consume", "rtos_host_consume before rtos_host_boot");
		return;
	}
	busy_loop(true, ns, UINT64_MAX);
}

/* rtos_host_spin_until when something may stop the spin short of t_ns, or before boot. */
static __attribute__((noinline)) uint64_t spin_slow(uint64_t t_ns)
{
	if (!kernel_booted) {
		rtos_host_bug("spin", "rtos_host_spin_until before rtos_host_boot");
		return 0;
	}
	/* two copies: in the second the bound is known finite, so its checks of the clock are one compare */
	if (t_ns == UINT64_MAX)
		return busy_loop(false, 0, UINT64_MAX);
	return busy_loop(false, 0, t_ns);
}

/* The calling context spins until t_ns like a loop polling a clock: time spent
 * preempted counts toward t_ns.  Returns the CPU time it spun. */
uint64_t rtos_host_spin_until(uint64_t t_ns)
{
	uint64_t now = now_ns;

	/* Most polls of a serial line end before the next event, the run's
	 * deadline and boot (all in quiet_until) with nothing to deliver or
	 * switch to: busy_loop's one pass, advancing to t_ns and settling it. */
	if (t_ns < quiet_until && (!consume_at_task_level() || task_consume_quiet())) {
		if (now >= t_ns)
			return 0;
		now_ns = t_ns;
		event_time_settled();
		return t_ns - now;
	}
	return spin_slow(t_ns);
}

/* The end of the stretch a task may spend with nothing but the clock moving
 * (the fast paths of rtos_host_spin_until and rtos_host_consume). */
uint64_t rtos_host_quiet_until(void)
{
	if (!consume_at_task_level() || !task_consume_quiet())
		return now_ns;
	return quiet_until;
}

/* rtos_host_consume when quiet_until comes first: before boot, or the run's
 * deadline before the end. */
static __attribute__((noinline)) void consume_unquiet(uint64_t ns)
{
	if (ns < event_next_time() - now_ns && kernel_booted && !consume_at_task_level()) {
		now_ns += ns;
		return;
	}
	consume_slow(ns);
}

/* The calling context is busy for ns of virtual CPU time; events fire meanwhile. */
void rtos_host_consume(uint64_t ns)
{
	uint64_t end = now_ns + ns;

	/* When nothing can stop the time short of its end, the common case (a
	 * register access, a service call's charge, a short delay in an ISR) is one
	 * addition; a task's consume also settles the time as busy_loop does.
	 * (end < ns: the addition wrapped around.) */
	if (end < quiet_until && end >= ns) {
		if (!consume_at_task_level()) {
			now_ns = end;
			return;
		}
		if (task_consume_quiet()) {
			now_ns = end;
			event_time_settled();
			return;
		}
		consume_slow(ns);
		return;
	}
	consume_unquiet(ns);
}
