/*
 * event.c — the event queue of the virtual clock: a binary heap keyed by
 * (time, sequence), so events at the same time run in scheduling order.
 * Device events, interrupt-line changes and the kernel's tick are events;
 * virtual time jumps from one to the next.
 */
#include <stdlib.h>
#include <string.h>

#include "kernel_impl.h"

#define EV_NONE UINT32_MAX

struct event {
	uint64_t time;
	uint64_t seq;
	rtos_host_event_fn fn;
	void    *arg;
	uint32_t gen;        /* bumped on every reuse: stale handles are harmless */
	uint32_t heap_pos;   /* EV_NONE when free */
	uint32_t next_free;
	bool     kernel;     /* kernel-internal (tick): not device work */
};

static struct event *ev_pool;
static uint32_t ev_cap;
static uint32_t ev_free = EV_NONE;
static uint32_t *ev_heap;
static uint32_t ev_len;
static uint64_t ev_seq;
static uint_t ev_user;

/* Heap order: earlier time first, then scheduling order. */
static bool ev_before(uint32_t a, uint32_t b)
{
	const struct event *ea = &ev_pool[a], *eb = &ev_pool[b];

	return ea->time < eb->time || (ea->time == eb->time && ea->seq < eb->seq);
}

/* Puts event idx at heap position pos. */
static void ev_place(uint32_t pos, uint32_t idx)
{
	ev_heap[pos] = idx;
	ev_pool[idx].heap_pos = pos;
}

/* Restores heap order upwards from pos. */
static void ev_sift_up(uint32_t pos)
{
	uint32_t idx = ev_heap[pos];

	while (pos > 0) {
		uint32_t parent = (pos - 1) / 2;

		if (!ev_before(idx, ev_heap[parent]))
			break;
		ev_place(pos, ev_heap[parent]);
		pos = parent;
	}
	ev_place(pos, idx);
}

/* Restores heap order downwards from pos. */
static void ev_sift_down(uint32_t pos)
{
	uint32_t idx = ev_heap[pos];

	for (;;) {
		uint32_t child = 2 * pos + 1;

		if (child >= ev_len)
			break;
		if (child + 1 < ev_len && ev_before(ev_heap[child + 1], ev_heap[child]))
			child++;
		if (!ev_before(ev_heap[child], idx))
			break;
		ev_place(pos, ev_heap[child]);
		pos = child;
	}
	ev_place(pos, idx);
}

/* Removes the event at heap position pos. */
static void ev_heap_remove(uint32_t pos)
{
	uint32_t last = ev_heap[--ev_len];

	if (pos == ev_len)
		return;
	ev_place(pos, last);
	ev_sift_down(pos);
	ev_sift_up(ev_pool[last].heap_pos);
}

/* Returns an event to the free list; its handle becomes stale. */
static void ev_release(uint32_t idx)
{
	struct event *ev = &ev_pool[idx];

	if (!ev->kernel)
		ev_user--;
	ev->heap_pos = EV_NONE;
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
	uint32_t *nheap;

	if (npool == NULL)
		return false;
	ev_pool = npool;
	nheap = realloc(ev_heap, ncap * sizeof(*nheap));
	if (nheap == NULL)
		return false;
	ev_heap = nheap;
	for (uint32_t i = ncap; i-- > ev_cap;) {
		memset(&ev_pool[i], 0, sizeof(ev_pool[i]));
		ev_pool[i].heap_pos = EV_NONE;
		ev_pool[i].next_free = ev_free;
		ev_free = i;
	}
	ev_cap = ncap;
	return true;
}

/* Schedules fn(arg) at t_ns; a time in the past is a bug and runs now. */
static rtos_host_event_t ev_schedule(uint64_t t_ns, rtos_host_event_fn fn, void *arg, bool kernel)
{
	uint32_t idx;
	struct event *ev;

	if (fn == NULL) {
		rtos_host_bug("event", "rtos_host_event_at with a NULL function");
		return 0;
	}
	if (t_ns < now_ns) {
		rtos_host_bug("event", "event scheduled in the past (t=%llu ns < now); runs now",
			      (unsigned long long)t_ns);
		t_ns = now_ns;
	}
	if (ev_free == EV_NONE && !ev_grow()) {
		rtos_host_bug("event", "out of memory for events");
		return 0;
	}
	idx = ev_free;
	ev = &ev_pool[idx];
	ev_free = ev->next_free;
	ev->time = t_ns;
	ev->seq = ev_seq++;
	ev->fn = fn;
	ev->arg = arg;
	ev->kernel = kernel;
	if (!kernel)
		ev_user++;
	ev_heap[ev_len] = idx;
	ev->heap_pos = ev_len++;
	ev_sift_up(ev->heap_pos);
	return ((rtos_host_event_t)ev->gen << 32) | (idx + 1U);
}

/* Schedules fn(arg) at absolute virtual time t_ns; same-time events run in order. */
rtos_host_event_t rtos_host_event_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg)
{
	return ev_schedule(t_ns, fn, arg, false);
}

/* Schedules a kernel-internal event (does not count as pending device work). */
rtos_host_event_t event_at_kernel(uint64_t t_ns, rtos_host_event_fn fn, void *arg)
{
	return ev_schedule(t_ns, fn, arg, true);
}

/* Cancels a scheduled event; fired, cancelled or unknown handles are ignored. */
void rtos_host_event_cancel(rtos_host_event_t handle)
{
	uint32_t idx = (uint32_t)(handle & 0xffffffffU);
	uint32_t gen = (uint32_t)(handle >> 32);

	if (idx == 0 || idx > ev_cap)
		return;
	idx--;
	if (ev_pool[idx].gen != gen || ev_pool[idx].heap_pos == EV_NONE)
		return;
	ev_heap_remove(ev_pool[idx].heap_pos);
	ev_release(idx);
}

/* Time of the earliest scheduled event, UINT64_MAX if none. */
uint64_t event_next_time(void)
{
	return ev_len ? ev_pool[ev_heap[0]].time : UINT64_MAX;
}

/* Number of scheduled device (non-kernel) events. */
uint_t event_user_count(void)
{
	return ev_user;
}

/* Pops and runs the earliest event as the hardware; interrupts it raises are delivered after it. */
void event_run_next(void)
{
	uint32_t idx = ev_heap[0];
	rtos_host_event_fn fn = ev_pool[idx].fn;
	void *arg = ev_pool[idx].arg;
	enum exec_kind saved_kind = cpu.kind;
	ID saved_id = cpu.exec_id;

	ev_heap_remove(0);
	ev_release(idx);
	cpu.kind = EXEC_EVENT;
	cpu.exec_id = 0;
	cpu.irq_defer++;
	fn(arg);
	cpu.irq_defer--;
	cpu.kind = saved_kind;
	cpu.exec_id = saved_id;
	irq_dispatch_pending();
}

/* Forgets all events (shutdown/boot); handles from before stay stale forever. */
void event_reset(void)
{
	ev_free = EV_NONE;
	for (uint32_t i = ev_cap; i-- > 0;) {
		if (ev_pool[i].heap_pos != EV_NONE)
			ev_pool[i].gen++;
		ev_pool[i].heap_pos = EV_NONE;
		ev_pool[i].fn = NULL;
		ev_pool[i].next_free = ev_free;
		ev_free = i;
	}
	ev_len = 0;
	ev_seq = 0;
	ev_user = 0;
}
