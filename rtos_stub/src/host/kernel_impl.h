/*
 * kernel_impl.h — state and helpers shared by the areas of the host kernel
 * (the .c files of rtos_stub/src/host).  Private to the kernel: nothing outside
 * rtos_stub/src/host includes it.
 *
 * Model (docs/rtos-stub.md): one CPU; tasks are coroutines on the OS thread;
 * the harness (rtos_host_run_*) runs on the thread's own stack and is the
 * idle context; interrupts run nested on whatever stack is current.  Nothing
 * here is thread-safe: the whole kernel runs on one OS thread.
 */
#ifndef RTOS_HOST_KERNEL_IMPL_H
#define RTOS_HOST_KERNEL_IMPL_H

#include <limits.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "kernel.h"
#include "rtos_cfg.h"
#include "rtos_host.h"

/* ---- Doubly-linked circular queues (ready queues, wait queues) ---- */

struct queue {
	struct queue *next;
	struct queue *prev;
};

/* Makes q an empty queue head. */
static inline void queue_init(struct queue *q)
{
	q->next = q;
	q->prev = q;
}

/* True if the queue head has no entries. */
static inline bool queue_empty(const struct queue *q)
{
	return q->next == q;
}

/* Inserts entry just before pos (at the tail when pos is the head). */
static inline void queue_insert_before(struct queue *pos, struct queue *entry)
{
	entry->prev = pos->prev;
	entry->next = pos;
	pos->prev->next = entry;
	pos->prev = entry;
}

/* Removes entry from whatever queue holds it; it becomes a lone node. */
static inline void queue_remove(struct queue *entry)
{
	entry->prev->next = entry->next;
	entry->next->prev = entry->prev;
	entry->next = entry;
	entry->prev = entry;
}

#define container_of_kernel(ptr, type, member) \
	((type *)(void *)((char *)(ptr) - offsetof(type, member)))

/* ---- Execution contexts ---- */

enum exec_kind {
	EXEC_IDLE,   /* the harness on the OS thread's stack: non-task context */
	EXEC_TASK,
	EXEC_ISR,
	EXEC_CYC,
	EXEC_ALM,
	EXEC_INIT,   /* ATT_INI routines at boot */
	EXEC_EVENT,  /* a device event (the hardware side), non-task context */
};

/* The CPU: what runs now and what it masks. */
struct cpu_state {
	enum exec_kind kind;
	ID       exec_id;        /* task, interrupt, cyclic or alarm ID */
	PRI      ipm;            /* current interrupt priority: 0 in task/idle, line priority in an ISR */
	uint_t   isr_depth;      /* nesting of interrupts (and time-event handlers) */
	bool     locked;         /* CPU lock (loc_cpu/iloc_cpu) */
	bool     dsp_disabled;   /* dis_dsp */
	uint_t   sil_lock;       /* SIL_LOC_INT nesting */
	uint_t   irq_defer;      /* >0 while a device event or MMIO access is in progress */
};
extern struct cpu_state cpu;

/* ---- Coroutines ---- */

/* A resume point of GCC's __builtin_setjmp: frame pointer, resume address,
 * stack pointer (five words, as GCC documents). */
typedef void *co_resume_point[5];

struct coroutine {
	co_resume_point jb;      /* where a suspended coroutine resumes */
	co_resume_point start_jb;   /* the entry point, kept for restarts */
	void    *map_base;       /* mmap'ed region including the guard page */
	size_t   map_size;
	void    *stack_lo;       /* usable stack [stack_lo, stack_lo + stack_size) */
	size_t   stack_size;
	void    *fake_stack;     /* ASan fake stack saved while suspended */
	void   (*entry)(void);   /* what a (re)started coroutine runs */
	bool     restart;        /* next switch enters at start_jb */
};
extern struct coroutine harness_co;   /* the OS thread's own stack: the harness and idle */

/* Creates a coroutine with a stack of stack_size bytes entering entry(); false on ENOMEM. */
bool co_create(struct coroutine *co, size_t stack_size, void (*entry)(void));
/* Frees the coroutine's stack. */
void co_destroy(struct coroutine *co);
/* Suspends from and resumes to; from_dying: from never resumes at jb again. */
void co_switch(struct coroutine *from, struct coroutine *to, bool from_dying);

/* ---- Tasks ---- */

enum wait_kind {
	WAIT_NONE, WAIT_SLP, WAIT_DLY, WAIT_SEM, WAIT_FLG,
	WAIT_SDTQ, WAIT_RDTQ, WAIT_SPDQ, WAIT_RPDQ, WAIT_MTX,
};

struct mtxcb;

/* A time event: fires in the tick handler when the tick count reaches tick. */
struct tmevt {
	uint64_t tick;
	uint64_t seq;
	uint_t   heap_index;     /* UINT32_MAX when not queued */
	void   (*callback)(struct tmevt *ev);
};

struct tcb {
	struct queue node;               /* ready queue or wait queue */
	const struct rtos_task_cfg *cfg;
	const char *cfg_name;            /* configuration that declared it */
	ID       id;
	STAT     state;                  /* TTS_DMT, TTS_RDY (includes running), TTS_WAI, TTS_SUS */
	PRI      bpri;                   /* current priority: what the queues order by */
	PRI      base_pri;               /* base priority (chg_pri); mutexes may raise bpri above it */
	bool     suspended;              /* sus_tsk: TTS_SUS, or TTS_WAS while state is TTS_WAI */
	struct mtxcb *mtx_last;          /* the mutex it locked last (a stack through mtxcb.prev_locked) */
	intptr_t wdata;                  /* data queues: the element sent or received */
	PRI      wdpri;                  /* priority data queues: its priority */
	uint_t   nocharge_depth;         /* inside a call whose cost covers its nested calls (cal_svc) */
	uint_t   actcnt;
	uint_t   wupcnt;
	enum wait_kind wait;
	ID       wobjid;
	struct queue *wait_queue;        /* queue the task waits in, or NULL */
	ER       wercd;
	FLGPTN   waiptn;
	MODE     wfmode;
	FLGPTN   flgptn;                 /* pattern at release */
	struct tmevt tmevt;
	struct coroutine co;
	bool     call_us;                /* inside an HRP3-profile service call: its times are in us (hrp3.c) */
	uintptr_t stack_entry;           /* the stack pointer where the task's code starts (task_entry) */
	size_t   stack_used;             /* the deepest use below stack_entry seen since boot */
};

extern struct tcb *tcb_table[TNUM_TSKID + 1];   /* NULL: not configured */
extern struct tcb *runtsk;     /* the task the CPU runs (NULL in idle) */
extern struct tcb *schedtsk;   /* the highest-priority ready task (NULL: none) */

/* Marks t ready at the tail of its priority queue. */
void ready_insert_tail(struct tcb *t);
/* Marks t ready at the head of its priority queue. */
void ready_insert_head(struct tcb *t);
/* Sets t's current priority: a ready task goes to the head (mutex) or tail (chg_pri)
 * of its new priority, a waiting one moves in a priority-ordered wait queue. */
void task_set_priority(struct tcb *t, PRI pri, bool head);
/* True if the queue t waits in is in priority order. */
bool wait_queue_tpri(const struct tcb *t);
/* Removes t from the ready queue. */
void ready_remove(struct tcb *t);
/* Moves the first ready task of pri to the tail of its priority. */
void ready_rotate(PRI pri);
/* Recomputes schedtsk from the ready queues. */
void update_schedtsk(void);
/* Switches tasks if the current task context may and should be preempted. */
void dispatch_if_needed(void);
/* From a task: switch to schedtsk (or to idle); returns when this task runs again. */
void task_switch(void);
/* Makes a dormant task ready from its start (activation). */
void task_activate(struct tcb *t);
/* Puts runtsk to wait; returns the release code (E_OK, E_TMOUT, E_RLWAI...). */
ER wait_block(enum wait_kind kind, ID objid, struct queue *wq, bool tpri, TMO tmout);
/* wait_block's first half: runtsk waits from now on; the caller then calls task_switch. */
void wait_enter(enum wait_kind kind, ID objid, struct queue *wq, bool tpri, TMO tmout);
/* Releases a waiting task with ercd; it becomes ready (no dispatch here). */
void wait_release(struct tcb *t, ER ercd);
/* Reinserts a waiting task after a priority change (priority-ordered queues). */
void wait_requeue(struct tcb *t, bool tpri);
/* Resolves TSK_SELF; NULL and *ercd set on failure. */
struct tcb *task_lookup(ID tskid, bool self_ok, ER *ercd);
/* Checks a task-supplied output pointer: E_OK, or E_MACV. */
ER check_out_ptr(const void *p, SIZE size);
/* Task control blocks: create/destroy at boot/shutdown. */
ER task_create_all(void);
void task_destroy_all(void);

/* ---- Semaphores and eventflags ---- */
struct semcb {
	const struct rtos_sem_cfg *cfg;
	uint_t cnt;
	struct queue wq;
};
extern struct semcb *sem_table[TNUM_SEMID + 1];

struct flgcb {
	const struct rtos_flg_cfg *cfg;
	FLGPTN ptn;
	struct queue wq;
};
extern struct flgcb *flg_table[TNUM_FLGID + 1];

/* ---- Data queues, priority data queues, mutexes ---- */
struct dtqcb {
	const struct rtos_dtq_cfg *cfg;
	intptr_t *buf;           /* ring of cfg->dtqcnt elements */
	uint_t head, count;
	struct queue swq;        /* senders waiting (FIFO or TA_TPRI) */
	struct queue rwq;        /* receivers waiting (FIFO) */
};
extern struct dtqcb *dtq_table[TNUM_DTQID + 1];

struct pdq_elem {
	intptr_t data;
	PRI      pri;
};
struct pdqcb {
	const struct rtos_pdq_cfg *cfg;
	struct pdq_elem *buf;    /* cfg->pdqcnt elements, sorted by priority then arrival */
	uint_t count;
	struct queue swq;
	struct queue rwq;
};
extern struct pdqcb *pdq_table[TNUM_PDQID + 1];

struct mtxcb {
	const struct rtos_mtx_cfg *cfg;
	struct tcb *owner;       /* NULL: unlocked */
	struct mtxcb *prev_locked;   /* the owner's mutex locked before this one */
	struct queue wq;         /* waiters, in priority order unless TA_NULL */
};
extern struct mtxcb *mtx_table[TNUM_MTXID + 1];

/* The priority t runs at: its base priority raised by the ceilings of the
 * mutexes it holds and by the waiters of those with priority inheritance. */
PRI  mtx_effective_priority(const struct tcb *t);
/* Recomputes t's current priority after a mutex change; follows inheritance chains. */
void mtx_update_priority(struct tcb *t);
/* Unlocks every mutex t holds (its end: ext_tsk, ter_tsk), handing each to its first waiter. */
void mtx_release_all(struct tcb *t);
/* A waiter left mutex mtxid's queue (timeout, rel_wai, ter_tsk): the owner's priority may drop. */
void mtx_waiter_left(ID mtxid);
/* Allocates the control blocks of one configuration's rows (already checked). */
ER   dtq_create(const struct rtos_dtq_cfg *cfg);
ER   pdq_create(const struct rtos_pdq_cfg *cfg);
ER   mtx_create(const struct rtos_mtx_cfg *cfg);
void dtq_pdq_mtx_reset(void);
/* ---- Time ---- */
extern uint64_t now_ns;        /* the virtual clock */
extern uint64_t tick_done;     /* last tick index processed by the tick handler */

/* Tick index of a relative time of ms from now (at least ms later, after tick_done). */
uint64_t tick_after_ns(uint64_t ns);
/* The largest relative time of the running call's profile: TMAX_RELTIM ms
 * (HRP2), HRP3_TMAX_RELTIM us inside an HRP3-profile call. */
uint32_t svc_reltim_max(void);
/* A relative time of the running call's profile (ms; us inside an HRP3-profile
 * call of a task) in ns. */
uint64_t svc_reltim_ns(uint32_t reltim);
/* sta_alm's body for any context: the alarm runs ns from now (E_ID, E_NOEXS). */
ER alm_start_ns(const char *svc, ID almid, uint64_t ns);
/* The time left until cyclic handler cycid's next activation (*left_ns) and
 * whether it runs (E_ID, E_NOEXS). */
ER cyc_state(ID cycid, bool *started, uint64_t *left_ns);
/* The time left until alarm almid runs (*left_ns) and whether it is armed. */
ER alm_state(ID almid, bool *started, uint64_t *left_ns);
void tmevt_enqueue(struct tmevt *ev, uint64_t tick);
void tmevt_dequeue(struct tmevt *ev);
static inline bool tmevt_queued(const struct tmevt *ev)
{
	return ev->heap_index != UINT32_MAX;
}
/* The kernel's part of the tick interrupt: processes due time events. */
void tick_handler(void);
/* Decides whether the tick must run on every boundary (ISRs on INTNO_TICK). */
void tick_set_every(bool every);
void time_reset(void);
void time_start(void);

/* ---- Events (the device-event heap) ---- */
void event_reset(void);
extern uint64_t event_head_time;         /* the earliest event's time, UINT64_MAX if none */
/* Time of the earliest scheduled event, UINT64_MAX if none. */
static inline uint64_t event_next_time(void)
{
	return event_head_time;
}
/* Until this time nothing can stop a context spending virtual time but the
 * clock: the earliest of the next event and, during a run of the harness, the
 * run's deadline; 0 while the kernel is not booted.  The fast ends of register
 * accesses and rtos_host_consume test it alone for all three. */
extern uint64_t quiet_until;
/* Sets quiet_until's other bound: the run's deadline when a run starts,
 * UINT64_MAX when it ends and at boot (event_reset sets 0). */
void event_set_run_bound(uint64_t t_ns);
/* Pops and runs the earliest event; now_ns must already be its time. */
void event_run_next(void);
/* Number of scheduled non-kernel events (deferred ones settled first). */
uint_t event_user_count(void);
/* The sequence of the last event taken, UINT64_MAX once its time is settled (event.c). */
extern uint64_t ev_pos_seq;
/* Tells the queue that every event due by now has run (deferred ones at now are
 * due); inline, as the run loops settle after every stretch of busy time. */
static inline void event_time_settled(void)
{
	ev_pos_seq = UINT64_MAX;
}
/* The kernel timer, beside the queue: raises the tick (irq_raise_tick) at t_ns (>= now),
 * ordered as an event scheduled now, then every period_ns unless 0, replacing its
 * previous setting; not device work. */
void event_timer_set(uint64_t t_ns, uint64_t period_ns);
/* The time the kernel timer is set to, UINT64_MAX when off. */
uint64_t event_timer_time(void);

/* ---- Interrupts ---- */
void irq_reset(void);
extern uint_t irq_pending_lines;   /* lines with a latched edge or an asserted level */
/* Priority of the pending enabled line delivered first (the lowest priority value, then
 * the lowest number), kept as lines change: IRQ_BEST_NONE if there is none, IRQ_BEST_RESCAN
 * when it is to be looked for again (below every interrupt priority mask: a delivery looks). */
extern PRI irq_best_pri;
#define IRQ_BEST_NONE   INT_MAX
#define IRQ_BEST_RESCAN INT_MIN
/* Latches the tick line's edge (the kernel timer's expiry) and delivers what the CPU accepts now. */
void irq_raise_tick(void);
/* irq_dispatch_pending's work, once its checks passed (a line pending, no lock, no deferral). */
void irq_deliver_pending(void);
/* Delivers pending interrupts the CPU accepts now (nested on the current stack). */
static inline void irq_dispatch_pending(void)
{
	/* inside a device event or access, or under a lock, nothing is delivered yet; in an
	 * ISR (the ipm is 0 outside them), nothing either unless a line is above its priority */
	if (irq_pending_lines != 0 && cpu.irq_defer == 0 && cpu.sil_lock == 0 && !cpu.locked &&
	    (irq_best_pri < cpu.ipm || cpu.isr_depth == 0))
		irq_deliver_pending();
}
/* True if some line could be delivered in the current CPU state. */
bool irq_deliverable(void);
ER   irq_configure(INTNO intno, ATR intatr, PRI intpri);
ER   irq_attach(const struct rtos_isr_cfg *isr);
bool irq_configured(INTNO intno);
/* Runs fn(arg) as a non-task handler of the given kind (cyclic, alarm) at the current ipm. */
void run_handler(enum exec_kind kind, ID id, void (*fn)(intptr_t), intptr_t exinf);

/* ---- Harness run state ---- */
extern bool run_active;        /* inside rtos_host_run_* */
extern uint64_t run_deadline;
extern bool kernel_booted;
extern bool terminating;       /* rtos_host_shutdown is running the ATT_TER routines */
extern struct tcb *paused_task;   /* a task stopped at the run deadline inside rtos_host_consume */
extern bool kernel_exited;        /* ext_ker was called: nothing runs until the next boot */
/* Enters the harness from a task paused at the run deadline mid-consume. */
void pause_to_harness(void);

/* ---- Cyclic and alarm handlers, service calls, memory regions ---- */
ER   cyc_register(const struct rtos_cyc_cfg *cfg, uint64_t unit_ns);
ER   alm_register(const struct rtos_alm_cfg *cfg);
bool cyc_exists(ID cycid);
bool alm_exists(ID almid);
ER   cyc_create_all(void);
void cyc_reset(void);
ER   svc_define(FN fncd, EXTSVC extsvc);
bool svc_defined(FN fncd);
void svc_reset(void);
void mem_reset(void);
ER   mem_add_region(const struct rtos_mem_cfg *mem);

/* ---- Trace, syslog, bugs ---- */
extern rtos_host_trace_sink trace_sink;
static inline bool trace_on(void)
{
	return trace_sink != NULL;
}
/* Traces a failing service call and returns its code. */
ER trace_svc_error(const char *svc, ER ercd);
static inline ER svc_result(const char *svc, ER ercd)
{
	return (ercd < 0 && trace_sink != NULL) ? trace_svc_error(svc, ercd) : ercd;
}
void bug_reset(void);
void syslog_reset(void);
/* Name of an error code ("E_CTX"), or "E_?". */
const char *ercd_name(ER ercd);

/* ---- Scheduler observer (rtos_host_set_sched_observer; trace.c) ---- */
extern const struct rtos_host_sched_observer *sched_observer;
/* The calls to the observer, out of line and cold (trace.c): without one the
 * dispatch and interrupt paths keep a test and a jump. */
void observer_task_state(const struct tcb *t);
void observer_running(const struct tcb *t);
void observer_handler(enum rtos_host_handler_kind kind, unsigned id, bool enter);
/* Tells the observer of t's state now. */
static inline void observe_task_state(const struct tcb *t)
{
	if (__builtin_expect(sched_observer != NULL, 0))
		observer_task_state(t);
}
/* Tells the observer which task runs now (NULL: idle). */
static inline void observe_running(const struct tcb *t)
{
	if (__builtin_expect(sched_observer != NULL, 0))
		observer_running(t);
}
/* Tells the observer a handler is entered or left. */
static inline void observe_handler(enum rtos_host_handler_kind kind, unsigned id, bool enter)
{
	if (__builtin_expect(sched_observer != NULL, 0))
		observer_handler(kind, id, enter);
}

/* ---- CPU cost of service calls (cost.c) and stall watch (stall.c) ---- */
extern struct rtos_host_cpu_cost cpu_cost;
/* The first step of every service call: its CPU time, charged to the calling
 * task (which may be preempted meanwhile).  Out of line in cost.c, so that
 * make bench's instruction counter sees one call of simulation code. */
void svc_charge(void);
/* The compiler's call at each basic block of an app's code (cost.c). */
void __sanitizer_cov_trace_pc(void);
/* cal_svc's charge: the extended service's cost, and no charge for the calls
 * it makes; returns the calling task (NULL in non-task context) for svc_ext_exit. */
struct tcb *svc_ext_enter(FN fncd);
void svc_ext_exit(struct tcb *caller);
/* True if a task consuming time at task level would find nothing to do before
 * the clock passes its end (which the caller checked is before quiet_until):
 * no interrupt to deliver, no task to switch to, the kernel not ended. */
static inline bool task_consume_quiet(void)
{
	return (irq_pending_lines == 0 || cpu.sil_lock != 0 || cpu.locked) && schedtsk == runtsk &&
	       !kernel_exited;
}
/* rtos_host_consume from a task at task level (the charges of service calls):
 * its quiet case inline, without the context checks the caller already made. */
static inline void task_consume(uint64_t ns)
{
	uint64_t end = now_ns + ns;

	/* (end < ns: the addition wrapped around) */
	if (end < quiet_until && end >= ns && task_consume_quiet()) {
		now_ns = end;
		event_time_settled();
		return;
	}
	rtos_host_consume(ns);
}
/* Starts the stall watch for a run of the harness (it ends with run_active). */
void stall_watch_start(void);
extern bool kernel_stalled;
/* The system ended on a task's stack overrun (until the next boot). */
extern bool kernel_stack_overrun;
/* A task's stack use passed its record: reports and ends the system if it
 * passes the configured size (crash.c). */
void stack_use_record(struct tcb *t, size_t used);
/* Samples the running task's stack use at frame (a service call's entry, at task level). */
static inline void stack_use_sample(struct tcb *t, const void *frame)
{
	size_t used = t->stack_entry - (uintptr_t)frame;

	if (used > t->stack_used && (uintptr_t)frame < t->stack_entry)
		stack_use_record(t, used);
}

/* ---- Context checks, TOPPERS shape ---- */
static inline bool ctx_is_task(void)
{
	return cpu.kind == EXEC_TASK;
}
/* Task context and CPU unlocked (CHECK_TSKCTX_UNL). */
static inline bool ctx_task_unlocked(void)
{
	return cpu.kind == EXEC_TASK && !cpu.locked;
}
/* Non-task context and CPU unlocked (CHECK_INTCTX_UNL). */
static inline bool ctx_nontask_unlocked(void)
{
	return cpu.kind != EXEC_TASK && !cpu.locked;
}
/* A task that may block: task context, CPU unlocked, dispatching enabled (CHECK_DISPATCH). */
static inline bool ctx_may_block(void)
{
	return cpu.kind == EXEC_TASK && !cpu.locked && !cpu.dsp_disabled;
}
/* HRP3's largest relative time, in us (ev3rt-git/ev3rt-hrp3, include/t_stddef.h:
 * TMAX_RELTIM 4000000000U, 66 min 40 s). */
#define HRP3_TMAX_RELTIM 4000000000U
/* HRP3's TMO_FEVR and TMO_NBLK as an HRP2 TMO holds them (UINT32_MAX, UINT32_MAX - 1). */
#define HRP3_TMO_FEVR ((uint32_t)UINT32_MAX)

/* True while the running task is inside an HRP3-profile call (times in us). */
static inline bool svc_in_us(void)
{
	return cpu.kind == EXEC_TASK && runtsk != NULL && runtsk->call_us;
}
/* Valid timeout value (CHECK_TMOUT): HRP2's TMO_FEVR or 0..TMAX_RELTIM ms, or inside
 * an HRP3-profile call HRP3's TMO_FEVR or 0..HRP3_TMAX_RELTIM us (TMO_NBLK: E_PAR,
 * ev3lx has no non-blocking calls). */
static inline bool tmout_valid(TMO tmout)
{
	if (svc_in_us())
		return (uint32_t)tmout == HRP3_TMO_FEVR || (uint32_t)tmout <= HRP3_TMAX_RELTIM;
	return tmout >= TMO_FEVR;
}

/* ---- The HRP3 profile's entry points (hrp3.c; kernel_hrp3.h binds an app's calls to them) ---- */
ER ev3lx_hrp3_tslp_tsk(TMO tmout);
ER ev3lx_hrp3_dly_tsk(RELTIM dlytim);
ER ev3lx_hrp3_twai_sem(ID semid, TMO tmout);
ER ev3lx_hrp3_twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout);
ER ev3lx_hrp3_tsnd_dtq(ID dtqid, intptr_t data, TMO tmout);
ER ev3lx_hrp3_trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout);
ER ev3lx_hrp3_tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout);
ER ev3lx_hrp3_trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout);
ER ev3lx_hrp3_tloc_mtx(ID mtxid, TMO tmout);
ER ev3lx_hrp3_ref_cyc(ID cycid, T_RCYC *pk_rcyc);
ER ev3lx_hrp3_ref_alm(ID almid, T_RALM *pk_ralm);
ER ev3lx_hrp3_sta_alm(ID almid, RELTIM almtim);
ER ev3lx_hrp3_get_tim(uint64_t *p_systim);
uint32_t ev3lx_hrp3_fch_hrt(void);
ER ev3lx_hrp3_act_tsk(ID tskid);
ER ev3lx_hrp3_wup_tsk(ID tskid);
ER ev3lx_hrp3_rel_wai(ID tskid);
ER ev3lx_hrp3_sig_sem(ID semid);
ER ev3lx_hrp3_set_flg(ID flgid, FLGPTN setptn);
ER ev3lx_hrp3_psnd_dtq(ID dtqid, intptr_t data);
ER ev3lx_hrp3_fsnd_dtq(ID dtqid, intptr_t data);
ER ev3lx_hrp3_psnd_pdq(ID pdqid, intptr_t data, PRI datapri);
ER ev3lx_hrp3_stp_alm(ID almid);
ER ev3lx_hrp3_rot_rdq(PRI tskpri);
ER ev3lx_hrp3_get_tid(ID *p_tskid);
ER ev3lx_hrp3_loc_cpu(void);
ER ev3lx_hrp3_unl_cpu(void);

#endif /* RTOS_HOST_KERNEL_IMPL_H */
