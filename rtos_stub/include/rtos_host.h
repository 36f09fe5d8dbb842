/*
 * rtos_host.h — the host backend's harness: boot, virtual time, interrupt
 * lines, device events, traces and bug reports.  Host only: nothing here
 * exists on the AM1808 (docs/rtos-stub.md lists what is host-only).
 *
 * Model: one CPU.  Tasks are coroutines on one OS thread.  Virtual time is
 * in nanoseconds and advances only when no task is ready (to the next event)
 * or when a context consumes CPU time (rtos_host_consume / sil_dly_nse).
 * Device events run at their time regardless of masking (they are the
 * hardware); interrupt delivery obeys enable state, CPU lock and priority.
 */
#ifndef RTOS_HOST_H
#define RTOS_HOST_H

#include <stdbool.h>
#include <stddef.h>
#include "kernel.h"
#include "rtos_cfg.h"

/* The length of one tick in virtual nanoseconds: TIC_NUME/TIC_DENO ms (kernel.h),
 * which must come out as a whole number of nanoseconds. */
#define RTOS_HOST_TICK_NS	((uint64_t)(TIC_NUME) * 1000000U / (TIC_DENO))

/* ---- Boot and run ---- */

/* Resets the kernel, checks cfg (and its includes), creates all objects, runs
 * ATT_INI routines, activates TA_ACT tasks.  Virtual time starts at 0.
 * Returns E_OK, or the error of the first bad row after printing it. */
ER rtos_host_boot(const struct rtos_cfg *cfg);

/* Text of the last boot error ("config \"app\" CRE_TSK[2] \"worker\": ... (E_PAR)"),
 * empty after a successful boot. */
const char *rtos_host_boot_error(void);

/* Ends the current boot like ext_ker: runs the ATT_TER routines (reverse
 * registration order, in the harness's non-task context "ter" with the
 * system still running, so they may use i-calls and rtos_host_run_* to let
 * tasks finish work), then frees task stacks, forgets objects and events. */
void rtos_host_shutdown(void);

/* Runs the system until virtual time now+ns (tasks, ticks, events, ISRs). */
void rtos_host_run_for(uint64_t ns);

/* Runs until virtual time t (absolute ns). */
void rtos_host_run_until(uint64_t t_ns);

/* Runs until no task is ready and no event other than ticks is pending, or
 * until max_ns of virtual time have passed.  Returns true if idle was reached. */
bool rtos_host_run_until_idle(uint64_t max_ns);

/* True once ext_ker has ended the system (until the next boot): the run
 * functions return at once; rtos_host_shutdown still runs the ATT_TER routines. */
bool rtos_host_exited(void);

/* Virtual time in ns since boot. */
uint64_t rtos_host_now(void);

/* The calling context (task, ISR, handler or harness) is busy for ns of
 * virtual CPU time; events due meanwhile fire, and interrupts nest if not
 * masked.  A task preempted meanwhile finishes its time when it runs again. */
void rtos_host_consume(uint64_t ns);

/* The calling context spins until absolute virtual time t_ns, as a loop that
 * polls a clock or a status register: events fire meanwhile and, in a task,
 * higher-priority tasks and interrupts preempt it — and unlike
 * rtos_host_consume the time it spends preempted counts toward t_ns, so it
 * never spins past t_ns for having been preempted.  Returns the CPU time the
 * caller itself spun (0 if t_ns has passed). */
uint64_t rtos_host_spin_until(uint64_t t_ns);

/* The time before which the calling task, at task level, spends CPU time
 * with nothing but the clock advancing: no event falls due, the run's
 * deadline is not reached, nothing is to be delivered or switched to.  Time
 * spent before it by rtos_host_consume and rtos_host_spin_until only moves
 * the clock, so one call to a time before it does what several would.  The
 * clock itself when something may happen at once, before boot, or when the
 * caller is not a task at task level. */
uint64_t rtos_host_quiet_until(void);

/* ---- CPU time of service calls and stalled tasks ---- */

/*
 * A service call made by a task costs virtual CPU time, so that a task that
 * busy-polls (`while (!ev3_touch_sensor_is_pressed(p));` makes a service call
 * or two per round) lets time pass as on the brick.  The defaults are make
 * bench's ARMv5 instruction counts (production build) at the AM1808's 300 MHz
 * when the model was made: a kernel service call costs what prb_mem, the call
 * ev3_uart_sensor_get_raw makes, measured (60 instructions: 200 ns), and
 * cal_svc what ev3_motor_set_speed, one extended service call, measured in
 * total (562 instructions: 1 873 ns; the service calls made inside it are not
 * charged again).  The counts have since fallen (prb_mem 29, set_speed 277),
 * but on the brick HRP2's trap, which make bench cannot count, comes on top of
 * each service call (estimated at 30 to 70 instructions, docs/bench.md): 29 +
 * 30..70 brackets 60, and 277 + 4 traps is 397..557, below 562.  The defaults
 * stay, keeping every recorded run's timing.  Only user-domain tasks are charged unless kernel_domain is set:
 * the platform's own timing stays what its tests measure.
 */
#define RTOS_HOST_CPU_HZ        300000000U
#define RTOS_HOST_SVC_INSN      60U
#define RTOS_HOST_EXT_SVC_INSN  562U
#define RTOS_HOST_INSN_NS(n)    ((uint32_t)(((uint64_t)(n) * 1000000000U + RTOS_HOST_CPU_HZ / 2) / RTOS_HOST_CPU_HZ))

/*
 * The app's own computation costs CPU time too: an EV3RT app is compiled
 * with -fsanitize-coverage=trace-pc (mk/ev3rt_app.mk), so every basic block
 * it enters calls __sanitizer_cov_trace_pc, and each block costs
 * RTOS_HOST_APP_BLOCK_INSN instructions at 300 MHz, charged to the task as
 * a service call is (user-domain tasks at task level, after boot; 16
 * blocks at a time).  The block counts are the compiler's, the same on the
 * host and the ARMv5 (gcc instruments before it lowers to a target).  Five
 * instructions a block is what the ARM926's build of integer code executes
 * under qemu-arm, measured with -singlestep on loops, a bubble sort and a
 * matrix product: 3.2 to 6.0 (docs/ev3rt-apps.md, CPU time); library code
 * the app calls (stdio, soft floating point) is not instrumented and costs
 * nothing, so a program spending its time there reads faster than on the
 * brick.
 */
#define RTOS_HOST_APP_BLOCK_INSN 5U

struct rtos_host_cpu_cost {
	uint32_t svc_ns;         /* a kernel service call (0: free) */
	uint32_t ext_svc_ns;     /* cal_svc, unless set per function code */
	bool     kernel_domain;  /* charge kernel-domain tasks too */
	uint32_t app_block_ns;   /* a basic block of an app's own code (0: free) */
};

/* Sets the costs (NULL: the defaults above); they stay across boots. */
void rtos_host_set_cpu_cost(const struct rtos_host_cpu_cost *cost);
void rtos_host_get_cpu_cost(struct rtos_host_cpu_cost *cost);
/* The cost of extended service call fncd (ns < 0: back to ext_svc_ns); E_PAR for a bad fncd. */
ER rtos_host_set_svc_cost(FN fncd, int32_t ns);

/*
 * A task that runs for stall_ms of wall-clock time without virtual time
 * advancing (a loop that makes no service call, or one in the kernel domain
 * with costs off) is reported as a bug naming the task and the PC it was at
 * ("addr2line -f -e PROGRAM OFFSET" gives the line); the system then ends as
 * after ext_ker and the run function returns.  A stall outside a task (an
 * ISR, the harness) is reported and the process exits with status 3.
 * Default 10 000 ms, or the environment's EV3LX_STALL_MS; 0 turns it off.
 */
void rtos_host_set_stall_bound(uint32_t stall_ms);
/* True if the last run ended with a stalled task (until the next boot). */
bool rtos_host_stalled(void);

/* ---- Fatal faults: stall, crash, stack overflow (docs/rtos-stub.md) ---- */

/*
 * The exit statuses of a program whose system ended on a fault: a stalled
 * task (stall.c), a fatal signal (crash.c: SIGSEGV, SIGBUS, SIGFPE, SIGILL,
 * SIGABRT), a task past its stack (its host stack's end, or more use than
 * its configuration gives it).  ev3sim uses the same numbers.
 */
#define RTOS_HOST_EXIT_STALL  3
#define RTOS_HOST_EXIT_CRASH  4
#define RTOS_HOST_EXIT_STACK  5

/*
 * Installs the fatal-signal report (rtos_host_boot does, once per process):
 * an alternate signal stack and handlers for SIGSEGV, SIGBUS, SIGFPE, SIGILL
 * and SIGABRT that print "FATAL: ..." lines on stderr naming the kind, the
 * context (the running task), the faulting address and the source line of
 * the faulting PC (addr2line), then exit with RTOS_HOST_EXIT_CRASH, or
 * RTOS_HOST_EXIT_STACK for a fault at a task stack's end.  A handler that was
 * installed before (AddressSanitizer's) runs after the report, for its own.
 */
void rtos_host_crash_install(void);
/* True if a handler running on the alternate signal stack may switch tasks:
 * the stack disarms itself while in use (SS_AUTODISARM), so a signal taken
 * meanwhile lands on the stack of whatever runs.  host_sim's pointer trap
 * runs there only then. */
bool rtos_host_signal_stack_disarms(void);
/* "function at file:line" of code address pc, by addr2line on the program
 * (or the shared object holding pc) into buf; false if unknown.  Safe enough
 * for a signal handler: dladdr, fork, exec, read, waitpid. */
bool rtos_host_source_line(uintptr_t pc, char *buf, size_t len);

/*
 * Stack use: the depth a task's own code reached below its entry, sampled
 * at each of its service calls made at task level (outside extended service
 * calls) — interrupts, device models and extended services run nested on the
 * host's task stacks and are not the task's.  A task whose use exceeds the
 * stack size its configuration gives it (stksz) by more than
 * RTOS_HOST_STACK_SLACK is reported as a bug ("stack: ...", naming the task,
 * the size and the use) and the system ends as after ext_ker;
 * rtos_host_end_status then says RTOS_HOST_EXIT_STACK.  The slack is the
 * host's own: 64-bit frames, and glibc's fprintf to an unbuffered stream (a
 * serial port's) keeps a BUFSIZ (8 KiB) buffer on the stack where newlib's
 * keeps 1 KiB — a 4 KiB task that logs that way measures 9.5 KiB here.
 */
#define RTOS_HOST_STACK_SLACK (16U * 1024U)
/* The deepest use measured for task tskid since boot (0 if none or no task). */
size_t rtos_host_task_stack_used(ID tskid);
/* Why the system ended: 0 (still running, never booted, or ext_ker),
 * RTOS_HOST_EXIT_STALL or RTOS_HOST_EXIT_STACK; until the next boot. */
int rtos_host_end_status(void);

/* ---- Device events (the hardware side) ---- */

typedef void (*rtos_host_event_fn)(void *arg);
typedef uint64_t rtos_host_event_t;         /* 0 = none */

/* Schedules fn(arg) at absolute virtual time t_ns (>= now).  Events at the
 * same time run in the order they were scheduled. */
rtos_host_event_t rtos_host_event_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg);

/* Cancels a scheduled event; cancelling a fired or unknown one is harmless. */
void rtos_host_event_cancel(rtos_host_event_t ev);

/*
 * A deferred event: an event whose effects only its owner can observe (a
 * polled transfer's end with no interrupt enabled) is not queued; it keeps
 * the place in the queue order it would have had (time and sequence), and
 * the owner completes it when something looks (rtos_host_deferred_due), or
 * queues it in that place when its effects become visible to others
 * (rtos_host_deferred_queue).  It counts as pending device work; when the
 * kernel needs it in the queue (rtos_host_run_until_idle's idle check) it
 * calls settle(arg), which must complete or queue it.  Owners keep the
 * struct; the kernel links it while armed.
 */
struct rtos_host_deferred {
	uint64_t time;
	uint64_t seq;
	rtos_host_event_fn fn;      /* the event's work, if queued */
	rtos_host_event_fn settle;  /* completes it if due, queues it otherwise */
	void *arg;
	struct rtos_host_deferred *next;
	bool armed;
};

/* Where the kernel keeps what the inline deferred-event functions below read
 * and update (the clock, the run's place in the queue order, the next
 * sequence number, the armed list); only event.c and those functions use it. */
struct rtos_host_deferred_state {
	uint64_t *now;              /* the virtual clock */
	const uint64_t *pos_time;   /* the last event taken (or the time settled) */
	const uint64_t *pos_seq;    /* its sequence (UINT64_MAX: the time settled) */
	uint64_t *seq;              /* the next event's sequence number */
	struct rtos_host_deferred **armed;
	/* before this time nothing stops time spent but the clock (no event due,
	 * not the run's deadline); 0 before boot */
	const uint64_t *quiet_until;
	const uint_t *access_depth; /* >0 inside a device event or register access */
};
extern const struct rtos_host_deferred_state rtos_host_deferred_state;

/* rtos_host_defer_at when d is still armed or t_ns has passed. */
void rtos_host_defer_at_slow(struct rtos_host_deferred *d, uint64_t t_ns, rtos_host_event_fn fn,
			     rtos_host_event_fn settle, void *arg);
/* rtos_host_deferred_disarm when d is armed but not first in the armed list. */
void rtos_host_deferred_unlink(struct rtos_host_deferred *d);

/* Binds d to its event fn(arg) and the owner's catch-up settle(arg) (see
 * above) for rtos_host_deferred_arm_in; d must not be armed.  Done once by an
 * owner that arms the same event again and again. */
static inline void rtos_host_deferred_bind(struct rtos_host_deferred *d, rtos_host_event_fn fn,
					   rtos_host_event_fn settle, void *arg)
{
	d->fn = fn;
	d->settle = settle;
	d->arg = arg;
}

/* Arms d, bound, at t_ns (>= now), ordered as rtos_host_event_at would
 * order it now. */
static inline void rtos_host_deferred_arm_at(struct rtos_host_deferred *d, uint64_t t_ns)
{
	const struct rtos_host_deferred_state *k = &rtos_host_deferred_state;

	if (d->armed || t_ns < *k->now) {
		rtos_host_defer_at_slow(d, t_ns, d->fn, d->settle, d->arg);
		return;
	}
	d->time = t_ns;
	d->seq = (*k->seq)++;
	d->armed = true;
	d->next = *k->armed;
	*k->armed = d;
}

/* Arms d, bound, ns from now (rtos_host_deferred_arm_at); returns its time.
 * Inline, with the clock read here: a polled transfer arms one per frame,
 * thousands per second. */
static inline uint64_t rtos_host_deferred_arm_in(struct rtos_host_deferred *d, uint64_t ns)
{
	uint64_t t_ns = *rtos_host_deferred_state.now + ns;

	rtos_host_deferred_arm_at(d, t_ns);
	return t_ns;
}

/* Binds d to fn(arg) and settle(arg) and arms it at t_ns (>= now). */
static inline void rtos_host_defer_at(struct rtos_host_deferred *d, uint64_t t_ns, rtos_host_event_fn fn,
				      rtos_host_event_fn settle, void *arg)
{
	rtos_host_deferred_bind(d, fn, settle, arg);
	rtos_host_deferred_arm_at(d, t_ns);
}

/* The calling context spends virtual CPU time until d's time as
 * rtos_host_consume does (nothing if it has come): a poll that waits for the
 * end of a transfer whose end is d (armed).  Inline, with rtos_host_consume's
 * quiet case outside task level (inside a register access or device event,
 * nothing due before d's time: only the clock moves): a polled transfer's
 * reader waits for nearly every frame. */
static inline void rtos_host_deferred_wait(const struct rtos_host_deferred *d)
{
	const struct rtos_host_deferred_state *k = &rtos_host_deferred_state;
	uint64_t now = *k->now;

	if (d->time <= now)
		return;
	if (d->time < *k->quiet_until && *k->access_depth != 0) {
		*k->now = d->time;
		return;
	}
	rtos_host_consume(d->time - now);
}

/* True if d, had it been queued, would have run by now (d must be armed):
 * the run is past d's place in the queue order, a later time, or d's time
 * with an event of a higher sequence run or the time settled. */
static inline bool rtos_host_deferred_due(const struct rtos_host_deferred *d)
{
	const struct rtos_host_deferred_state *k = &rtos_host_deferred_state;

	if (*k->now != d->time)
		return *k->now > d->time;
	return *k->pos_time != d->time || *k->pos_seq > d->seq;
}

/* Disarms d (completed by its owner, or abandoned); harmless if not armed. */
static inline void rtos_host_deferred_disarm(struct rtos_host_deferred *d)
{
	struct rtos_host_deferred **armed = rtos_host_deferred_state.armed;

	if (!d->armed)
		return;
	if (*armed != d) {
		rtos_host_deferred_unlink(d);
		return;
	}
	*armed = d->next;
	d->next = NULL;
	d->armed = false;
}

/* Disarms d and queues its event in d's place in the order; its handle. */
rtos_host_event_t rtos_host_deferred_queue(struct rtos_host_deferred *d);

/* ---- Interrupt lines ---- */

/* Latches an edge on the line: it is delivered once, when enabled and unmasked. */
void rtos_host_irq_raise(INTNO intno);
/* Sets a level-sensitive request; delivered (again) while asserted. */
void rtos_host_irq_set_level(INTNO intno, bool asserted);
/* The same at absolute virtual time t_ns (a device event; cancel with rtos_host_event_cancel). */
rtos_host_event_t rtos_host_irq_raise_at(uint64_t t_ns, INTNO intno);
rtos_host_event_t rtos_host_irq_set_level_at(uint64_t t_ns, INTNO intno, bool asserted);
/* Forgets a latched edge that was not delivered yet. */
void rtos_host_irq_clear(INTNO intno);
bool rtos_host_irq_pending(INTNO intno);
bool rtos_host_irq_enabled(INTNO intno);
/* Priority the line was configured with (CFG_INT), or 0 if unconfigured. */
PRI  rtos_host_irq_priority(INTNO intno);
/* Interrupt nesting depth of the running code (0 in task context or idle). */
uint_t rtos_host_irq_depth(void);

/* ---- Register access routing (installed by host_sim) ---- */

struct rtos_host_mmio_ops {
	/* Return true if addr is device memory this handler serves. */
	bool (*claims)(const volatile void *addr, void *ctx);
	uint32_t (*read)(const volatile void *addr, uint_t width, void *ctx);
	void (*write)(volatile void *addr, uint_t width, uint32_t data, void *ctx);
	/* Returns a window for physical range [phys, phys+size), or NULL if unmodelled. */
	void *(*map)(uintptr_t phys, SIZE size, void *ctx);
	void *ctx;
};
/* Installs the handler (NULL: plain memory accesses, no device windows). */
void rtos_host_set_mmio_handler(const struct rtos_host_mmio_ops *ops);
/* Optional, after rtos_host_set_mmio_handler: the handler claims exactly the
 * addresses in [start, start + len), so accesses are routed by that range
 * without calling claims (a handler change forgets it). */
void rtos_host_set_mmio_window(uintptr_t start, uintptr_t len);
/* The handler's read and write, except that they return the virtual CPU time
 * the access costs instead of spending it (a read: in the upper 32 bits, the
 * value read in the lower). */
typedef uint64_t (*rtos_host_mmio_read_timed_fn)(const volatile void *addr, uint_t width, void *ctx);
typedef uint32_t (*rtos_host_mmio_write_timed_fn)(volatile void *addr, uint_t width, uint32_t data, void *ctx);
/* Optional, after rtos_host_set_mmio_handler: accesses the handler serves go
 * to these instead of its read and write, and the accessor spends the time
 * they return right after them — without a call when no event falls due
 * before its end (a handler change forgets them; both or neither). */
void rtos_host_set_mmio_timed(rtos_host_mmio_read_timed_fn read, rtos_host_mmio_write_timed_fn write);
/*
 * Optional, after rtos_host_set_mmio_timed: the route cache.  A handler whose
 * accesses all cost the same time can tell the accessors how it serves an
 * access it has checked (address, width, direction): a route, which it embeds
 * in its own structure.  An access the cache knows calls the route's function
 * directly, with no window test and no call to the timed pair; any other goes
 * the way above.  The handler fills the cache from its timed pair and empties
 * it whenever a route stops being right for its address (the device's power,
 * its registers or their logging changed); a handler change empties it.
 */
struct rtos_host_mmio_route {
	/* read routes: the value the access reads */
	uint32_t (*read)(const struct rtos_host_mmio_route *rt);
	/* write routes: the write of data (not yet masked to the access's width) */
	void (*write)(const struct rtos_host_mmio_route *rt, uint32_t data);
};
/* Turns the route cache on (emptied); every access it serves costs access_ns
 * of virtual CPU time, spent as the timed pair's. */
void rtos_host_set_mmio_route_cache(uint32_t access_ns);
/* Caches rt for width-byte accesses at addr (write: writes, else reads); nothing
 * while the cache is off.  The access must be one the timed pair serves in the
 * window, with a width of 1, 2 or 4 that addr is aligned to, and rt must stay
 * valid until the cache is emptied; anything else is reported as a bug and not
 * cached. */
void rtos_host_mmio_route_cache_fill(bool write, const volatile void *addr, uint_t width,
				     const struct rtos_host_mmio_route *rt);
/* Empties the route cache. */
void rtos_host_mmio_route_cache_clear(void);
/* The window for a physical register range, or NULL if none is modelled. */
void *rtos_host_map_io(uintptr_t phys, SIZE size);

/* ---- Boot arguments ---- */

/* The command line the simulated boot loader hands the next boots (NULL:
 * none), as U-Boot's bootargs: the board sets it when it is created, the
 * layers above read it (linux_compat takes "module.param=value" words as
 * module parameters).  The string must stay valid until changed. */
void rtos_host_set_boot_args(const char *args);
/* The command line set by rtos_host_set_boot_args ("" if none). */
const char *rtos_host_boot_args(void);

/* ---- Trace ---- */

/* Every kernel event (dispatch, ISR entry/exit, tick work, service-call
 * errors) and every line other layers record goes to the sink as one text
 * line "<ns> <source> <text>".  Same inputs give byte-identical traces. */
typedef void (*rtos_host_trace_sink)(const char *line, void *ctx);
void rtos_host_trace_set_sink(rtos_host_trace_sink sink, void *ctx);
/* The same for a sink that takes the lines of one source only ("syslog"):
 * the other lines are not even formatted. */
void rtos_host_trace_set_source_sink(const char *source, rtos_host_trace_sink sink, void *ctx);
void rtos_host_trace(const char *source, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

/* ---- Scheduler observer (host_sim's VCD timeline of tasks and interrupts) ---- */

/* What runs a handler the observer is told of. */
enum rtos_host_handler_kind { RTOS_HOST_HANDLER_ISR, RTOS_HOST_HANDLER_CYC, RTOS_HOST_HANDLER_ALM };

/* Told of every task state change (state: TTS_DMT, TTS_RDY, TTS_WAI, TTS_SUS,
 * TTS_WAS; the running task is TTS_RDY and is named by running), of every
 * change of the running task (0: the CPU is idle) and of every entry and exit
 * of an interrupt line's service (id: the line) or of a cyclic or alarm
 * handler (id: its ID).  It must not call the kernel or spend virtual time:
 * a run observed is the run unobserved. */
struct rtos_host_sched_observer {
	void (*task_state)(ID tskid, const char *name, STAT state);
	void (*running)(ID tskid);
	void (*handler)(enum rtos_host_handler_kind kind, unsigned id, bool enter);
};
/* Installs the observer (NULL: none, the default); it stays across boots. */
void rtos_host_set_sched_observer(const struct rtos_host_sched_observer *obs);

/* ---- Bug reports (context violations and other misuse) ---- */

/* Reports a bug: prints "BUG: ..." with virtual time and context to stderr and
 * a TAP diagnostic; unless expected, the process will exit non-zero. */
void rtos_host_bug(const char *what, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* While expecting, bugs are counted but do not fail the run (for tests of the checks). */
void rtos_host_expect_bugs(bool expect);
/* Number of bugs reported since boot. */
uint_t rtos_host_bug_count(void);
/* Text of the last bug report (empty if none). */
const char *rtos_host_last_bug(void);

/* ---- Context introspection for layers above ---- */

/* A name for the current context: "task <name>", "isr <intno>", "cyclic <id>", "alarm <id>", "init",
 * "event", "ter" (the harness during ATT_TER routines), "idle". */
const char *rtos_host_context_name(void);
/* The domain of the calling task (TDOM_KERNEL in non-task context). */
ID rtos_host_current_domain(void);

#endif /* RTOS_HOST_H */
