/*
 * test_uaccess.c — copy_*_user & co. from a task in a user protection
 * domain with configured memory regions: good, bad and straddling ranges
 * give Linux's "bytes not copied" results, only the accessible prefix is
 * copied (bisection, few probes), the read-only region refuses writes, and
 * a call from interrupt context is reported and copies nothing.
 */
#include "lx_test.h"
#include <linux/uaccess.h>
#include <linux/interrupt.h>
#include <linux/string.h>
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

/* The arena: [0, 1024) read-write for domain 1, [1024, 2048) inaccessible,
 * [2048, 3072) read-only, [3072, 4096) inaccessible. */
static unsigned char arena[4096] __attribute__((aligned(64)));
#define RW	(arena)
#define GAP	(arena + 1024)
#define RO	(arena + 2048)

static unsigned char kbuf[256];
static unsigned int failed_probes;

static const struct rtos_mem_cfg mems[] = {
	{ 1, arena, 1024, TPM_READ | TPM_WRITE, "rw" },
	{ 1, arena + 2048, 1024, TPM_READ, "ro" },
};

static ER_UINT svc_copy_in(intptr_t to, intptr_t from, intptr_t n, intptr_t p4, intptr_t p5, ID cdmid)
{
	return (ER_UINT)copy_from_user((void *)to, (const void __user *)from, (unsigned long)n);
}

static const struct rtos_svc_cfg svcs[] = {
	{ 1, svc_copy_in, 4096 },
};

static const struct rtos_cfg extra = {
	.name = "uaccess", .mems = RTOS_TABLE(mems), .svcs = RTOS_TABLE(svcs),
};

static void count_probes(const char *line, void *ctx)
{
	if (strstr(line, "prb_mem"))
		failed_probes++;
}

static bool all_are(const unsigned char *p, size_t n, unsigned char v)
{
	for (size_t i = 0; i < n; i++)
		if (p[i] != v)
			return false;
	return true;
}

static void test_copies(void)
{
	int value = 0;
	unsigned char local[16];

	memset(kbuf, 0xee, sizeof(kbuf));
	failed_probes = 0;
	is_int(copy_from_user(kbuf, RW, 256), 0, "copy_from_user of an accessible range: 0 bytes left");
	ok(all_are(kbuf, 256, 0x11), "the bytes arrived");
	is_int(failed_probes, 0, "one successful probe, no failed ones");

	memset(kbuf, 0xee, sizeof(kbuf));
	failed_probes = 0;
	is_int(copy_from_user(kbuf, RW + 1000, 100), 76, "straddling the region's end: 76 of 100 not copied");
	ok(all_are(kbuf, 24, 0x11), "the accessible 24 bytes were copied");
	ok(all_are(kbuf + 24, 76, 0), "the rest of the destination is zero-filled");
	ok(failed_probes >= 1 && failed_probes <= 8, "found by bisection: %u failed probes", failed_probes);

	is_int(copy_from_user(kbuf, GAP, 10), 10, "an inaccessible range: nothing copied");
	is_int(copy_from_user(kbuf, NULL, 10), 10, "NULL: nothing copied");
	is_int(copy_from_user(kbuf, (const void __user *)kbuf, 10), 10, "kernel memory: nothing copied");
	is_int(copy_from_user(kbuf, RW, 0), 0, "zero bytes: 0");

	memset(kbuf, 0x22, sizeof(kbuf));
	is_int(copy_to_user(RW + 1000, kbuf, 100), 76, "copy_to_user straddling: 76 not copied");
	ok(all_are(RW + 1000, 24, 0x22), "the accessible part was written");
	ok(all_are(GAP, 1024, 0), "nothing beyond the region was touched");
	is_int(copy_to_user(RO, kbuf, 16), 16, "copy_to_user into a read-only region: nothing copied");
	ok(all_are(RO, 16, 0x33), "the read-only region is intact");
	is_int(copy_from_user(kbuf, RO, 16), 0, "but it can be read");
	is_int(copy_from_user(kbuf, RO + 1000, 100), 76, "read-only region straddling into the gap: 76 left");

	is_int(copy_to_user(local, kbuf, sizeof(local)), 0, "the task's own stack is accessible");

	memcpy(RW + 16, &(int){ 1234 }, sizeof(int));
	is_int(get_user(value, (int __user *)(RW + 16)), 0, "get_user from the region: 0");
	is_int(value, 1234, "get_user read the value");
	/* NOLINTNEXTLINE(clang-analyzer-deadcode.DeadStores): the 99 is there to be overwritten */
	value = 99;
	is_int(get_user(value, (int __user *)GAP), -EFAULT, "get_user from the gap: -EFAULT");
	is_int(value, 0, "and stores 0");
	is_int(put_user(4321, (int __user *)(RW + 20)), 0, "put_user into the region: 0");
	ok(memcmp(RW + 20, &(int){ 4321 }, sizeof(int)) == 0, "put_user wrote the value");
	is_int(put_user(1, (int __user *)RO), -EFAULT, "put_user into read-only memory: -EFAULT");
	{
		u8 small = 0;
		u64 big = 0;

		RW[40] = 0xab;
		memset(RW + 48, 0x5c, 8);
		is_int(get_user(small, (u8 __user *)(RW + 40)), 0, "get_user of a u8");
		is_int(small, 0xab, "reads one byte");
		is_int(get_user(big, (u64 __user *)(RW + 48)), 0, "get_user of a u64");
		is_u64(big, 0x5c5c5c5c5c5c5c5cULL, "reads eight bytes");
	}

	ok(access_ok(RW, 1024), "access_ok(addr, size) on the region");
	ok(!access_ok(RW + 1000, 100), "access_ok false when straddling");
	ok(access_ok(VERIFY_READ, RO, 10), "2.6.33's access_ok(VERIFY_READ, ...) on read-only memory");
	ok(!access_ok(VERIFY_WRITE, RO, 10), "access_ok(VERIFY_WRITE, ...) refuses it");

	memset(RW + 900, 0x44, 124);
	is_int(clear_user(RW + 1000, 100), 76, "clear_user straddling: 76 not cleared");
	ok(all_are(RW + 1000, 24, 0) && all_are(RW + 900, 100, 0x44), "exactly the accessible part cleared");

	{
		char s[32];

		strcpy((char *)RW + 100, "hello");
		is_int(strncpy_from_user(s, (const char __user *)(RW + 100), sizeof(s)), 5, "strncpy_from_user: length");
		is_str(s, "hello", "the string was copied with its NUL");
		is_int(strncpy_from_user(s, (const char __user *)(RW + 100), 3), 3, "count reached first: count");
		memset(RW + 1014, 'x', 10);
		is_int(strncpy_from_user(s, (const char __user *)(RW + 1014), sizeof(s)), -EFAULT,
		       "a string running off the region: -EFAULT");
		is_int(strnlen_user((const char __user *)(RW + 100), 32), 6, "strnlen_user counts the NUL");
		is_int(strnlen_user((const char __user *)GAP, 32), 0, "strnlen_user on inaccessible memory: 0");
	}

	memset(kbuf, 0, sizeof(kbuf));
	is_int(cal_svc(1, (intptr_t)kbuf, (intptr_t)(RW + 1000), 100, 0, 0), 76,
	       "through an extended service call: the caller's domain is checked");
}

static unsigned long isr_result;

static irqreturn_t copying_handler(int irq, void *dev)
{
	isr_result = copy_from_user(kbuf, RW, 8);
	return IRQ_HANDLED;
}

static void test_interrupt_context(void)
{
	static int dev;

	is_int(request_irq(IRQ_DA8XX_EVTOUT2, copying_handler, 0, "copy", &dev), 0, "request_irq");
	rtos_host_expect_bugs(true);
	rtos_host_irq_raise(IRQ_DA8XX_EVTOUT2);
	rtos_host_expect_bugs(false);
	is_int(isr_result, 8, "copy_from_user in an interrupt handler copies nothing");
	ok(strstr(rtos_host_last_bug(), "copy_from_user") != NULL, "and is reported: %s", rtos_host_last_bug());
	(void)free_irq(IRQ_DA8XX_EVTOUT2, &dev);
}

/* set_fs(KERNEL_DS): how a hack hands the driver a buffer of its own. */
static void test_address_limit(void)
{
	mm_segment_t old = get_fs();

	ok(segment_eq(old, USER_DS), "a task starts with USER_DS");
	is_int(copy_from_user(kbuf, GAP, 16), 16, "memory outside the domain is refused under USER_DS");
	set_fs(KERNEL_DS);
	ok(uaccess_kernel(), "set_fs(KERNEL_DS) takes effect");
	is_int(copy_from_user(kbuf, GAP, 16), 0, "and the same copy is accepted");
	is_int(copy_to_user(GAP, kbuf, 16), 0, "copy_to_user too");
	ok(access_ok(GAP, 16), "access_ok too");
	set_fs(old);
	is_int(copy_from_user(kbuf, GAP, 16), 16, "refused again after set_fs(old)");
}

/*
 * A kernel-domain task: prb_mem checks nothing, so a wild pointer faults
 * inside the copy; the fix-up makes every call return what Linux's
 * exception table gives: the exact bytes not copied, never a crash.
 */
static void test_kernel_task(void)
{
	long page = sysconf(_SC_PAGESIZE);
	unsigned char *two = mmap(NULL, (size_t)page * 2, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	unsigned char *edge;
	char small[16];
	struct sigaction before, after;

	is_int(copy_from_user(kbuf, GAP, 16), 0, "a kernel-domain task may copy from anywhere");
	if (two == MAP_FAILED) {
		tap_skip(14, "mmap failed");
		return;
	}
	edge = two + page;
	munmap(edge, (size_t)page);
	memset(edge - 10, 0x5a, 10);
	sigaction(SIGSEGV, NULL, &before);

	memset(kbuf, 0xee, sizeof(kbuf));
	is_int(copy_from_user(kbuf, (const void __user *)(edge - 10), 30), 20,
	       "copy_from_user running into an unmapped page: 20 of 30 not copied");
	ok(all_are(kbuf, 10, 0x5a) && all_are(kbuf + 10, 20, 0), "the 10 mapped bytes arrived, the rest is zeroed");
	memset(kbuf, 0x77, sizeof(kbuf));
	is_int(copy_to_user((void __user *)(edge - 10), kbuf, 30), 20, "copy_to_user into it: 20 of 30 not copied");
	ok(all_are(edge - 10, 10, 0x77), "the mapped part was written");
	is_int(copy_from_user(kbuf, (const void __user *)edge, 8), 8, "entirely unmapped: nothing copied");
	is_int(clear_user((void __user *)(edge - 4), 12), 8, "clear_user: 8 of 12 not cleared");
	ok(all_are(edge - 4, 4, 0), "the mapped 4 bytes cleared");
	memset(edge - 8, 'x', 8);
	is_int(strnlen_user((const char __user *)(edge - 8), 64), 0, "strnlen_user without a NUL before the hole: 0");
	is_int(strncpy_from_user(small, (const char __user *)(edge - 8), sizeof(small)), -EFAULT,
	       "strncpy_from_user: -EFAULT");
	memcpy(edge - 4, "abc", 4);
	is_int(strnlen_user((const char __user *)(edge - 4), 64), 4, "a NUL-terminated string at the edge: 4");
	is_int(strncpy_from_user(small, (const char __user *)(edge - 4), sizeof(small)), 3, "and copied: 3");
	ok(strcmp(small, "abc") == 0, "as \"abc\"");

	mprotect(two, (size_t)page, PROT_READ);
	is_int(copy_to_user((void __user *)two, kbuf, 16), 16, "copy_to_user into a read-only page: nothing copied");
	sigaction(SIGSEGV, NULL, &after);
	ok(before.sa_sigaction == after.sa_sigaction && before.sa_flags == after.sa_flags,
	   "the SIGSEGV handler of before (host_sim's trap or the default) is back");
	munmap(two, (size_t)page);
}

int main(void)
{
	tap_plan(72);
	memset(arena, 0, sizeof(arena));
	memset(RW, 0x11, 1024);
	memset(RO, 0x33, 1024);
	rtos_host_trace_set_sink(count_probes, NULL);
	ok(lx_test_run_in(test_copies, 1, &extra), "user-domain task ran");
	rtos_host_trace_set_sink(NULL, NULL);
	ok(lx_test_run_in(test_address_limit, 1, &extra), "address-limit task ran");
	ok(lx_test_run(test_interrupt_context), "interrupt test ran");
	ok(lx_test_run(test_kernel_task), "kernel task ran");
	return tap_done();
}
