/*
 * test_event_order.c — device events run in (time, scheduling order) order
 * however the queue holds them: hundreds at once (more than the queue's
 * front, so most wait in its heap), many at the same time, events scheduled
 * by events (also at the current time), and events cancelled before they
 * run.  The order is checked against a model that sorts every scheduled
 * event by (time, sequence) and drops the cancelled ones.
 */
#include <stdlib.h>

#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define MAX_EVENTS  6000U
#define FIRST       400U      /* scheduled before the run */
#define GRAIN_NS    1000U     /* coarse times: many ties */

struct record {
	uint64_t time;
	uint32_t seq;             /* scheduling order */
	rtos_host_event_t handle;
	bool ran, cancelled;
};

static struct record recs[MAX_EVENTS];
static uint32_t nrecs;
static uint32_t ran_order[MAX_EVENTS];
static uint32_t nran;
static uint32_t rand_state = 12345U;
static bool order_ok = true;

/* A small deterministic generator (xorshift32). */
static uint32_t next_rand(void)
{
	rand_state ^= rand_state << 13;
	rand_state ^= rand_state >> 17;
	rand_state ^= rand_state << 5;
	return rand_state;
}

static void on_event(void *arg);

/* Schedules event number nrecs at t_ns and records it. */
static void schedule(uint64_t t_ns)
{
	struct record *r;

	if (nrecs == MAX_EVENTS)
		return;
	r = &recs[nrecs];
	r->time = t_ns;
	r->seq = nrecs;
	r->handle = rtos_host_event_at(t_ns, on_event, (void *)(uintptr_t)nrecs);
	nrecs++;
}

/* An event: logs itself, may schedule up to two more (some now) and cancel a pending one. */
static void on_event(void *arg)
{
	uint32_t id = (uint32_t)(uintptr_t)arg;
	uint32_t more = next_rand() % 3U;

	if (recs[id].ran || recs[id].cancelled || rtos_host_now() != recs[id].time)
		order_ok = false;
	recs[id].ran = true;
	ran_order[nran++] = id;
	for (uint32_t i = 0; i < more; i++)
		schedule(rtos_host_now() + (uint64_t)(next_rand() % 40U) * GRAIN_NS);
	if (next_rand() % 4U == 0 && nrecs > 0) {
		struct record *victim = &recs[next_rand() % nrecs];

		rtos_host_event_cancel(victim->handle);
		if (!victim->ran)
			victim->cancelled = true;
	}
}

/* Model order: earlier time first, then scheduling order. */
static int model_cmp(const void *a, const void *b)
{
	const struct record *x = &recs[*(const uint32_t *)a], *y = &recs[*(const uint32_t *)b];

	if (x->time != y->time)
		return x->time < y->time ? -1 : 1;
	return x->seq < y->seq ? -1 : x->seq > y->seq;
}

static const struct rtos_cfg cfg = { .name = "event_order" };

int main(void)
{
	static uint32_t expected[MAX_EVENTS];
	uint32_t nexpected = 0, cancelled = 0;
	bool same = true;

	tap_plan(5);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	for (uint32_t i = 0; i < FIRST; i++)
		schedule((uint64_t)(next_rand() % 200U) * GRAIN_NS);
	ok(rtos_host_run_until_idle(10ULL * 1000000000ULL), "every event ran or was cancelled");
	for (uint32_t i = 0; i < nrecs; i++) {
		if (recs[i].cancelled)
			cancelled++;
		else
			expected[nexpected++] = i;
	}
	qsort(expected, nexpected, sizeof(expected[0]), model_cmp);
	tap_diag("%u events scheduled, %u cancelled before they ran", nrecs, cancelled);
	ok(nrecs > 2000U && cancelled > 100U, "the run scheduled thousands of events and cancelled some");
	ok(order_ok, "each event ran once, at its time, and none after its cancel");
	same = nran == nexpected;
	for (uint32_t i = 0; same && i < nran; i++)
		same = ran_order[i] == expected[i];
	ok(same, "the events ran in (time, scheduling order) order");
	rtos_host_shutdown();
	return tap_done();
}
