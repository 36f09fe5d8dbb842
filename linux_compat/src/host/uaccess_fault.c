/*
 * uaccess_fault.c (host) — the exception-table fix-up of copy_*_user for a
 * kernel-domain task: the access runs byte by byte with a SIGSEGV/SIGBUS
 * handler armed for its duration; a fault jumps back and the count of bytes
 * done is the result.
 *
 * The handler is installed around each guarded access and the previous one
 * restored after it, so host_sim's register trap (which also claims SIGSEGV)
 * is untouched outside it.  Only kernel-domain accesses pay for this (two
 * sigaction calls and a sigsetjmp); a user-domain task's ranges were checked
 * exactly by prb_mem and are copied plainly.  The byte loops are volatile
 * (never turned into a library call) and not instrumented by ASan, so the
 * fault is the access's own.
 */
#include <setjmp.h>
#include <signal.h>
#include <string.h>
#include <kernel.h>
#include <rtos_host.h>
#include <linux_compat/uaccess_fault.h>

enum guarded_op { GUARD_COPY, GUARD_CLEAR, GUARD_STRLEN };

/* The armed fix-up: where a fault returns to (one at a time: the host kernel runs one context). */
static sigjmp_buf fixup;

static void fault_handler(int sig, siginfo_t *si, void *uctx)
{
	(void)sig;
	(void)si;
	(void)uctx;
	siglongjmp(fixup, 1);
}

/* The access itself: up to n bytes, counting in *done; GUARD_STRLEN stops at a NUL. */
__attribute__((no_sanitize("address"), noinline))
static void guarded_loop(enum guarded_op op, volatile unsigned char *dst, const volatile unsigned char *src,
			 size_t n, volatile size_t *done)
{
	for (size_t i = 0; i < n; i++) {
		if (op == GUARD_COPY)
			dst[i] = src[i];
		else if (op == GUARD_CLEAR)
			dst[i] = 0;
		else if (src[i] == 0)
			return;
		*done = i + 1;
	}
}

/* Runs one guarded access; returns the bytes done, *faulted set if a fault ended it. */
static size_t guarded(enum guarded_op op, void *dst, const void *src, size_t n, bool *faulted)
{
	struct sigaction sa, old_segv, old_bus;
	volatile size_t done = 0;

	memset(&sa, 0, sizeof(sa));
	sa.sa_sigaction = fault_handler;
	sa.sa_flags = SA_SIGINFO;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGSEGV, &sa, &old_segv);
	sigaction(SIGBUS, &sa, &old_bus);
	*faulted = sigsetjmp(fixup, 1) != 0;
	if (!*faulted)
		guarded_loop(op, dst, src, n, &done);
	sigaction(SIGBUS, &old_bus, NULL);
	sigaction(SIGSEGV, &old_segv, NULL);
	return done;
}

/* A kernel-domain task's prb_mem accepts any range without looking at the memory map. */
bool lx_uaccess_unverified(void)
{
	return rtos_host_current_domain() == TDOM_KERNEL;
}

/* Copies up to n bytes; stops at a fault. */
size_t lx_uaccess_copy(void *dst, const void *src, size_t n)
{
	bool faulted;

	return guarded(GUARD_COPY, dst, src, n, &faulted);
}

/* Zeroes up to n bytes; stops at a fault. */
size_t lx_uaccess_clear(void *dst, size_t n)
{
	bool faulted;

	return guarded(GUARD_CLEAR, dst, NULL, n, &faulted);
}

/* strnlen that stops at a fault. */
size_t lx_uaccess_strnlen(const char *s, size_t n, bool *faulted)
{
	return guarded(GUARD_STRLEN, NULL, s, n, faulted);
}
