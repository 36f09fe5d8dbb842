/*
 * app_heap.c — the apps' heap: the memory ev3_memfile_load gives out, in
 * every user domain's memory (config.c's rows), as EV3RT's app heap lies in
 * the app's domain (APP_HEAP_SIZE, 1 MiB: public source ev3rt-git/ev3rt-hrp2,
 * target/ev3_gcc/ev3.h).  So what an app loaded may be handed to any API
 * call and on to a driver's service call, which checks it with prb_mem.
 *
 * First fit over one free list kept in address order, neighbours merged on
 * free; each block starts with a header (its size, whether it is in use).
 * Task context: dispatching is disabled while the list changes.
 */
#include <stddef.h>
#include "rtos_cfg.h"
#include "api_internal.h"

#define ALIGN       16U
#define TAG_USED    0x55EDB10CU
#define TAG_FREE    0xF4EEB10CU

struct block {
	SIZE size;                      /* the whole block's, header included */
	uint32_t tag;                   /* TAG_USED or TAG_FREE */
	struct block *next;             /* free blocks: the next one up */
};

/* the header, padded so that payloads keep the heap's alignment */
#define HEADER     ((sizeof(struct block) + ALIGN - 1U) & ~(SIZE)(ALIGN - 1U))
#define MIN_BLOCK  (HEADER + ALIGN)

uint8_t api_app_heap[EV3LX_APP_HEAP_SIZE] __attribute__((aligned(ALIGN))) EV3LX_SHARED_RW;
static struct block *free_list;

/* An empty heap: one free block of everything (at every boot). */
void api_app_heap_boot(void)
{
	free_list = (struct block *)(void *)api_app_heap;
	free_list->size = sizeof(api_app_heap);
	free_list->tag = TAG_FREE;
	free_list->next = NULL;
}

void *api_app_heap_alloc(SIZE size)
{
	SIZE need = (size + HEADER + ALIGN - 1U) & ~(SIZE)(ALIGN - 1U);
	struct block **link, *b;
	void *payload = NULL;

	if (size == 0 || size > sizeof(api_app_heap) - HEADER)
		return NULL;
	dis_dsp();
	for (link = &free_list; (b = *link) != NULL; link = &b->next) {
		if (b->size < need)
			continue;
		if (b->size - need >= MIN_BLOCK) {     /* split: the rest stays free */
			struct block *rest = (struct block *)(void *)((uint8_t *)b + need);

			rest->size = b->size - need;
			rest->tag = TAG_FREE;
			rest->next = b->next;
			*link = rest;
			b->size = need;
		} else {
			*link = b->next;
		}
		b->tag = TAG_USED;
		payload = (uint8_t *)b + HEADER;
		break;
	}
	ena_dsp();
	return payload;
}

ER api_app_heap_free(void *p)
{
	uint8_t *at = p;
	struct block *b, **link, *prev = NULL;

	if (at < api_app_heap + HEADER || at >= api_app_heap + sizeof(api_app_heap) ||
	    (SIZE)(at - api_app_heap) % ALIGN != 0)
		return E_PAR;
	b = (struct block *)(void *)(at - HEADER);
	dis_dsp();
	if (b->tag != TAG_USED) {       /* freed already, or not a block's start */
		ena_dsp();
		return E_PAR;
	}
	for (link = &free_list; *link != NULL && *link < b; link = &(*link)->next)
		prev = *link;
	b->tag = TAG_FREE;
	b->next = *link;
	*link = b;
	if (b->next != NULL && (uint8_t *)b + b->size == (uint8_t *)b->next) {
		b->size += b->next->size;
		b->next = b->next->next;
	}
	if (prev != NULL && (uint8_t *)prev + prev->size == (uint8_t *)b) {
		prev->size += b->size;
		prev->next = b->next;
	}
	ena_dsp();
	return E_OK;
}

SIZE api_app_heap_usable_size(const void *p)
{
	const struct block *b = (const struct block *)(const void *)((const uint8_t *)p - HEADER);

	return b->size - HEADER;
}
