/*
 * coroutine.c — task stacks and the context switch of the host kernel.
 *
 * makecontext() is used once per coroutine, to enter a fresh stack; every
 * later switch is GCC's __builtin_setjmp/__builtin_longjmp: the function that
 * sets the resume point keeps every callee-saved register in its own frame,
 * so the point holds the frame, the stack pointer and the resume address
 * and a switch is a few instructions
 * (swapcontext would also call sigprocmask, a system call per switch; glibc's
 * _setjmp/_longjmp save all registers, mangle the pointers and run the
 * unwinder's cancellation step, about twice the instructions).
 * Under AddressSanitizer every switch is announced with the fiber API so that
 * ASan knows which stack is current.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>

#include "kernel_impl.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#include <sanitizer/common_interface_defs.h>
#define CO_ASAN 1
#else
#define CO_ASAN 0
#endif

struct coroutine harness_co;

static jmp_buf creator_jb;                 /* co_create waits here while the trampoline starts */
static struct coroutine *volatile co_starting;
static struct coroutine *volatile co_running;   /* the coroutine that owns the CPU stack now */

#if CO_ASAN
/* Tells ASan we leave the current stack for to's; save: where to keep our fake stack (NULL: dying). */
static void asan_leave(void **save, const struct coroutine *to)
{
	__sanitizer_start_switch_fiber(save, to->stack_lo, to->stack_size);
}

/* Tells ASan the switch into co completed; learns the harness stack bounds on first use. */
static void asan_arrive(struct coroutine *co, void *fake_stack)
{
	const void *old_lo = NULL;
	size_t old_size = 0;

	__sanitizer_finish_switch_fiber(fake_stack, &old_lo, &old_size);
	if (harness_co.stack_lo == NULL && co != &harness_co && old_lo != NULL) {
		harness_co.stack_lo = (void *)(uintptr_t)old_lo;
		harness_co.stack_size = old_size;
	}
}
#endif

/* Entry of every coroutine stack: parks at start_jb, then runs entry() on each (re)start. */
__attribute__((noreturn, no_sanitize_address)) static void co_trampoline(void)
{
#if CO_ASAN
	asan_arrive(co_starting, NULL);
#endif
	if (__builtin_setjmp(co_starting->start_jb) == 0) {
#if CO_ASAN
		asan_leave(&co_starting->fake_stack, &harness_co);
#endif
		_longjmp(creator_jb, 1);
	}
	/* (Re)started by co_switch: locals are stale after the resume point, use co_running. */
#if CO_ASAN
	asan_arrive(co_running, NULL);
#endif
	co_running->entry();
	abort();   /* entry() never returns: tasks leave through a dying switch */
}

/* Creates a coroutine with a stack of stack_size bytes entering entry(); false on ENOMEM. */
bool co_create(struct coroutine *co, size_t stack_size, void (*entry)(void))
{
	size_t page = (size_t)sysconf(_SC_PAGESIZE);
	size_t size = (stack_size + page - 1) / page * page;
	ucontext_t uc;
	char *map;

	memset(co, 0, sizeof(*co));
	map = mmap(NULL, size + page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	if (map == MAP_FAILED)
		return false;
	/* The guard page below the stack turns an overflow into a fault, not corruption. */
	if (mprotect(map, page, PROT_NONE) != 0) {
		munmap(map, size + page);
		return false;
	}
	co->map_base = map;
	co->map_size = size + page;
	co->stack_lo = map + page;
	co->stack_size = size;
	co->entry = entry;
#if CO_ASAN
	ASAN_UNPOISON_MEMORY_REGION(co->stack_lo, co->stack_size);
#endif
	if (getcontext(&uc) != 0) {
		co_destroy(co);
		return false;
	}
	uc.uc_stack.ss_sp = co->stack_lo;
	uc.uc_stack.ss_size = co->stack_size;
	uc.uc_link = NULL;
	makecontext(&uc, co_trampoline, 0);
	co_starting = co;
#if CO_ASAN
	asan_leave(&harness_co.fake_stack, co);
#endif
	if (_setjmp(creator_jb) == 0)
		setcontext(&uc);
#if CO_ASAN
	asan_arrive(&harness_co, harness_co.fake_stack);
#endif
	co_starting = NULL;
	co->restart = true;
	return true;
}

/* Frees the coroutine's stack (never the one running). */
void co_destroy(struct coroutine *co)
{
	if (co->map_base != NULL) {
#if CO_ASAN
		ASAN_UNPOISON_MEMORY_REGION(co->stack_lo, co->stack_size);
#endif
		munmap(co->map_base, co->map_size);
	}
	memset(co, 0, sizeof(*co));
}

/* Resumes at point p.  Out of line: GCC's longjmp builtin may not be in the
 * function that set the point (co_switch). */
static __attribute__((noinline, noreturn)) void co_jump(co_resume_point p)
{
	__builtin_longjmp(p, 1);
}

/* Suspends from and resumes to; from_dying: from will only ever be restarted. */
void co_switch(struct coroutine *from, struct coroutine *to, bool from_dying)
{
#if CO_ASAN
	if (to->restart && to != &harness_co)
		ASAN_UNPOISON_MEMORY_REGION(to->stack_lo, to->stack_size);
	asan_leave(from_dying ? NULL : &from->fake_stack, to);
	if (from_dying)
		from->fake_stack = NULL;
#endif
	if (!from_dying && __builtin_setjmp(from->jb) != 0) {
#if CO_ASAN
		asan_arrive(from, from->fake_stack);
#endif
		return;
	}
	co_running = to;
	if (to->restart) {
		to->restart = false;
		co_jump(to->start_jb);
	}
	co_jump(to->jb);
}
