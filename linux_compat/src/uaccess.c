/*
 * uaccess.c — user memory: every copy checks the calling task's protection
 * domain with prb_mem first (linux/uaccess.h states the contract).
 */
#include <linux/uaccess.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <kernel.h>
#include <rtos_cfg.h>
#include <linux_compat/irq.h>
#include <linux_compat/uaccess_fault.h>

/* Tasks running with the address limit KERNEL_DS (set_fs), by task ID. */
static bool task_kernel_ds[TNUM_TSKID + 1];

/* The calling task's ID, or 0 outside task context. */
static ID calling_task(void)
{
	ID tid;

	return (get_tid(&tid) == E_OK && tid > 0 && tid <= TNUM_TSKID) ? tid : 0;
}

mm_segment_t get_fs(void)
{
	ID tid = calling_task();

	return (tid && task_kernel_ds[tid]) ? KERNEL_DS : USER_DS;
}

void set_fs(mm_segment_t fs)
{
	ID tid = calling_task();

	if (tid)
		task_kernel_ds[tid] = segment_eq(fs, KERNEL_DS);
}

void lx_uaccess_boot(void)
{
	memset(task_kernel_ds, 0, sizeof(task_kernel_ds));
}

/*
 * How many bytes from p on the calling task may access with mode, after the
 * one probe of the whole range failed: the length of the accessible prefix
 * by bisection (accessibility of prefixes is monotonic).
 */
static size_t accessible_prefix_slow(const void *p, size_t n, MODE mode)
{
	size_t ok = 0, bad = n;

	while (bad - ok > 1) {
		size_t mid = ok + (bad - ok) / 2;

		if (prb_mem(p, (SIZE)mid, TSK_SELF, mode) == E_OK)
			ok = mid;
		else
			bad = mid;
	}
	return ok;
}

/*
 * How many bytes from p on the calling task may access with mode (one probe
 * when all).  *unverified is set when that answer says nothing about the
 * memory map (a kernel-domain task, or KERNEL_DS): the access must then be
 * the fault-safe one.
 */
static size_t accessible_prefix(const void *p, size_t n, MODE mode, bool *unverified)
{
	*unverified = false;
	if (n == 0)
		return 0;
	if (prb_mem(p, (SIZE)n, TSK_SELF, mode) == E_OK) {
		*unverified = lx_uaccess_unverified();
		return n;
	}
	if (uaccess_kernel()) {
		*unverified = true;
		return n;
	}
	return accessible_prefix_slow(p, n, mode);
}

/* Copies the accessible prefix; returns the bytes copied (fewer if an unverified range faults). */
static size_t copy_prefix(void *to, const void *from, size_t ok, bool unverified)
{
	if (unverified)
		return lx_uaccess_copy(to, from, ok);
	if (ok)
		memcpy(to, from, ok);
	return ok;
}

/*
 * The checks every user copy starts with: reports a call from a context that
 * may not sleep (LX_DEBUG_ATOMIC_SLEEP), and returns false if there is no
 * calling task to check against (interrupt context), in which case nothing
 * is copied.
 */
static bool user_copy_allowed(const char *what)
{
	lx_might_sleep(what, NULL, 0);
	return !sns_ctx();
}

/*
 * The common case costs one probe and the copy: prb_mem(TSK_SELF) accepts the
 * whole range only for a calling task (outside task context it fails), so the
 * context is asked only when the probe fails.  A kernel-domain caller's range
 * is accepted unchecked, so its copy is the fault-safe one.
 */
unsigned long copy_from_user(void *to, const void __user *from, unsigned long n)
{
	size_t ok;
	bool unverified;

	lx_might_sleep("copy_from_user()", NULL, 0);
	if (likely(n != 0 && prb_mem((__force const void *)from, (SIZE)n, TSK_SELF, TPM_READ) == E_OK &&
		   !lx_uaccess_unverified())) {
		memcpy(to, (__force const void *)from, n);
		return 0;
	}
	if (n == 0)
		return 0;
	if (sns_ctx()) {
		memset(to, 0, n);
		return n;
	}
	ok = accessible_prefix((__force const void *)from, n, TPM_READ, &unverified);
	ok = copy_prefix(to, (__force const void *)from, ok, unverified);
	if (ok < n)
		memset((char *)to + ok, 0, n - ok);
	return n - ok;
}

/* As copy_from_user: one probe and the copy in the common case. */
unsigned long copy_to_user(void __user *to, const void *from, unsigned long n)
{
	size_t ok;
	bool unverified;

	lx_might_sleep("copy_to_user()", NULL, 0);
	if (likely(n != 0 && prb_mem((__force const void *)to, (SIZE)n, TSK_SELF, TPM_WRITE) == E_OK &&
		   !lx_uaccess_unverified())) {
		memcpy((__force void *)to, from, n);
		return 0;
	}
	if (n == 0)
		return 0;
	if (sns_ctx())
		return n;
	ok = accessible_prefix((__force const void *)to, n, TPM_WRITE, &unverified);
	return n - copy_prefix((__force void *)to, from, ok, unverified);
}

unsigned long clear_user(void __user *to, unsigned long n)
{
	size_t ok;
	bool unverified;

	if (!user_copy_allowed("clear_user()"))
		return n;
	ok = accessible_prefix((__force const void *)to, n, TPM_WRITE, &unverified);
	if (unverified)
		ok = lx_uaccess_clear((__force void *)to, ok);
	else if (ok)
		memset((__force void *)to, 0, ok);
	return n - ok;
}

/* strnlen over the accessible prefix; *hit_end set when inaccessible memory came before a NUL. */
static size_t user_strnlen(const char *s, size_t n, MODE mode, bool *hit_end)
{
	bool unverified, faulted = false;
	size_t ok = accessible_prefix(s, n, mode, &unverified);
	size_t len = unverified ? lx_uaccess_strnlen(s, ok, &faulted) : strnlen(s, ok);

	*hit_end = faulted || (len == ok && ok < n);
	return len;
}

long strncpy_from_user(char *dst, const char __user *src, long count)
{
	size_t len;
	bool hit_end;

	if (count <= 0)
		return 0;
	if (!user_copy_allowed("strncpy_from_user()"))
		return -EFAULT;
	len = user_strnlen((__force const char *)src, (size_t)count, TPM_READ, &hit_end);
	if (hit_end)
		return -EFAULT;     /* ran into inaccessible memory before a NUL */
	if (len < (size_t)count) {
		memcpy(dst, (__force const char *)src, len + 1);
		return (long)len;
	}
	memcpy(dst, (__force const char *)src, (size_t)count);
	return count;
}

long strnlen_user(const char __user *str, long n)
{
	size_t len;
	bool hit_end;

	if (n <= 0)
		return 0;
	if (!user_copy_allowed("strnlen_user()"))
		return 0;
	len = user_strnlen((__force const char *)str, (size_t)n, TPM_READ, &hit_end);
	if (hit_end)
		return 0;
	return len < (size_t)n ? (long)len + 1 : n + 1;
}

bool lx_access_ok(const void __user *addr, unsigned long size, int write)
{
	if (size == 0)
		return true;
	if (sns_ctx())
		return false;
	return prb_mem((__force const void *)addr, (SIZE)size, TSK_SELF,
		       write ? TPM_WRITE : TPM_READ) == E_OK || uaccess_kernel();
}

int lx_get_user(void *val, const void __user *ptr, size_t size)
{
	return copy_from_user(val, ptr, size) ? -EFAULT : 0;
}

int lx_put_user(const void *val, void __user *ptr, size_t size)
{
	return copy_to_user(ptr, val, size) ? -EFAULT : 0;
}
