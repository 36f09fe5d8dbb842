/*
 * linux_compat/timerheap.h — the timer queues' priority queue: an intrusive
 * pairing heap (Fredman, Sedgewick, Sleator and Tarjan, "The pairing heap: a
 * new form of self-adjusting heap", Algorithmica 1, 1986).  Insertion is O(1),
 * removing the first or any node O(log n) amortized, and the first node is
 * read in O(1) — what Linux's timerqueue (an rbtree with its leftmost node
 * cached) gives the hrtimer and timer wheel code, without a fixed capacity:
 * each timer carries its node.  The order is (key, seq): the expiry as a
 * 64-bit count, then the sequence the heap gives each node it is given, so
 * equal expiries come out first in, first out.
 *
 * Beside the heap, a FIFO of deferred nodes: while the tick runs the due
 * nodes (between lx_heap_pass_begin and lx_heap_pass_end), a node added with
 * a key already due waits there and joins the heap when the pass ends, so a
 * callback re-arming itself in the past cannot hold the tick.  Not locked:
 * the caller holds the queue's lock.
 */
#ifndef _LINUX_COMPAT_TIMERHEAP_H
#define _LINUX_COMPAT_TIMERHEAP_H

#include <linux/types.h>

struct lx_heap_node {
	struct lx_heap_node *child;   /* first child (the node itself: on the deferred FIFO) */
	struct lx_heap_node *next;    /* next sibling (on the FIFO: the next node) */
	struct lx_heap_node *prev;    /* previous sibling, or the parent of a first child
				       * (on the FIFO: the previous node) */
	u64 key;                      /* the expiry, set by the owner before adding */
	u64 seq;                      /* the order the node was added in */
};

struct lx_heap {
	struct lx_heap_node *root;
	struct lx_heap_node *deferred_first, *deferred_last;
	u64 next_seq;
	bool in_pass;                 /* the due nodes (key <= pass_key) are being taken */
	u64 pass_key;
};

/* The first node (the earliest), or NULL if the heap is empty. */
static inline struct lx_heap_node *lx_heap_first(const struct lx_heap *heap)
{
	return heap->root;
}

/* Empties heap. */
void lx_heap_init(struct lx_heap *heap);
/* Adds node (not in any heap; its key set), after every node of the same key;
 * during a pass, a node already due goes to the deferred FIFO instead. */
void lx_heap_insert(struct lx_heap *heap, struct lx_heap_node *node);
/* Removes node, which must be in heap or on its deferred FIFO. */
void lx_heap_remove(struct lx_heap *heap, struct lx_heap_node *node);
/* A pass over the nodes due at key begins: nodes added due from now on wait. */
void lx_heap_pass_begin(struct lx_heap *heap, u64 key);
/* The pass ends: the deferred nodes join the heap, first in first. */
void lx_heap_pass_end(struct lx_heap *heap);

#endif /* _LINUX_COMPAT_TIMERHEAP_H */
