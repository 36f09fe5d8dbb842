/*
 * event.c — the event queue of the virtual clock, ordered by (time, sequence),
 * so events at the same time run in scheduling order.  Device events,
 * interrupt-line changes and the kernel's tick (a timer beside the queue, see
 * below) are events; virtual time jumps from one to the next.
 *
 * Most events are due soon (an SPI frame's end, a motor edge, a UART byte):
 * they go into the front, a small array sorted latest-first, where inserting
 * one that is due before most others moves few slots and taking the earliest
 * is taking the last.  Everything due later than the front's latest is in a
 * binary heap behind it (the front's latest moves there when the front is
 * full), so a long queue stays O(log n).  A cancelled event's slot stays where
 * it is and is skipped when it reaches the head (its generation no longer
 * matches); when such slots outnumber the live ones they are swept out.
 * The earliest live time is kept in event_head_time for the run loop.
 *
 * The kernel's tick, due every tick period when ISRs are attached to it, is
 * not queued: it is one timer slot beside the queue with a time and a
 * sequence taken as a queued event's would be, and the head is whichever of
 * the two comes first in the same (time, sequence) order, so it runs exactly
 * where its queued event would have run without an insertion and a release
 * per tick.  Its expiry only latches the tick interrupt, so it needs no
 * event context, and a periodic timer re-arms itself in place.
 *
 * A deferred event (rtos_host.h) holds a sequence number like a queued one
 * but no slot; it is due once the run has moved past its place in the order:
 * a later time, or its time with an event of a higher sequence run, or its
 * time settled (run.c calls event_time_settled once every event due by now
 * has run).
 */
#include <stdlib.h>
#include <string.h>

#include "kernel_impl.h"

#define EV_NONE      UINT32_MAX
#define EV_FRONT_CAP 32U
#define EV_SWEEP_MIN 64U     /* stale slots tolerated before a sweep is considered */

/* A queued event's key and identity; stale once the event's generation moved on. */
struct ev_slot {
	uint64_t time;
	uint64_t seq;
	uint32_t idx;        /* the event in ev_pool */
	uint32_t gen;        /* its generation when queued */
};

struct event {
	rtos_host_event_fn fn;   /* NULL while the event is free (not queued) */
	void    *arg;
	uint32_t gen;        /* bumped on every release: stale handles and slots are harmless */
	uint32_t next_free;
};

static struct event *ev_pool;
static uint32_t ev_cap;
static uint32_t ev_free = EV_NONE;
/* The front, latest first (the earliest is last), after a sentinel slot due
 * at UINT64_MAX, where an insertion's walk stops without a bound check. */
static struct ev_slot ev_front_slots[1U + EV_FRONT_CAP] = { { UINT64_MAX, 0, 0, 0 } };
static struct ev_slot *const ev_front = &ev_front_slots[1];
static uint32_t ev_front_len;
static struct ev_slot *ev_heap;                  /* all later than every front slot */
static uint32_t ev_heap_len;
static uint32_t ev_heap_cap;
static uint64_t ev_heap_first = UINT64_MAX;      /* the heap's earliest time, UINT64_MAX if empty */
static uint32_t ev_stale;                        /* slots of cancelled events still queued */
static uint32_t ev_live;                         /* queued events: all device work (the tick is the timer) */
static uint64_t ev_seq;
uint64_t event_head_time = UINT64_MAX;
uint64_t quiet_until;
static uint64_t ev_run_bound;                    /* the active run's deadline; UINT64_MAX booted, 0 not */
/* Where the run is in the queue order: the last event taken, or its time settled (sequence UINT64_MAX). */
static uint64_t ev_pos_time;
uint64_t ev_pos_seq = UINT64_MAX;
static struct rtos_host_deferred *ev_deferred;   /* the armed deferred events */
static struct ev_slot ev_timer = { UINT64_MAX, 0, 0, 0 };   /* the kernel timer: time UINT64_MAX when off */
static uint64_t ev_timer_period;                 /* its re-arming interval, 0 for a single expiry */

/* Sets the earliest event's time, and quiet_until with it. */
static inline void ev_head_set(uint64_t t_ns)
{
	event_head_time = t_ns;
	quiet_until = t_ns < ev_run_bound ? t_ns : ev_run_bound;
}

/* An event or the timer is now due at t_ns: the head and quiet_until move no later. */
static inline void ev_head_lower(uint64_t t_ns)
{
	if (t_ns < event_head_time)
		event_head_time = t_ns;
	if (t_ns < quiet_until)
		quiet_until = t_ns;
}

/* Queue order: earlier time first, then scheduling order. */
static inline bool ev_before(const struct ev_slot *a, const struct ev_slot *b)
{
	return a->time < b->time || (a->time == b->time && a->seq < b->seq);
}

/* True if the slot's event was cancelled (the event may be in use again). */
static inline bool ev_slot_stale(const struct ev_slot *s)
{
	return ev_pool[s->idx].gen != s->gen;
}

/* Puts slot s at or above the hole at heap position pos. */
static void ev_sift_up(uint32_t pos, struct ev_slot s)
{
	while (pos > 0) {
		uint32_t parent = (pos - 1) / 2;

		if (!ev_before(&s, &ev_heap[parent]))
			break;
		ev_heap[pos] = ev_heap[parent];
		pos = parent;
	}
	ev_heap[pos] = s;
}

/* Keeps ev_heap_first after the heap's root changed. */
static inline void ev_heap_root_changed(void)
{
	ev_heap_first = ev_heap_len > 0 ? ev_heap[0].time : UINT64_MAX;
}

/* Adds slot s to the heap; false on ENOMEM. */
static bool ev_heap_push(struct ev_slot s)
{
	if (ev_heap_len == ev_heap_cap) {
		uint32_t ncap = ev_heap_cap ? ev_heap_cap * 2 : 256;
		struct ev_slot *nheap = realloc(ev_heap, ncap * sizeof(*nheap));

		if (nheap == NULL)
			return false;
		ev_heap = nheap;
		ev_heap_cap = ncap;
	}
	ev_sift_up(ev_heap_len++, s);
	ev_heap_root_changed();
	return true;
}

/* Removes the heap's earliest slot: the hole at the root goes down along the
 * earlier children to a leaf, where the last slot (usually a late one) refills it. */
static void ev_heap_pop(void)
{
	struct ev_slot last = ev_heap[--ev_heap_len];
	uint32_t pos = 0;

	if (ev_heap_len == 0) {
		ev_heap_root_changed();
		return;
	}
	for (;;) {
		uint32_t child = 2 * pos + 1;

		if (child >= ev_heap_len)
			break;
		if (child + 1 < ev_heap_len && ev_before(&ev_heap[child + 1], &ev_heap[child]))
			child++;
		ev_heap[pos] = ev_heap[child];
		pos = child;
	}
	ev_sift_up(pos, last);
	ev_heap_root_changed();
}

/* Inserts slot s into the front (which has room), keeping it latest-first:
 * the slots ordered before s move up. */
static void ev_front_insert(struct ev_slot s)
{
	uint32_t pos = ev_front_len;

	while (pos > 0 && ev_before(&ev_front[pos - 1], &s)) {
		ev_front[pos] = ev_front[pos - 1];
		pos--;
	}
	ev_front[pos] = s;
	ev_front_len++;
}

/* Removes the front's cancelled slots, keeping its order. */
static void ev_front_sweep(void)
{
	uint32_t n = 0;

	for (uint32_t i = 0; i < ev_front_len; i++)
		if (!ev_slot_stale(&ev_front[i]))
			ev_front[n++] = ev_front[i];
	ev_stale -= ev_front_len - n;
	ev_front_len = n;
}

/* Queues slot s (a new one, or a deferred event's with its earlier sequence); false on ENOMEM. */
static __attribute__((noinline)) bool ev_queue(struct ev_slot s)
{
	if (ev_front_len == EV_FRONT_CAP)
		ev_front_sweep();
	if (ev_front_len == EV_FRONT_CAP) {
		/* The front's latest precedes the whole heap: it becomes the heap's root. */
		if (!ev_heap_push(ev_front[0]))
			return false;
		memmove(&ev_front[0], &ev_front[1], (EV_FRONT_CAP - 1U) * sizeof(ev_front[0]));
		ev_front_len--;
	}
	if (ev_heap_len > 0 && !ev_before(&s, &ev_heap[0]))
		return ev_heap_push(s);
	ev_front_insert(s);
	return true;
}

/* The queue's head slot (live: ev_settle leaves one there), NULL if the queue is empty. */
static inline const struct ev_slot *ev_queue_head(void)
{
	if (ev_front_len > 0)
		return &ev_front[ev_front_len - 1];
	return ev_heap_len > 0 ? &ev_heap[0] : NULL;
}

/* Drops cancelled slots at the queue's head; returns the head (NULL if the queue is empty). */
static inline const struct ev_slot *ev_settle_queue(void)
{
	for (;;) {
		if (ev_front_len > 0) {
			const struct ev_slot *s = &ev_front[ev_front_len - 1];

			if (!ev_slot_stale(s))
				return s;
			ev_front_len--;
		} else if (ev_heap_len > 0) {
			if (!ev_slot_stale(&ev_heap[0]))
				return &ev_heap[0];
			ev_heap_pop();
		} else {
			return NULL;
		}
		ev_stale--;
	}
}

/* Drops cancelled slots at the head and sets event_head_time to the earliest live event's or the timer's. */
static inline void ev_settle(void)
{
	const struct ev_slot *s = ev_settle_queue();
	uint64_t t = s != NULL ? s->time : UINT64_MAX;

	ev_head_set(t < ev_timer.time ? t : ev_timer.time);
}

/* Removes every cancelled slot (their count outgrew the live ones): the
 * front keeps its order, the heap is rebuilt. */
static void ev_sweep(void)
{
	uint32_t n = 0;

	ev_front_sweep();
	for (uint32_t i = 0; i < ev_heap_len; i++)
		if (!ev_slot_stale(&ev_heap[i]))
			ev_heap[n++] = ev_heap[i];
	ev_heap_len = 0;
	for (uint32_t i = 0; i < n; i++)
		ev_sift_up(ev_heap_len++, ev_heap[i]);
	ev_heap_root_changed();
	ev_stale = 0;
}

/* Returns an event to the free list; its handle and slot become stale. */
static inline void ev_release(uint32_t idx)
{
	struct event *ev = &ev_pool[idx];

	ev_live--;
	ev->fn = NULL;
	ev->gen++;
	ev->next_free = ev_free;
	ev_free = idx;
}

/* Doubles the event pool; false on ENOMEM. */
static bool ev_grow(void)
{
	uint32_t ncap = ev_cap ? ev_cap * 2 : 256;
	struct event *npool = realloc(ev_pool, ncap * sizeof(*npool));

	if (npool == NULL)
		return false;
	ev_pool = npool;
	for (uint32_t i = ncap; i-- > ev_cap;) {
		memset(&ev_pool[i], 0, sizeof(ev_pool[i]));
		ev_pool[i].next_free = ev_free;
		ev_free = i;
	}
	ev_cap = ncap;
	return true;
}

/* rtos_host_event_at's checks: false after a bug report for no function or no
 * memory; a time in the past is reported and moved to now. */
static __attribute__((noinline)) bool ev_schedule_check(uint64_t *t_ns, rtos_host_event_fn fn)
{
	if (fn == NULL) {
		rtos_host_bug("event", "rtos_host_event_at with a NULL function");
		return false;
	}
	if (*t_ns < now_ns) {
		rtos_host_bug("event", "event scheduled in the past (t=%llu ns < now); runs now",
			      (unsigned long long)*t_ns);
		*t_ns = now_ns;
	}
	if (ev_free == EV_NONE && !ev_grow()) {
		rtos_host_bug("event", "out of memory for events");
		return false;
	}
	return true;
}

/* Takes event idx off the free list (its slot is queued) as fn(arg) due at t_ns. */
static inline __attribute__((always_inline)) void ev_claim(uint32_t idx, uint64_t t_ns, rtos_host_event_fn fn,
							   void *arg)
{
	struct event *ev = &ev_pool[idx];

	ev_free = ev->next_free;
	ev->fn = fn;
	ev->arg = arg;
	ev_live++;
	ev_head_lower(t_ns);
}

/* The handle of queued event idx: its generation and index, never 0. */
static inline rtos_host_event_t ev_handle(uint32_t idx)
{
	return ((rtos_host_event_t)ev_pool[idx].gen << 32) | (idx + 1U);
}

/* Queues the first free event (there is one) as fn(arg) at t_ns with sequence
 * seq and claims it; its handle, or 0 after a bug report for no memory. */
static rtos_host_event_t ev_queue_free(uint64_t t_ns, uint64_t seq, rtos_host_event_fn fn, void *arg)
{
	uint32_t idx = ev_free;

	if (!ev_queue((struct ev_slot){ t_ns, seq, idx, ev_pool[idx].gen })) {
		rtos_host_bug("event", "out of memory for events");
		return 0;
	}
	ev_claim(idx, t_ns, fn, arg);
	return ev_handle(idx);
}

/* rtos_host_event_at's other cases: a bad request, no free event, a full front or
 * a time at or after the heap's earliest. */
static __attribute__((noinline)) rtos_host_event_t ev_schedule_slow(uint64_t t_ns, rtos_host_event_fn fn,
								     void *arg)
{
	rtos_host_event_t handle;

	if ((fn == NULL || t_ns < now_ns || ev_free == EV_NONE) && !ev_schedule_check(&t_ns, fn))
		return 0;
	handle = ev_queue_free(t_ns, ev_seq, fn, arg);
	if (handle != 0)
		ev_seq++;
	return handle;
}

/* Schedules fn(arg) at absolute virtual time t_ns; same-time events run in order. */
rtos_host_event_t rtos_host_event_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg)
{
	uint32_t idx;
	struct ev_slot *pos;

	if (fn == NULL || t_ns < now_ns || ev_free == EV_NONE || ev_front_len == EV_FRONT_CAP ||
	    t_ns >= ev_heap_first)
		return ev_schedule_slow(t_ns, fn, arg);
	/* the common case, without calls: into the front, moving up the slots due
	 * no later (t_ns < UINT64_MAX: the sentinel stops the walk) */
	idx = ev_free;
	pos = &ev_front[ev_front_len++];
	while (pos[-1].time <= t_ns) {
		pos[0] = pos[-1];
		pos--;
	}
	*pos = (struct ev_slot){ t_ns, ev_seq, idx, ev_pool[idx].gen };
	ev_seq++;
	ev_claim(idx, t_ns, fn, arg);
	return ev_handle(idx);
}

/* Cancels a scheduled event; fired, cancelled or unknown handles are ignored. */
void rtos_host_event_cancel(rtos_host_event_t handle)
{
	uint32_t idx = (uint32_t)(handle & 0xffffffffU);
	uint32_t gen = (uint32_t)(handle >> 32);
	bool was_head;

	if (idx == 0 || idx > ev_cap)
		return;
	idx--;
	if (ev_pool[idx].gen != gen || ev_pool[idx].fn == NULL)
		return;
	/* the head slot is live, so it is this event's slot if it has its index;
	 * if not, the head stays where it is (a sweep keeps it too) */
	was_head = ev_queue_head()->idx == idx;
	ev_release(idx);
	ev_stale++;
	if (ev_stale > EV_SWEEP_MIN && ev_stale > ev_live)
		ev_sweep();
	if (was_head)
		ev_settle();
}

const struct rtos_host_deferred_state rtos_host_deferred_state = {
	&now_ns, &ev_pos_time, &ev_pos_seq, &ev_seq, &ev_deferred, &quiet_until, &cpu.irq_defer,
};

/* rtos_host_defer_at's rare cases: d armed again before it completed (its
 * old place is given up), or a time in the past (a bug; due now). */
void rtos_host_defer_at_slow(struct rtos_host_deferred *d, uint64_t t_ns, rtos_host_event_fn fn,
			     rtos_host_event_fn settle, void *arg)
{
	rtos_host_deferred_disarm(d);
	if (t_ns < now_ns) {
		rtos_host_bug("event", "deferred event in the past (t=%llu ns < now); due now",
			      (unsigned long long)t_ns);
		t_ns = now_ns;
	}
	rtos_host_defer_at(d, t_ns, fn, settle, arg);
}

/* Unlinks d from the armed list behind its head (a handful at most: one per
 * transfer in flight). */
void rtos_host_deferred_unlink(struct rtos_host_deferred *d)
{
	struct rtos_host_deferred **link = &ev_deferred;

	while (*link != d)
		link = &(*link)->next;
	*link = d->next;
	d->next = NULL;
	d->armed = false;
}

/* Queues d's event with d's own time and sequence, as rtos_host_event_at would have. */
rtos_host_event_t rtos_host_deferred_queue(struct rtos_host_deferred *d)
{
	uint64_t t_ns = d->time;

	rtos_host_deferred_disarm(d);
	if (!ev_schedule_check(&t_ns, d->fn))
		return 0;
	return ev_queue_free(t_ns, d->seq, d->fn, d->arg);
}

/* Number of scheduled device events (all queued ones), after every deferred one
 * is settled: completed if due, queued otherwise (its owner decides). */
uint_t event_user_count(void)
{
	while (ev_deferred != NULL) {
		struct rtos_host_deferred *d = ev_deferred;

		d->settle(d->arg);
		if (d->armed) {
			rtos_host_bug("event", "a deferred event's settle left it deferred");
			rtos_host_deferred_disarm(d);
		}
	}
	return ev_live;
}

/* Sets the kernel timer to raise the tick at t_ns (>= now), ordered as an event
 * scheduled now, then every period_ns if not 0; replaces its previous setting. */
void event_timer_set(uint64_t t_ns, uint64_t period_ns)
{
	ev_timer = (struct ev_slot){ t_ns, ev_seq++, 0, 0 };
	ev_timer_period = period_ns;
	ev_head_lower(t_ns);
}

/* The time the kernel timer is set to, UINT64_MAX when off. */
uint64_t event_timer_time(void)
{
	return ev_timer.time;
}

/* Sets the bound quiet_until keeps below besides the next event (see kernel_impl.h). */
void event_set_run_bound(uint64_t t_ns)
{
	ev_run_bound = t_ns;
	ev_head_set(event_head_time);
}

/* An event taken off the queue: what event_run_next calls (returned in two
 * registers, so that no argument lives in memory across the selection). */
struct ev_call {
	rtos_host_event_fn fn;
	void *arg;
};

/* Takes event idx's call and releases it (its slot has left the queue). */
static inline struct ev_call ev_take(uint32_t idx)
{
	struct ev_call c = { ev_pool[idx].fn, ev_pool[idx].arg };

	ev_release(idx);
	return c;
}

/* event_run_next's step when the queue's head is the heap's root (the front is
 * empty): pops it, settles the head and returns its call. */
static __attribute__((noinline)) struct ev_call ev_take_heap_root(void)
{
	uint32_t idx = ev_heap[0].idx;

	ev_pos_time = ev_heap[0].time;
	ev_pos_seq = ev_heap[0].seq;
	ev_heap_pop();
	ev_settle();
	return ev_take(idx);
}

/* The timer's expiry (it is due now, before the queue's live head, which
 * stays where it is): re-armed one period later with the sequence an event
 * scheduled now would take, or off, then the tick interrupt is raised as the
 * hardware timer would (delivered at once if the CPU accepts it). */
static inline void ev_timer_expire(const struct ev_slot *head)
{
	uint64_t head_time = head != NULL ? head->time : UINT64_MAX;

	ev_pos_time = ev_timer.time;
	ev_pos_seq = ev_timer.seq;
	if (ev_timer_period != 0) {
		ev_timer.time += ev_timer_period;
		ev_timer.seq = ev_seq++;
		if (ev_timer.time < head_time)
			head_time = ev_timer.time;
	} else {
		ev_timer.time = UINT64_MAX;
	}
	ev_head_set(head_time);
	irq_raise_tick();
}

/* Pops and runs the queue's head event (the earliest; not the timer) as the
 * hardware; interrupts it raises are delivered after it.  Out of line: the
 * timer's expiry in event_run_next then saves no registers. */
static __attribute__((noinline)) void ev_run_queued(void)
{
	const struct ev_slot *head = ev_queue_head();
	struct ev_call c;
	enum exec_kind saved_kind = cpu.kind;
	ID saved_id = cpu.exec_id;

	if (ev_front_len > 0) {
		uint32_t idx = head->idx;

		ev_pos_time = head->time;
		ev_pos_seq = head->seq;
		ev_front_len--;
		/* the event is off the queue: settling first does not look at it */
		ev_settle();
		c = ev_take(idx);
	} else {
		c = ev_take_heap_root();
	}
	cpu.kind = EXEC_EVENT;
	cpu.exec_id = 0;
	cpu.irq_defer++;
	c.fn(c.arg);
	cpu.irq_defer--;
	cpu.kind = saved_kind;
	cpu.exec_id = saved_id;
	irq_dispatch_pending();
}

/* Runs the earliest event (the timer's expiry or a queued event); now_ns is its time. */
void event_run_next(void)
{
	if (ev_timer.time == now_ns) {
		const struct ev_slot *head = ev_queue_head();

		if (head == NULL || ev_before(&ev_timer, head)) {
			ev_timer_expire(head);
			return;
		}
	}
	ev_run_queued();
}

/* Forgets all events (shutdown/boot); handles from before stay stale forever. */
void event_reset(void)
{
	ev_free = EV_NONE;
	for (uint32_t i = ev_cap; i-- > 0;) {
		if (ev_pool[i].fn != NULL)
			ev_pool[i].gen++;
		ev_pool[i].fn = NULL;
		ev_pool[i].next_free = ev_free;
		ev_free = i;
	}
	ev_front_len = 0;
	ev_heap_len = 0;
	ev_heap_root_changed();
	ev_stale = 0;
	ev_live = 0;
	ev_run_bound = 0;
	ev_head_set(UINT64_MAX);
	ev_timer.time = UINT64_MAX;
	ev_seq = 0;
	ev_pos_time = 0;
	ev_pos_seq = UINT64_MAX;
	while (ev_deferred != NULL)
		rtos_host_deferred_disarm(ev_deferred);
}
