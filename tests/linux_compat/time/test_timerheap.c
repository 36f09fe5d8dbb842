/*
 * test_timerheap.c — the timer queues' pairing heap against a reference:
 * random insertions, removals of the first and of arbitrary nodes, and equal
 * keys; after every operation the first node is the reference's minimum, and
 * draining yields the keys in order; the deferred FIFO of a pass.  Then hrtimers: 256 armed at random
 * expiries (many equal) fire in expiry order, FIFO among equal expiries,
 * with cancellations of arbitrary ones in between.
 */
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/hrtimer.h>
#include <linux/kernel.h>
#include <linux_compat/timerheap.h>
#include <kernel.h>

#define NODES	512
#define OPS	20000
#define TIMERS	256

struct item {
	struct lx_heap_node node;
	bool in;
};

static struct item items[NODES];
static unsigned int rng = 12345;

static unsigned int next_random(void)
{
	rng = rng * 1103515245U + 12345U;
	return rng >> 8;
}

/* The heap's order: key, then the sequence it gave the node. */
static bool item_before(const struct lx_heap_node *a, const struct lx_heap_node *b)
{
	return a->key < b->key || (a->key == b->key && a->seq < b->seq);
}

/* The reference minimum: the inserted item with the least (key, seq). */
static struct item *reference_min(void)
{
	struct item *min = NULL;

	for (int i = 0; i < NODES; i++)
		if (items[i].in && (min == NULL || item_before(&items[i].node, &min->node)))
			min = &items[i];
	return min;
}

static void heap_against_reference(void)
{
	struct lx_heap heap;
	unsigned int mismatches = 0, inserted = 0, removed = 0, popped = 0, last_key = 0;
	bool ordered = true;
	struct lx_heap_node *first;
	u64 last_seq = 0;

	lx_heap_init(&heap);
	for (int op = 0; op < OPS; op++) {
		unsigned int r = next_random();
		struct item *it = &items[r % NODES];

		if (!it->in) {
			it->node.key = next_random() % 64;   /* many equal keys */
			it->in = true;
			lx_heap_insert(&heap, &it->node);
			inserted++;
		} else if (r & 0x100) {
			lx_heap_remove(&heap, &it->node);    /* an arbitrary node */
			it->in = false;
			removed++;
		} else {
			struct item *min = reference_min();

			lx_heap_remove(&heap, &min->node);   /* the first */
			min->in = false;
			popped++;
		}
		first = lx_heap_first(&heap);
		if ((first == NULL ? NULL : container_of(first, struct item, node)) != reference_min())
			mismatches++;
	}
	ok(mismatches == 0, "after each of %d random operations the first node is the reference minimum "
	   "(%u inserted, %u removed anywhere, %u first removed)", OPS, inserted, removed, popped);
	while ((first = lx_heap_first(&heap)) != NULL) {
		struct item *it = container_of(first, struct item, node);

		if (it->node.key < last_key || (it->node.key == last_key && it->node.seq < last_seq))
			ordered = false;
		last_key = (unsigned int)it->node.key;
		last_seq = it->node.seq;
		lx_heap_remove(&heap, first);
		it->in = false;
	}
	ok(ordered && reference_min() == NULL, "draining yields every key, in order (FIFO among equal keys)");

	/* the deferred FIFO: during a pass over key 8, nodes added due (7) stay out of
	 * the heap until the pass ends, and can be removed meanwhile; a later one (9) does not wait */
	lx_heap_pass_begin(&heap, 8);
	for (int i = 0; i < 4; i++) {
		items[i].node.key = 7;
		lx_heap_insert(&heap, &items[i].node);
	}
	items[4].node.key = 9;
	lx_heap_insert(&heap, &items[4].node);
	first = lx_heap_first(&heap);
	lx_heap_remove(&heap, &items[1].node);
	lx_heap_remove(&heap, &items[3].node);
	lx_heap_pass_end(&heap);
	{
		bool fifo = first == &items[4].node;
		const int expect[] = { 0, 2, 4 };

		for (int k = 0; k < 3; k++) {
			fifo = fifo && lx_heap_first(&heap) == &items[expect[k]].node;
			lx_heap_remove(&heap, lx_heap_first(&heap));
		}
		ok(fifo && lx_heap_first(&heap) == NULL,
		   "deferred nodes stay out of the heap, can be removed, and join it in order when flushed");
	}
}

/* ---- hrtimers ---- */

static struct hrtimer timers[TIMERS];
static u64 expiry_ns[TIMERS];
static int fired[TIMERS], fired_count;
static bool cancelled[TIMERS];
static bool done;

static enum hrtimer_restart on_expiry(struct hrtimer *t)
{
	fired[fired_count++] = (int)(t - timers);
	return HRTIMER_NORESTART;
}

static void main_task(intptr_t exinf)
{
	ktime_t base = ktime_get();

	(void)exinf;
	for (int i = 0; i < TIMERS; i++) {
		hrtimer_init(&timers[i], CLOCK_MONOTONIC, HRTIMER_MODE_ABS);
		timers[i].function = on_expiry;
		expiry_ns[i] = (u64)base + (1 + next_random() % 40) * 200000ULL;   /* ticks, many equal */
		hrtimer_start(&timers[i], (ktime_t)expiry_ns[i], HRTIMER_MODE_ABS);
	}
	for (int i = 0; i < TIMERS; i += 7) {
		cancelled[i] = true;
		hrtimer_cancel(&timers[i]);
	}
	done = true;
}

static void hrtimers_in_order(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 8, true) };
	int expected = 0, order_errors = 0;

	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return;
	rtos_host_run_for(20 * NSEC_PER_MSEC);
	rtos_host_shutdown();
	for (int i = 0; i < TIMERS; i++)
		expected += !cancelled[i];
	is_int(fired_count, expected, "every armed timer fired once, no cancelled one (%d)", expected);
	for (int k = 1; k < fired_count; k++) {
		int a = fired[k - 1], b = fired[k];
		bool started_later = a > b;     /* timers were started in index order */
		u64 ea = expiry_ns[a], eb = expiry_ns[b];

		if (ea > eb || (ea == eb && started_later))
			order_errors++;
	}
	ok(done && order_errors == 0, "in expiry order, and in starting order among equal expiries");
}

int main(void)
{
	tap_plan(5);
	heap_against_reference();
	hrtimers_in_order();
	return tap_done();
}
