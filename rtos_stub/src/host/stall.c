/*
 * stall.c — the stall watch: while the harness runs the system, a wall-clock
 * interval timer samples the virtual clock; when a task has kept the CPU for
 * the bound without virtual time moving (a loop that calls nothing that costs
 * time), it is reported with its name and PC, and the system ends as after
 * ext_ker: the task is left where it is and the run function returns.  The
 * report is made from the signal handler, which then leaves the task's stack
 * for the harness for good (the signal is unblocked first); a stall outside a
 * task cannot be left that way and ends the process (status 3).
 *
 * The interval timer stays armed from one run to the next and disarms
 * itself on its first tick outside a run: a harness that runs the system in
 * many short slices (a millisecond each) does not pay two system calls a
 * slice, which cost more than the slice's simulation.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <ucontext.h>
#include <unistd.h>

#include "kernel_impl.h"

#define STALL_DEFAULT_MS 10000U
#define STALL_SAMPLES    10U      /* samples per bound */

bool kernel_stalled;
static uint32_t stall_ms = UINT32_MAX;    /* UINT32_MAX: not read from the environment yet */
static uint32_t period_ms;
static volatile uint32_t quiet_ms;
static volatile uint64_t seen_now;
static bool handler_installed;
static volatile sig_atomic_t timer_armed;   /* cleared by the handler when it disarms */
static uint32_t armed_period_ms;

void rtos_host_set_stall_bound(uint32_t ms)
{
	stall_ms = ms;
}

bool rtos_host_stalled(void)
{
	return kernel_stalled;
}

/* The interrupted program counter. */
static uintptr_t context_pc(const void *uctx)
{
	const ucontext_t *uc = uctx;

#if defined(__x86_64__)
	return (uintptr_t)uc->uc_mcontext.gregs[REG_RIP];
#elif defined(__i386__)
	return (uintptr_t)uc->uc_mcontext.gregs[REG_EIP];
#elif defined(__arm__)
	return (uintptr_t)uc->uc_mcontext.arm_pc;
#elif defined(__aarch64__)
	return (uintptr_t)uc->uc_mcontext.pc;
#else
	(void)uc;
	return 0;
#endif
}

/* "PC 0x...: function at file:line" as addr2line knows it, else
 * "PC 0x... (file+0xoffset: symbol)" as far as the dynamic linker knows. */
static void describe_pc(uintptr_t pc, char *buf, size_t size)
{
	Dl_info info;

	char line[256];

	if (rtos_host_source_line(pc, line, sizeof(line))) {
		snprintf(buf, size, "PC %#lx: %s", (unsigned long)pc, line);
		return;
	}
	if (pc != 0 && dladdr((void *)pc, &info) != 0 && info.dli_fname != NULL) {
		snprintf(buf, size, "PC %#lx (%s+%#lx%s%s)", (unsigned long)pc, info.dli_fname,
			 (unsigned long)(pc - (uintptr_t)info.dli_fbase), info.dli_sname ? ": " : "",
			 info.dli_sname ? info.dli_sname : "");
		return;
	}
	snprintf(buf, size, "PC %#lx", (unsigned long)pc);
}

/* Stops the interval timer (async-signal-safe). */
static void stall_timer_disarm(void)
{
	struct itimerval it = { { 0, 0 }, { 0, 0 } };

	if (timer_armed) {
		setitimer(ITIMER_REAL, &it, NULL);
		timer_armed = 0;
	}
}

static void stall_signal(int sig, siginfo_t *si, void *uctx)
{
	char where[320];
	sigset_t set;

	(void)si;
	if (!run_active || stall_ms == 0) {
		stall_timer_disarm();   /* between runs: nothing to watch until the next one */
		return;
	}
	if (now_ns != seen_now) {
		seen_now = now_ns;
		quiet_ms = 0;
		return;
	}
	quiet_ms += period_ms;
	if (quiet_ms < stall_ms || kernel_stalled)
		return;
	/* Before the report, which runs addr2line and may take longer than a period (qemu-arm
	 * on a loaded machine): a tick pending meanwhile comes when the signal is unblocked
	 * below and must not report the stall again. */
	stall_timer_disarm();
	kernel_stalled = true;
	describe_pc(context_pc(uctx), where, sizeof(where));
	rtos_host_bug("stall", "ran %u ms of wall-clock time without advancing virtual time (a loop that "
		      "makes no service call?), at %s", quiet_ms, where);
	kernel_exited = true;
	if (cpu.kind != EXEC_TASK || cpu.isr_depth != 0 || cpu.irq_defer != 0) {
		fflush(NULL);
		_exit(RTOS_HOST_EXIT_STALL);
	}
	/* Never returning to the task: the signal must not stay blocked. */
	sigemptyset(&set);
	sigaddset(&set, sig);
	sigprocmask(SIG_UNBLOCK, &set, NULL);
	ext_ker();
}

/* Arms the watch for a run of the harness. */
void stall_watch_start(void)
{
	struct itimerval it = { { 0, 0 }, { 0, 0 } };

	if (stall_ms == UINT32_MAX) {
		const char *env = getenv("EV3LX_STALL_MS");

		stall_ms = env != NULL ? (uint32_t)strtoul(env, NULL, 10) : STALL_DEFAULT_MS;
	}
	if (stall_ms == 0) {
		stall_timer_disarm();
		return;
	}
	if (!handler_installed) {
		struct sigaction sa;

		memset(&sa, 0, sizeof(sa));
		sa.sa_sigaction = stall_signal;
		sa.sa_flags = SA_SIGINFO | SA_RESTART;
		sigemptyset(&sa.sa_mask);
		if (sigaction(SIGALRM, &sa, NULL) != 0)
			return;
		handler_installed = true;
	}
	period_ms = stall_ms / STALL_SAMPLES > 0 ? stall_ms / STALL_SAMPLES : 1;
	quiet_ms = 0;
	if (timer_armed && armed_period_ms == period_ms) {
		/* still ticking from the previous run: its next tick comes before a
		 * whole period has passed, so it only starts the count */
		seen_now = UINT64_MAX;
		return;
	}
	seen_now = now_ns;
	it.it_interval.tv_sec = period_ms / 1000U;
	it.it_interval.tv_usec = (period_ms % 1000U) * 1000U;
	it.it_value = it.it_interval;
	if (setitimer(ITIMER_REAL, &it, NULL) == 0) {
		armed_period_ms = period_ms;
		timer_armed = 1;
	}
}
