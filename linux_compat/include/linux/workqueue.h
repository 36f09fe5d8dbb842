/*
 * linux/workqueue.h — deferred work in a real kernel task.
 *
 * Worker tasks (linux_compat/config.h: LX_WORKER_TSKID and the
 * LX_NR_POOL_WORKERS pool workers, at LX_WORKER_PRIORITY) serve every
 * workqueue from one FIFO as the kworkers of a CPU's pool: work runs in task
 * context, started in queueing order, and when a work item sleeps another
 * worker runs the next, as Linux's concurrency-managed workqueues do on one
 * CPU.  An item never runs on two workers at once; an ordered workqueue
 * (alloc_ordered_workqueue, create_singlethread_workqueue, max_active 1)
 * runs one item at a time.  Queueing is legal from any context.  The flush and cancel-sync calls
 * sleep until the work is done; called from the worker itself (a work item,
 * or a module_init, which the worker runs at boot) they run the queued
 * items in place instead, and waiting for the very item that is running is
 * reported as the deadlock it would be in Linux.  flush_workqueue waits for
 * everything queued before it on any workqueue.  Workqueues from
 * alloc_workqueue come from a static pool of LX_NR_WORKQUEUES.
 */
#ifndef _LINUX_WORKQUEUE_H
#define _LINUX_WORKQUEUE_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/timer.h>

struct work_struct;
typedef void (*work_func_t)(struct work_struct *work);

struct work_struct {
	work_func_t func;
	/* Private to linux_compat. */
	struct work_struct *lx_next;
	struct workqueue_struct *lx_wq;
	u64 lx_seq;                 /* queueing sequence of the pending instance */
	u32 lx_magic;
	u8 lx_pending;
};

struct delayed_work {
	struct work_struct work;
	struct timer_list timer;
	struct workqueue_struct *wq;
};

#define LX_WORK_MAGIC		0x776f726bU    /* "work" */
#define LX_NR_WORKQUEUES	8
#define LX_WQ_NAME_LEN		24

struct workqueue_struct {
	char name[LX_WQ_NAME_LEN];
	unsigned int flags;
	bool in_use;
	bool ordered;               /* one item at a time (max_active 1 or __WQ_ORDERED) */
};

enum {
	WQ_UNBOUND		= 1 << 1,
	WQ_FREEZABLE		= 1 << 2,
	WQ_MEM_RECLAIM		= 1 << 3,
	WQ_HIGHPRI		= 1 << 4,
	WQ_CPU_INTENSIVE	= 1 << 5,
	WQ_SYSFS		= 1 << 6,
	WQ_POWER_EFFICIENT	= 1 << 7,
	__WQ_ORDERED		= 1 << 17,
	WQ_MAX_ACTIVE		= 512,
};

extern struct workqueue_struct *system_wq;
extern struct workqueue_struct *system_highpri_wq;
extern struct workqueue_struct *system_long_wq;
extern struct workqueue_struct *system_unbound_wq;
extern struct workqueue_struct *system_freezable_wq;
extern struct workqueue_struct *system_power_efficient_wq;
extern struct workqueue_struct *system_freezable_power_efficient_wq;

/* Initialises work to run func (reports re-initialising a pending work). */
void lx_init_work(struct work_struct *work, work_func_t func);
/* The timer callback of delayed work: queues the work. */
void lx_delayed_work_timer_fn(struct timer_list *t);
/* Initialises delayed work. */
void lx_init_delayed_work(struct delayed_work *dwork, work_func_t func);

#define INIT_WORK(_work, _func)			lx_init_work((_work), (_func))
#define INIT_WORK_ONSTACK(_work, _func)		lx_init_work((_work), (_func))
#define INIT_DELAYED_WORK(_work, _func)		lx_init_delayed_work((_work), (_func))
#define INIT_DEFERRABLE_WORK(_work, _func)	lx_init_delayed_work((_work), (_func))
#define __WORK_INITIALIZER(n, f)		{ .func = (f), .lx_magic = LX_WORK_MAGIC }
#define DECLARE_WORK(n, f)			struct work_struct n = __WORK_INITIALIZER(n, f)
#define DECLARE_DELAYED_WORK(n, f)					\
	struct delayed_work n = {					\
		.work = __WORK_INITIALIZER((n).work, (f)),		\
		.timer = { .function = lx_delayed_work_timer_fn,	\
			   .lx_magic = LX_TIMER_MAGIC } }
#define destroy_work_on_stack(work)		do { (void)(work); } while (0)
#define destroy_delayed_work_on_stack(work)	do { (void)(work); } while (0)

/* True while work is queued (not yet started). */
static inline bool work_pending(const struct work_struct *work)	{ return READ_ONCE(work->lx_pending); }
/* The delayed work embedding work. */
static inline struct delayed_work *to_delayed_work(struct work_struct *work)
{
	return container_of(work, struct delayed_work, work);
}
/* True while the delay runs or the work is queued. */
static inline bool delayed_work_pending(const struct delayed_work *dwork)
{
	return timer_pending(&dwork->timer) || work_pending(&dwork->work);
}

/* Queues work on wq; false if it was already pending.  Any context. */
bool queue_work(struct workqueue_struct *wq, struct work_struct *work);
#define queue_work_on(cpu, wq, work)	queue_work((wq), (work))
/* Queues dwork after delay jiffies (at once for 0); false if already pending.  Any context. */
bool queue_delayed_work(struct workqueue_struct *wq, struct delayed_work *dwork, unsigned long delay);
#define queue_delayed_work_on(cpu, wq, dwork, delay) queue_delayed_work((wq), (dwork), (delay))
/* Re-arms dwork to run after delay, pending or not; true if it was pending. */
bool mod_delayed_work(struct workqueue_struct *wq, struct delayed_work *dwork, unsigned long delay);
/* Sleeps until the last queued instance of work has run; true if there was one. */
bool flush_work(struct work_struct *work);
/* Dequeues work without waiting; true if it was pending.  Any context. */
bool cancel_work(struct work_struct *work);
/* Dequeues work and waits for a running instance; true if it was pending. */
bool cancel_work_sync(struct work_struct *work);
/* Stops the delay or dequeues; true if it was pending.  Any context. */
bool cancel_delayed_work(struct delayed_work *dwork);
/* cancel_delayed_work, then waits for a running instance. */
bool cancel_delayed_work_sync(struct delayed_work *dwork);
/* Ends the delay now and waits until the work has run; true if it was pending. */
bool flush_delayed_work(struct delayed_work *dwork);
/* Sleeps until everything queued before the call (on any workqueue) has run. */
void flush_workqueue(struct workqueue_struct *wq);
#define drain_workqueue(wq)	flush_workqueue(wq)

/* Call-site forms: deadlock and context reports name the caller's file and line. */
bool lx_flush_work_at(struct work_struct *work, const char *file, int line);
bool lx_cancel_work_sync_at(struct work_struct *work, const char *file, int line);
bool lx_cancel_delayed_work_sync_at(struct delayed_work *dwork, const char *file, int line);
bool lx_flush_delayed_work_at(struct delayed_work *dwork, const char *file, int line);
void lx_flush_workqueue_at(struct workqueue_struct *wq, const char *file, int line);
#define flush_work(w)			lx_flush_work_at((w), __FILE__, __LINE__)
#define cancel_work_sync(w)		lx_cancel_work_sync_at((w), __FILE__, __LINE__)
#define cancel_delayed_work_sync(dw)	lx_cancel_delayed_work_sync_at((dw), __FILE__, __LINE__)
#define flush_delayed_work(dw)		lx_flush_delayed_work_at((dw), __FILE__, __LINE__)
#define flush_workqueue(wq)		lx_flush_workqueue_at((wq), __FILE__, __LINE__)

/* A workqueue from the pool (name formatted like printf), or NULL if the pool is used up. */
__printf(1, 4) struct workqueue_struct *alloc_workqueue(const char *fmt, unsigned int flags,
							int max_active, ...);
#define alloc_ordered_workqueue(fmt, flags, args...) \
	alloc_workqueue(fmt, WQ_UNBOUND | __WQ_ORDERED | (flags), 1, ##args)
#define create_workqueue(name)			alloc_workqueue("%s", WQ_MEM_RECLAIM, 1, (name))
#define create_freezable_workqueue(name)	alloc_workqueue("%s", WQ_FREEZABLE | WQ_MEM_RECLAIM, 1, (name))
#define create_singlethread_workqueue(name)	alloc_ordered_workqueue("%s", WQ_MEM_RECLAIM, (name))
/* Waits for its work, then returns wq to the pool. */
void destroy_workqueue(struct workqueue_struct *wq);

static inline bool schedule_work(struct work_struct *work)	{ return queue_work(system_wq, work); }
static inline bool schedule_delayed_work(struct delayed_work *dwork, unsigned long delay)
{
	return queue_delayed_work(system_wq, dwork, delay);
}
static inline void flush_scheduled_work(void)			{ flush_workqueue(system_wq); }

#endif /* _LINUX_WORKQUEUE_H */
