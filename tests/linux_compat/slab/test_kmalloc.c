/*
 * test_kmalloc.c — the kmalloc pool: alignment, zeroing, kfree(NULL),
 * exhaustion and reuse (buddies merge back into the whole pool), a random
 * workload that keeps every block intact, misuse reports, and GFP_KERNEL
 * from an interrupt handler reported as a context bug (GFP_ATOMIC fine).
 */
#include "lx_test.h"
#include <linux/slab.h>
#include <linux/mm.h>
#include <linux/interrupt.h>
#include <linux_compat/heap.h>

#define N_SMALL ((int)(LX_HEAP_SIZE / 1024))

static void *small[N_SMALL];
static unsigned char static_buf[3 * PAGE_SIZE];

static size_t in_use(void)
{
	struct lx_heap_stats st;

	lx_heap_get_stats(&st);
	return st.in_use;
}

static void test_basics(void)
{
	struct lx_heap_stats st;
	void *p, *q;
	unsigned char *z;
	size_t i;
	bool all_zero = true;

	lx_heap_get_stats(&st);
	is_u64(st.size, LX_HEAP_SIZE, "pool size is LX_HEAP_SIZE");
	is_u64(st.in_use, 0, "nothing allocated at start");

	p = kmalloc(1, GFP_KERNEL);
	ok(p && ((uintptr_t)p % 8) == 0, "kmalloc(1) is 8-byte aligned");
	ok(ksize(p) == LX_HEAP_MIN_BLOCK, "ksize(kmalloc(1)) is the minimum block (%zu)", ksize(p));
	kfree(p);

	p = kmalloc(PAGE_SIZE, GFP_KERNEL);
	q = kmalloc(13 * PAGE_SIZE, GFP_KERNEL);
	ok(p && PAGE_ALIGNED(p), "kmalloc(PAGE_SIZE) is page-aligned");
	ok(q && PAGE_ALIGNED(q), "kmalloc(13 pages) is page-aligned (UART-sized area)");
	ok(lx_heap_contains(q) && !lx_heap_contains(static_buf), "lx_heap_contains");
	kfree(p);
	kfree(q);

	z = kmalloc(200, GFP_KERNEL);
	memset(z, 0xa5, 200);
	kfree(z);
	z = kzalloc(200, GFP_KERNEL);
	for (i = 0; z && i < 200; i++)
		all_zero = all_zero && z[i] == 0;
	ok(z && all_zero, "kzalloc returns zeroed memory (even a reused block)");
	kfree(z);
	z = kcalloc(10, 30, GFP_KERNEL);
	all_zero = z != NULL;
	for (i = 0; z && i < 300; i++)
		all_zero = all_zero && z[i] == 0;
	ok(all_zero, "kcalloc zeroes");
	kfree(z);
	ok(kcalloc((size_t)-1 / 2, 4, GFP_KERNEL) == NULL, "kcalloc with an overflowing size is NULL");
	ok(kmalloc_array((size_t)-1 / 8, 16, GFP_KERNEL) == NULL, "kmalloc_array overflow is NULL");

	ok(kmalloc(0, GFP_KERNEL) == ZERO_SIZE_PTR, "kmalloc(0) is ZERO_SIZE_PTR");
	kfree(NULL);
	kfree(ZERO_SIZE_PTR);
	is_int(rtos_host_bug_count(), 0, "kfree(NULL) and kfree(ZERO_SIZE_PTR) are silent");

	z = kmalloc(20, GFP_KERNEL);
	memcpy(z, "0123456789abcdefghi", 20);
	z = krealloc(z, 5000, GFP_KERNEL);
	ok(z && memcmp(z, "0123456789abcdefghi", 20) == 0, "krealloc keeps the contents");
	kfree(z);
	is_u64(in_use(), 0, "everything freed");
}

static void test_exhaustion_and_reuse(void)
{
	struct lx_heap_stats st;
	int n = 0, i;
	void *big;
	unsigned long failures_before;

	lx_heap_get_stats(&st);
	failures_before = st.failures;
	lx_heap_reset_high_water();
	while (n < N_SMALL && (small[n] = kmalloc(1024, GFP_KERNEL | __GFP_NOWARN)) != NULL)
		n++;
	is_int(n, N_SMALL, "the pool holds exactly LX_HEAP_SIZE / 1 KiB blocks of 1 KiB");
	ok(kmalloc(1024, GFP_KERNEL | __GFP_NOWARN) == NULL, "then kmalloc returns NULL (exhausted)");
	ok(kmalloc(1, GFP_ATOMIC | __GFP_NOWARN) == NULL, "even for one byte");
	lx_heap_get_stats(&st);
	is_u64(st.failures, failures_before + 2, "failures are counted");
	is_u64(st.in_use, LX_HEAP_SIZE, "in_use is the whole pool");
	is_u64(st.largest_free, 0, "no free block left");

	/* Free every other block: half the memory, but no two free buddies. */
	for (i = 0; i < n; i += 2)
		kfree(small[i]);
	lx_heap_get_stats(&st);
	is_u64(st.largest_free, 1024, "holes do not merge with allocated buddies");
	ok(kmalloc(2048, GFP_KERNEL | __GFP_NOWARN) == NULL, "so a 2 KiB request fails");
	for (i = 1; i < n; i += 2)
		kfree(small[i]);
	lx_heap_get_stats(&st);
	is_u64(st.in_use, 0, "all freed");
	is_u64(st.high_water, LX_HEAP_SIZE, "high-water mark saw the full pool");
	big = kmalloc(LX_HEAP_SIZE, GFP_KERNEL);
	ok(big != NULL, "after freeing, the buddies merged back: the whole pool is one block again");
	kfree(big);
}

/* A deterministic random workload: blocks never overlap and keep their contents. */
static void test_random_workload(void)
{
	enum { SLOTS = 96 };
	static unsigned char *blk[SLOTS];
	static size_t len[SLOTS];
	uint32_t seed = 12345;
	int round, s, corrupt = 0, overlap = 0, alloc_ok = 0;

	for (round = 0; round < 20000; round++) {
		seed = seed * 1103515245U + 12345U;
		s = (int)((seed >> 8) % SLOTS);
		if (blk[s]) {
			for (size_t i = 0; i < len[s]; i++)
				corrupt += blk[s][i] != (unsigned char)(s + i);
			kfree(blk[s]);
			blk[s] = NULL;
		} else {
			len[s] = 1 + ((seed >> 12) % ((seed & 1) ? 9000 : 300));
			blk[s] = kmalloc(len[s], GFP_KERNEL | __GFP_NOWARN);
			if (blk[s]) {
				alloc_ok++;
				for (size_t i = 0; i < len[s]; i++)
					blk[s][i] = (unsigned char)(s + i);
			}
		}
	}
	for (s = 0; s < SLOTS; s++) {
		for (int t = 0; t < SLOTS; t++) {
			if (s != t && blk[s] && blk[t] && blk[s] < blk[t] + len[t] && blk[t] < blk[s] + len[s])
				overlap++;
		}
	}
	for (s = 0; s < SLOTS; s++) {
		if (blk[s]) {
			for (size_t i = 0; i < len[s]; i++)
				corrupt += blk[s][i] != (unsigned char)(s + i);
			kfree(blk[s]);
		}
	}
	ok(alloc_ok > 5000, "random workload allocated %d blocks", alloc_ok);
	is_int(corrupt, 0, "no block was overwritten");
	is_int(overlap, 0, "no two live blocks overlap");
	is_u64(in_use(), 0, "the workload freed everything");
	blk[0] = kmalloc(LX_HEAP_SIZE, GFP_KERNEL);
	ok(blk[0] != NULL, "and the pool is whole again");
	kfree(blk[0]);
}

static void test_pages(void)
{
	unsigned char *buf = kmalloc(3 * PAGE_SIZE, GFP_KERNEL);
	struct page *pg = virt_to_page(buf + PAGE_SIZE + 5);
	struct page *spg = virt_to_page(static_buf + 10);

	ok(page_address(pg) == buf + PAGE_SIZE, "page_address(virt_to_page(p)) is p's page (pool)");
	ok(virt_to_page(buf + 2 * PAGE_SIZE - 1) == pg, "one struct page per page");
	ok(page_address(spg) == (void *)((uintptr_t)(static_buf + 10) & PAGE_MASK),
	   "virt_to_page works outside the pool too");
	ok(virt_to_page(static_buf + 11) == spg, "and is stable");
	SetPageReserved(pg);
	ok(PageReserved(pg) && !PageReserved(virt_to_page(buf)), "SetPageReserved marks one page");
	ClearPageReserved(pg);
	ok(!PageReserved(pg), "ClearPageReserved");
	is_u64(virt_to_phys(buf), (uintptr_t)buf, "virt_to_phys is the identity (flat address space)");
	ok(phys_to_virt(virt_to_phys(buf)) == buf, "phys_to_virt inverts it");
	is_u64(page_to_pfn(pg), ((uintptr_t)buf + PAGE_SIZE) >> PAGE_SHIFT, "page_to_pfn");
	kfree(buf);
}

static void test_misuse(void)
{
	void *p = kmalloc(64, GFP_KERNEL);
	uint_t before;

	rtos_host_expect_bugs(true);
	before = rtos_host_bug_count();
	kfree(p);
	kfree(p);
	is_int(rtos_host_bug_count(), before + 1, "a double kfree is reported");
	kfree(static_buf);
	is_int(rtos_host_bug_count(), before + 2, "kfree of memory not from kmalloc is reported");
	ok(strstr(rtos_host_last_bug(), "kfree") != NULL, "the report names kfree");
	rtos_host_expect_bugs(false);
}

static void *isr_kernel_result, *isr_atomic_result;
static uint_t isr_bugs_kernel, isr_bugs_atomic;

static irqreturn_t alloc_handler(int irq, void *dev)
{
	uint_t before = rtos_host_bug_count();

	isr_atomic_result = kmalloc(32, GFP_ATOMIC);
	isr_bugs_atomic = rtos_host_bug_count() - before;
	before = rtos_host_bug_count();
	isr_kernel_result = kmalloc(32, GFP_KERNEL);
	isr_bugs_kernel = rtos_host_bug_count() - before;
	return IRQ_HANDLED;
}

static void test_gfp_context(void)
{
	static int dev;

	is_int(request_irq(IRQ_DA8XX_UARTINT0, alloc_handler, 0, "alloc", &dev), 0, "request_irq");
	rtos_host_expect_bugs(true);
	rtos_host_irq_raise(IRQ_DA8XX_UARTINT0);
	rtos_host_expect_bugs(false);
	is_int(isr_bugs_atomic, 0, "GFP_ATOMIC from an interrupt handler is fine");
	ok(isr_atomic_result != NULL, "and succeeds");
	is_int(isr_bugs_kernel, 1, "GFP_KERNEL from an interrupt handler is reported as a context bug");
	ok(strstr(rtos_host_last_bug(), "sleeping function") || strstr(rtos_host_last_bug(), "might_sleep"),
	   "the report says why: %s", rtos_host_last_bug());
	kfree(isr_atomic_result);
	kfree(isr_kernel_result);
	free_irq(IRQ_DA8XX_UARTINT0, &dev);
}

static void body(void)
{
	test_basics();
	test_exhaustion_and_reuse();
	test_random_workload();
	test_pages();
	test_misuse();
	test_gfp_context();
}

int main(void)
{
	tap_plan(49);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
