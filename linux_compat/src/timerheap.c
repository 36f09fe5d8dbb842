/*
 * timerheap.c — the pairing heap of linux_compat/timerheap.h.
 *
 * A node's children hang off its `child` in a doubly linked sibling list;
 * the first child's `prev` is the parent, which is how a node is cut out.
 * Removing the root (or cutting any node) melds its children in two passes:
 * pairs left to right, then the pairs right to left.
 */
#include <linux/kernel.h>
#include <linux_compat/timerheap.h>

/* True if a comes out before b. */
static inline bool before(const struct lx_heap_node *a, const struct lx_heap_node *b)
{
	return a->key < b->key || (a->key == b->key && a->seq < b->seq);
}

/* Melds two roots into one; the later becomes the first child of the earlier. */
static struct lx_heap_node *meld(struct lx_heap_node *a, struct lx_heap_node *b)
{
	struct lx_heap_node *t;

	if (before(b, a)) {
		t = a;
		a = b;
		b = t;
	}
	b->prev = a;
	b->next = a->child;
	if (a->child != NULL)
		a->child->prev = b;
	a->child = b;
	return a;
}

/* Melds a sibling list into one tree (the two-pass pairing); NULL for none. */
static struct lx_heap_node *merge_pairs(struct lx_heap_node *first)
{
	struct lx_heap_node *pairs = NULL, *a, *b, *tree;

	while (first != NULL) {
		a = first;
		b = a->next;
		first = b != NULL ? b->next : NULL;
		a->next = a->prev = NULL;
		if (b != NULL) {
			b->next = b->prev = NULL;
			a = meld(a, b);
		}
		a->next = pairs;           /* the pairs, last first */
		pairs = a;
	}
	tree = pairs;
	if (tree == NULL)
		return NULL;
	pairs = tree->next;
	tree->next = NULL;
	while (pairs != NULL) {
		a = pairs;
		pairs = a->next;
		a->next = NULL;
		tree = meld(tree, a);
	}
	return tree;
}

/* Empties heap. */
void lx_heap_init(struct lx_heap *heap)
{
	heap->root = heap->deferred_first = heap->deferred_last = NULL;
	heap->next_seq = 0;
	heap->in_pass = false;
	heap->pass_key = 0;
}

/* Melds node as a one-node tree with the root: O(1). */
static void insert(struct lx_heap *heap, struct lx_heap_node *node)
{
	node->child = node->next = node->prev = NULL;
	heap->root = heap->root == NULL ? node : meld(heap->root, node);
}

/* Appends node to the deferred FIFO, marked by pointing its child at itself. */
static void defer(struct lx_heap *heap, struct lx_heap_node *node)
{
	node->child = node;
	node->next = NULL;
	node->prev = heap->deferred_last;
	if (heap->deferred_last != NULL)
		heap->deferred_last->next = node;
	else
		heap->deferred_first = node;
	heap->deferred_last = node;
}

/* Adds node with the next sequence: to the heap, or during a pass, if due, to the FIFO. */
void lx_heap_insert(struct lx_heap *heap, struct lx_heap_node *node)
{
	node->seq = heap->next_seq++;
	if (unlikely(heap->in_pass && node->key <= heap->pass_key))
		defer(heap, node);
	else
		insert(heap, node);
}

/* Cuts node out with its subtree, melds its children and the rest: O(log n)
 * amortized; a deferred node is unlinked from the FIFO. */
void lx_heap_remove(struct lx_heap *heap, struct lx_heap_node *node)
{
	struct lx_heap_node *sub;

	if (node->child == node) {
		if (node->prev != NULL)
			node->prev->next = node->next;
		else
			heap->deferred_first = node->next;
		if (node->next != NULL)
			node->next->prev = node->prev;
		else
			heap->deferred_last = node->prev;
	} else if (node == heap->root) {
		heap->root = merge_pairs(node->child);
	} else {
		if (node->prev->child == node)
			node->prev->child = node->next;
		else
			node->prev->next = node->next;
		if (node->next != NULL)
			node->next->prev = node->prev;
		sub = merge_pairs(node->child);
		if (sub != NULL)
			heap->root = meld(heap->root, sub);
	}
	node->child = node->next = node->prev = NULL;
}

void lx_heap_pass_begin(struct lx_heap *heap, u64 key)
{
	heap->in_pass = true;
	heap->pass_key = key;
}

/* Ends the pass and inserts the deferred nodes into the heap in FIFO order. */
void lx_heap_pass_end(struct lx_heap *heap)
{
	struct lx_heap_node *node = heap->deferred_first, *next;

	heap->in_pass = false;
	heap->deferred_first = heap->deferred_last = NULL;
	for (; node != NULL; node = next) {
		next = node->next;
		insert(heap, node);
	}
}
