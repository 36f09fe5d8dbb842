/*
 * workqueue.c — the one FIFO of work the worker tasks serve (worker.c).
 *
 * Several workers serve it, as the kworkers of one CPU's pool in Linux: each
 * takes the oldest item it may run, so when one sleeps inside a work item
 * another runs the rest (a sleeping item on one workqueue does not stall the
 * others).  An item never runs on two workers at once, and an ordered
 * workqueue (alloc_ordered_workqueue, max_active 1) runs one item at a time.
 *
 * A work item's identity while queued or running is its queueing sequence
 * number, so flushes wait for exactly the instance that was there when they
 * started, and the worker never touches a work item after its function
 * returned (the function may free it).
 */
#include <linux/workqueue.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux/wait.h>
#include <linux_compat/config.h>
#include <linux_compat/context.h>
#include <linux_compat/report.h>
#include <linux_compat/sched.h>
#include <linux_compat/workqueue.h>
#include <sil.h>

static struct workqueue_struct default_wq = { .name = "events", .in_use = true };
struct workqueue_struct *system_wq = &default_wq;
struct workqueue_struct *system_highpri_wq = &default_wq;
struct workqueue_struct *system_long_wq = &default_wq;
struct workqueue_struct *system_unbound_wq = &default_wq;
struct workqueue_struct *system_freezable_wq = &default_wq;
struct workqueue_struct *system_power_efficient_wq = &default_wq;
struct workqueue_struct *system_freezable_power_efficient_wq = &default_wq;

static struct workqueue_struct wq_pool[LX_NR_WORKQUEUES];

/* How deep a worker may nest items (a flush inside a work runs others in place). */
#define LX_WORK_NESTING 8

/* What one worker runs: its stack of items, innermost last. */
struct worker_running {
	const struct work_struct *work[LX_WORK_NESTING];
	const struct workqueue_struct *q[LX_WORK_NESTING];
	u64 seq[LX_WORK_NESTING];
	unsigned int depth;
	bool idle;                   /* sleeping in its loop, waiting for work */
};

static struct {
	struct work_struct *head, *tail;
	u64 next_seq;                /* sequence numbers start at 1; 0 = none */
	struct worker_running workers[LX_NR_WORKERS];
} wq;

static DECLARE_WAIT_QUEUE_HEAD(flush_waiters);

/* Forgets queued work, the pool and the worker's state. */
void lx_workqueue_reset(void)
{
	memset(&wq, 0, sizeof(wq));
	wq.next_seq = 1;
	memset(wq_pool, 0, sizeof(wq_pool));
	lx_init_waitqueue_head(&flush_waiters, "flush_waiters");
	lx_worker_reset();
}

/* Initialises work. */
void lx_init_work(struct work_struct *work, work_func_t func)
{
	if (work->lx_magic == LX_WORK_MAGIC && work->lx_pending) {
		lx_report("INIT_WORK on a pending work", NULL, 0, "the work is cancelled first");
		(void)cancel_work(work);
	}
	work->func = func;
	work->lx_next = NULL;
	work->lx_wq = NULL;
	work->lx_seq = 0;
	work->lx_pending = 0;
	work->lx_magic = LX_WORK_MAGIC;
}

/* Queues the work of a delayed work whose delay ended (timer context). */
void lx_delayed_work_timer_fn(struct timer_list *t)
{
	struct delayed_work *dwork = from_timer(dwork, t, timer);

	(void)queue_work(dwork->wq != NULL ? dwork->wq : system_wq, &dwork->work);
}

/* Initialises delayed work. */
void lx_init_delayed_work(struct delayed_work *dwork, work_func_t func)
{
	lx_init_work(&dwork->work, func);
	timer_setup(&dwork->timer, lx_delayed_work_timer_fn, 0);
	dwork->wq = NULL;
}

/* Wakes one idle worker, the main one first (none if all are busy: each takes more work when it is done). */
static void wake_idle_worker(void)
{
	unsigned int i;

	for (i = 0; i < LX_NR_WORKERS; i++) {
		if (READ_ONCE(wq.workers[i].idle)) {
			WRITE_ONCE(wq.workers[i].idle, false);
			lx_wake_task(lx_worker_tskid(i));
			return;
		}
	}
}

/* Where work runs: WORK_RUNS_HERE (the calling worker's stack), WORK_RUNS_ELSEWHERE, or WORK_IDLE. */
enum work_place { WORK_IDLE, WORK_RUNS_HERE, WORK_RUNS_ELSEWHERE };

/* Where the item (or, for an ordered q, any of q's items) runs; interrupts locked or a snapshot. */
static enum work_place running_place(const struct work_struct *work, const struct workqueue_struct *q)
{
	int self = lx_worker_index();
	unsigned int i, d;

	for (i = 0; i < LX_NR_WORKERS; i++) {
		const struct worker_running *w = &wq.workers[i];

		for (d = 0; d < w->depth; d++) {
			if (w->work[d] == work || (q != NULL && w->q[d] == q))
				return (int)i == self ? WORK_RUNS_HERE : WORK_RUNS_ELSEWHERE;
		}
	}
	return WORK_IDLE;
}

/* The workqueue an item of q blocks while it runs: q itself if ordered, else none. */
static const struct workqueue_struct *ordering_of(const struct workqueue_struct *q)
{
	return q != NULL && q->ordered ? q : NULL;
}

/* Appends work to the FIFO; interrupts locked. */
static void enqueue_locked(struct workqueue_struct *q, struct work_struct *work)
{
	work->lx_next = NULL;
	work->lx_wq = q;
	work->lx_seq = wq.next_seq++;
	work->lx_pending = 1;
	if (wq.tail != NULL)
		wq.tail->lx_next = work;
	else
		wq.head = work;
	wq.tail = work;
}

/* Unlinks a pending work from the FIFO; interrupts locked. */
static void dequeue_locked(struct work_struct *work)
{
	struct work_struct *prev = NULL, *cur;

	for (cur = wq.head; cur != NULL; prev = cur, cur = cur->lx_next) {
		if (cur != work)
			continue;
		if (prev != NULL)
			prev->lx_next = cur->lx_next;
		else
			wq.head = cur->lx_next;
		if (wq.tail == cur)
			wq.tail = prev;
		break;
	}
	work->lx_next = NULL;
	work->lx_pending = 0;
}

/* Checks a work before queueing; reports and returns false if unusable. */
static bool queueable(struct work_struct *work, const char *what)
{
	if (work == NULL) {
		lx_report(what, NULL, 0, "NULL work");
		return false;
	}
	if (work->lx_magic != LX_WORK_MAGIC || work->func == NULL) {
		lx_report(what, NULL, 0, "the work was not initialised (INIT_WORK) or has no function");
		return false;
	}
	return true;
}

/* Queues work; false if already pending. */
bool queue_work(struct workqueue_struct *q, struct work_struct *work)
{
	bool queued = false;
	SIL_PRE_LOC;

	if (!queueable(work, "queue_work"))
		return false;
	SIL_LOC_INT();
	if (!work->lx_pending) {
		enqueue_locked(q != NULL ? q : system_wq, work);
		queued = true;
	}
	SIL_UNL_INT();
	if (queued)
		wake_idle_worker();
	return queued;
}

/* Queues dwork after delay jiffies; false if already pending. */
bool queue_delayed_work(struct workqueue_struct *q, struct delayed_work *dwork, unsigned long delay)
{
	if (dwork == NULL || !queueable(&dwork->work, "queue_delayed_work"))
		return false;
	if (delayed_work_pending(dwork))
		return false;
	dwork->wq = q;
	if (delay == 0)
		return queue_work(q, &dwork->work);
	(void)mod_timer(&dwork->timer, jiffies + delay);
	return true;
}

/* Re-arms dwork after delay; true if it was pending. */
bool mod_delayed_work(struct workqueue_struct *q, struct delayed_work *dwork, unsigned long delay)
{
	bool was_pending = cancel_delayed_work(dwork);

	(void)queue_delayed_work(q, dwork, delay);
	return was_pending;
}

/* Dequeues work; true if it was pending. */
bool cancel_work(struct work_struct *work)
{
	bool was_pending;
	SIL_PRE_LOC;

	if (work == NULL || work->lx_magic != LX_WORK_MAGIC)
		return false;
	SIL_LOC_INT();
	was_pending = work->lx_pending;
	if (was_pending)
		dequeue_locked(work);
	SIL_UNL_INT();
	if (was_pending)
		wake_up_all(&flush_waiters);
	return was_pending;
}

/*
 * Runs the oldest queued work the calling worker may run (not running on any
 * worker, and its ordered workqueue idle); false if there is none.  Nests (a
 * flush inside a work runs others in place): the worker's running stack.
 */
bool lx_workqueue_run_one(void)
{
	struct work_struct *work, *prev = NULL;
	struct worker_running *self;
	int index = lx_worker_index();
	work_func_t func;
	bool more;
	SIL_PRE_LOC;

	if (index < 0)
		return false;
	self = &wq.workers[index];
	SIL_LOC_INT();
	for (work = wq.head; work != NULL; prev = work, work = work->lx_next) {
		if (running_place(work, ordering_of(work->lx_wq)) == WORK_IDLE)
			break;
	}
	if (work == NULL || self->depth == LX_WORK_NESTING) {
		SIL_UNL_INT();
		return false;
	}
	if (prev != NULL)
		prev->lx_next = work->lx_next;
	else
		wq.head = work->lx_next;
	if (wq.tail == work)
		wq.tail = prev;
	work->lx_next = NULL;
	work->lx_pending = 0;
	self->work[self->depth] = work;
	self->q[self->depth] = ordering_of(work->lx_wq);
	self->seq[self->depth] = work->lx_seq;
	self->depth++;
	func = work->func;
	more = wq.head != NULL;
	SIL_UNL_INT();

	if (more)
		wake_idle_worker();      /* the rest must not wait if this one sleeps */
	func(work);    /* work may be freed or re-queued from here on */

	SIL_LOC_INT();
	self->depth--;
	SIL_UNL_INT();
	wake_up_all(&flush_waiters);
	return true;
}

/*
 * Marks the calling worker idle (about to sleep in its loop, so queue_work
 * wakes it) or busy again; marking it idle fails (false) if an item it may
 * run was queued meanwhile.
 */
bool lx_workqueue_set_idle(bool idle)
{
	int index = lx_worker_index();
	const struct work_struct *work;
	SIL_PRE_LOC;

	if (index < 0)
		return false;
	SIL_LOC_INT();
	for (work = wq.head; idle && work != NULL; work = work->lx_next) {
		if (running_place(work, ordering_of(work->lx_wq)) == WORK_IDLE)
			idle = false;
	}
	wq.workers[index].idle = idle;
	SIL_UNL_INT();
	return idle;
}

/* True if an instance with sequence seq runs on a worker; *here set if on the calling one. */
static bool seq_running(u64 seq, bool *here)
{
	int self = lx_worker_index();
	unsigned int i, d;

	for (i = 0; i < LX_NR_WORKERS; i++) {
		for (d = 0; d < READ_ONCE(wq.workers[i].depth); d++) {
			if (READ_ONCE(wq.workers[i].seq[d]) == seq) {
				*here = (int)i == self;
				return true;
			}
		}
	}
	*here = false;
	return false;
}

/* True while the instance seq of work is queued or running. */
static bool instance_alive(const struct work_struct *work, u64 seq)
{
	bool here;

	return (READ_ONCE(work->lx_pending) && READ_ONCE(work->lx_seq) == seq) || seq_running(seq, &here);
}

/* The sequence of work's running instance on any worker, or 0; interrupts locked. */
static u64 running_seq_of(const struct work_struct *work)
{
	unsigned int i, d;

	for (i = 0; i < LX_NR_WORKERS; i++) {
		for (d = 0; d < wq.workers[i].depth; d++) {
			if (wq.workers[i].work[d] == work)
				return wq.workers[i].seq[d];
		}
	}
	return 0;
}

/*
 * Waits until instance seq of work is gone (the caller checked it may
 * sleep); false (reported) if that would deadlock.  A worker runs queued
 * items in place while it waits, so it never waits for work only it could run.
 */
static bool wait_instance(const struct work_struct *work, u64 seq, const char *what,
			  const char *file, int line)
{
	bool here;

	if (!lx_in_worker()) {
		wait_event(flush_waiters, !instance_alive(work, seq));
		return true;
	}
	while (instance_alive(work, seq)) {
		if ((seq_running(seq, &here) && here) ||
		    (READ_ONCE(work->lx_pending) && running_place(NULL, ordering_of(work->lx_wq)) == WORK_RUNS_HERE)) {
			lx_report("workqueue deadlock", file, line,
				  "%s from the worker while that very work (or its ordered workqueue) runs", what);
			return false;
		}
		if (!lx_workqueue_run_one())
			wait_event(flush_waiters, !instance_alive(work, seq));
	}
	return true;
}

/* Sleeps until the instance of work queued or running now has finished. */
bool lx_flush_work_at(struct work_struct *work, const char *file, int line)
{
	u64 seq;
	SIL_PRE_LOC;

	/* Checked whether or not it would wait, as Linux's might_sleep(). */
	bool may_sleep = lx_might_sleep_check("flush_work()", file, line);

	if (work == NULL || work->lx_magic != LX_WORK_MAGIC)
		return false;
	SIL_LOC_INT();
	seq = work->lx_pending ? work->lx_seq : running_seq_of(work);
	SIL_UNL_INT();
	if (seq == 0)
		return false;
	if (may_sleep)
		(void)wait_instance(work, seq, "flush_work()", file, line);
	return true;
}

/* Dequeues work and waits for a running instance. */
bool lx_cancel_work_sync_at(struct work_struct *work, const char *file, int line)
{
	bool was_pending;
	u64 seq;
	SIL_PRE_LOC;

	bool may_sleep = lx_might_sleep_check("cancel_work_sync()", file, line);

	if (work == NULL || work->lx_magic != LX_WORK_MAGIC)
		return false;
	was_pending = cancel_work(work);
	SIL_LOC_INT();
	seq = running_seq_of(work);
	SIL_UNL_INT();
	if (seq != 0 && may_sleep)
		(void)wait_instance(work, seq, "cancel_work_sync()", file, line);
	return was_pending;
}

/* Stops the delay or dequeues. */
bool cancel_delayed_work(struct delayed_work *dwork)
{
	bool timer_was = del_timer(&dwork->timer) != 0;
	bool work_was = cancel_work(&dwork->work);

	return timer_was || work_was;
}

/* cancel_delayed_work and wait for a running instance. */
bool lx_cancel_delayed_work_sync_at(struct delayed_work *dwork, const char *file, int line)
{
	bool timer_was, work_was;

	if (!lx_might_sleep_check("cancel_delayed_work_sync()", file, line)) {
		/* Reported once: the parts below would repeat the report. */
		return cancel_delayed_work(dwork);
	}
	timer_was = lx_del_timer_sync_at(&dwork->timer, file, line) != 0;
	work_was = lx_cancel_work_sync_at(&dwork->work, file, line);

	return timer_was || work_was;
}

/* Ends the delay now and waits for the work. */
bool lx_flush_delayed_work_at(struct delayed_work *dwork, const char *file, int line)
{
	if (del_timer(&dwork->timer))
		(void)queue_work(dwork->wq != NULL ? dwork->wq : system_wq, &dwork->work);
	return lx_flush_work_at(&dwork->work, file, line);
}

/* True while an item queued at or before seq_limit is queued or running; *here if one runs on the caller. */
static bool older_work_alive(u64 seq_limit, bool *here)
{
	const struct work_struct *head = READ_ONCE(wq.head);
	int self = lx_worker_index();
	unsigned int i, d;
	bool alive = head != NULL && head->lx_seq <= seq_limit;

	*here = false;
	for (i = 0; i < LX_NR_WORKERS; i++) {
		for (d = 0; d < READ_ONCE(wq.workers[i].depth); d++) {
			if (READ_ONCE(wq.workers[i].seq[d]) <= seq_limit) {
				alive = true;
				*here = *here || (int)i == self;
			}
		}
	}
	return alive;
}

/* Sleeps until all work queued before the call has run. */
void lx_flush_workqueue_at(struct workqueue_struct *q, const char *file, int line)
{
	u64 limit;
	bool here;
	SIL_PRE_LOC;

	(void)q;
	if (!lx_might_sleep_check("flush_workqueue()", file, line))
		return;
	SIL_LOC_INT();
	limit = wq.next_seq - 1;
	SIL_UNL_INT();
	if (!lx_in_worker()) {
		wait_event(flush_waiters, !older_work_alive(limit, &here));
		return;
	}
	while (older_work_alive(limit, &here)) {
		if (here) {
			lx_report("workqueue deadlock", file, line,
				  "flush_workqueue from the work item it would wait for");
			return;
		}
		if (!lx_workqueue_run_one())
			wait_event(flush_waiters, !older_work_alive(limit, &here));
	}
}

bool (flush_work)(struct work_struct *work)
{
	return lx_flush_work_at(work, NULL, 0);
}

bool (cancel_work_sync)(struct work_struct *work)
{
	return lx_cancel_work_sync_at(work, NULL, 0);
}

bool (cancel_delayed_work_sync)(struct delayed_work *dwork)
{
	return lx_cancel_delayed_work_sync_at(dwork, NULL, 0);
}

bool (flush_delayed_work)(struct delayed_work *dwork)
{
	return lx_flush_delayed_work_at(dwork, NULL, 0);
}

void (flush_workqueue)(struct workqueue_struct *q)
{
	lx_flush_workqueue_at(q, NULL, 0);
}

/* A pool workqueue named from fmt, or NULL. */
struct workqueue_struct *alloc_workqueue(const char *fmt, unsigned int flags, int max_active, ...)
{
	struct workqueue_struct *q = NULL;
	unsigned int i;
	va_list args;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	for (i = 0; i < LX_NR_WORKQUEUES; i++) {
		if (!wq_pool[i].in_use) {
			q = &wq_pool[i];
			q->in_use = true;
			break;
		}
	}
	SIL_UNL_INT();
	if (q == NULL) {
		pr_err("alloc_workqueue: all %d workqueues are in use\n", LX_NR_WORKQUEUES);
		return NULL;
	}
	q->flags = flags;
	q->ordered = (flags & __WQ_ORDERED) != 0 || max_active == 1;
	va_start(args, max_active);
	vscnprintf(q->name, sizeof(q->name), fmt, args);
	va_end(args);
	return q;
}

/* Drains wq and returns it to the pool. */
void destroy_workqueue(struct workqueue_struct *q)
{
	if (q == NULL)
		return;
	flush_workqueue(q);
	if (q >= wq_pool && q < wq_pool + LX_NR_WORKQUEUES)
		q->in_use = false;
}
