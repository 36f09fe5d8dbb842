/*
 * crash.c — fatal signals (rtos_host.h): a NULL or wild pointer, a division
 * by zero, an undefined instruction, abort(), or a task running off its host
 * stack ends the process with a report instead of a bare "Segmentation
 * fault" (or nothing, for a stack overflow: with no stack left the kernel
 * cannot even enter a handler, hence the alternate signal stack).
 *
 * The report is written with write(2) from the handler: the kind, the
 * signal and its code, the faulting address, the context (the running task
 * by name), virtual time, and the faulting PC's function and source line as
 * addr2line (GNU binutils) gives them from the program's debug information.
 * addr2line runs in a child process (fork, exec), the one way to read DWARF
 * lines from a handler without the allocator.  Then the process exits with
 * RTOS_HOST_EXIT_STACK (a fault at a task stack's end, or with the
 * interrupted stack pointer below its task's stack) or RTOS_HOST_EXIT_CRASH.
 *
 * The alternate stack disarms itself while a handler runs on it
 * (SS_AUTODISARM, Linux 4.7) where the kernel has it: host_sim's pointer trap
 * then runs there too, and may switch tasks inside its handler, because a
 * signal taken on another task's stack meanwhile lands on that stack instead
 * of on the handler's frames.  Without it (qemu-arm 7.2 rejects the flag)
 * the trap stays on the faulting stack and a fault at a stack's end, with
 * the trap installed, still kills the process without a report.
 *
 * A handler installed before ours runs after the report: AddressSanitizer's
 * (SIGSEGV, SIGBUS and SIGFPE, installed before main) for its own report with
 * the stack trace — ASan's death callback then exits with this file's status
 * instead of ASan's 1 — or a fuzzer's, which keeps the input.
 *
 * The stack-use check (stack_use_record, rtos_host_task_stack_used) lives
 * here too: its overrun ends the system with RTOS_HOST_EXIT_STACK as well.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <elf.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <link.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <ucontext.h>
#include <unistd.h>

#include "kernel_impl.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#define CRASH_ASAN 1
#else
#define CRASH_ASAN 0
#endif

#ifndef SS_AUTODISARM
#define SS_AUTODISARM (1U << 31)
#endif

#define ALT_STACK_SIZE (1024U * 1024U)   /* room for the pointer trap's emulation and ASan's report */
#define FRAME_REACH    (64U * 1024U)     /* a stack pointer this far below a stack: a frame jumped its guard */

static const int fatal_signals[] = { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT };
#define NFATAL (sizeof(fatal_signals) / sizeof(fatal_signals[0]))

static bool installed;
static bool stack_disarms;
static struct sigaction previous[NFATAL];
static uintptr_t exe_base;      /* where the program is loaded */
static bool exe_relocatable;    /* ET_DYN (PIE): addr2line wants pc - exe_base */
static volatile sig_atomic_t exit_status;   /* ASan's death callback exits with it */

bool kernel_stack_overrun;

/* ---- Text without stdio (the handler) ---- */

struct text {
	char *buf;
	size_t len, size;
};

/* Appends s (truncated at the buffer's end). */
static void put_str(struct text *t, const char *s)
{
	while (*s != '\0' && t->len + 1 < t->size)
		t->buf[t->len++] = *s++;
	t->buf[t->len] = '\0';
}

/* Appends v in base (10 or 16) with at least min_digits digits. */
static void put_uint(struct text *t, unsigned long long v, unsigned base, unsigned min_digits)
{
	char digits[24];
	unsigned n = 0;

	do {
		digits[n++] = "0123456789abcdef"[v % base];
		v /= base;
	} while (v != 0 || n < min_digits);
	while (n > 0 && t->len + 1 < t->size)
		t->buf[t->len++] = digits[--n];
	t->buf[t->len] = '\0';
}

/* Appends v as 0x... */
static void put_hex(struct text *t, uintptr_t v)
{
	put_str(t, "0x");
	put_uint(t, v, 16, 1);
}

/* Writes n bytes of s to fd, through short writes and EINTR. */
static void write_all(int fd, const char *s, size_t n)
{
	while (n > 0) {
		ssize_t w = write(fd, s, n);

		if (w <= 0 && errno != EINTR)
			return;
		if (w > 0) {
			s += w;
			n -= (size_t)w;
		}
	}
}

/* ---- Source lines ---- */

/* Runs tool -f -C -p -e file hex (addr2line); its first output line into buf. */
static bool addr2line_run(const char *tool, const char *file, uintptr_t addr, char *buf, size_t len)
{
	char hex[2 + 2 * sizeof(uintptr_t) + 1];
	struct text h = { hex, 0, sizeof(hex) };
	int fd[2], wstatus;
	size_t n = 0;
	pid_t pid;

	put_hex(&h, addr);
	if (pipe(fd) != 0)
		return false;
	pid = fork();
	if (pid < 0) {
		close(fd[0]);
		close(fd[1]);
		return false;
	}
	if (pid == 0) {
		char *argv[] = { (char *)tool, "-f", "-C", "-p", "-e", (char *)file, hex, NULL };
		int null = open("/dev/null", O_RDWR);

		dup2(fd[1], STDOUT_FILENO);
		if (null >= 0) {
			dup2(null, STDIN_FILENO);
			dup2(null, STDERR_FILENO);
		}
		close(fd[0]);
		execvp(tool, argv);
		_exit(127);
	}
	close(fd[1]);
	while (n + 1 < len) {
		ssize_t r = read(fd[0], buf + n, len - 1 - n);

		if (r < 0 && errno == EINTR)
			continue;
		if (r <= 0)
			break;
		n += (size_t)r;
	}
	close(fd[0]);
	while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR)
		;
	buf[n] = '\0';
	buf[strcspn(buf, "\n")] = '\0';
	/* "?? ??:0": no symbol and no line; a function without a line ("f at ??:0") still helps */
	return n > 0 && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 && strncmp(buf, "?? ", 3) != 0;
}

/* Where the program is loaded and whether addr2line needs addresses relative to it. */
static void find_program(void)
{
	Dl_info info;

	if (dladdr((void *)(uintptr_t)&rtos_host_crash_install, &info) == 0 || info.dli_fbase == NULL)
		return;
	exe_base = (uintptr_t)info.dli_fbase;
	exe_relocatable = ((const ElfW(Ehdr) *)info.dli_fbase)->e_type == ET_DYN;
}

bool rtos_host_source_line(uintptr_t pc, char *buf, size_t len)
{
	static const char *const tools[] = {
#if defined(__arm__)
		"arm-linux-gnueabi-addr2line",   /* the build host's addr2line may not read ARM ELF */
#endif
		"addr2line",
	};
	char exe[PATH_MAX];
	const char *file = exe;
	uintptr_t addr = pc;
	Dl_info info;
	ssize_t n;

	if (len == 0)
		return false;
	buf[0] = '\0';
	if (pc == 0)
		return false;
	if (exe_base == 0)
		find_program();
	if (dladdr((void *)pc, &info) != 0 && info.dli_fbase != NULL &&
	    (uintptr_t)info.dli_fbase != exe_base && info.dli_fname != NULL && info.dli_fname[0] == '/') {
		file = info.dli_fname;                   /* a shared object: always relocatable */
		addr = pc - (uintptr_t)info.dli_fbase;
	} else {
		n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
		if (n <= 0)
			return false;
		exe[n] = '\0';
		if (exe_relocatable)
			addr = pc - exe_base;
	}
	for (size_t i = 0; i < sizeof(tools) / sizeof(tools[0]); i++)
		if (addr2line_run(tools[i], file, addr, buf, len))
			return true;
	buf[0] = '\0';
	return false;
}

/* ---- The report ---- */

/* The interrupted program counter and stack pointer. */
static void context_pc_sp(const void *uctx, uintptr_t *pc, uintptr_t *sp)
{
	const ucontext_t *uc = uctx;

#if defined(__x86_64__)
	*pc = (uintptr_t)uc->uc_mcontext.gregs[REG_RIP];
	*sp = (uintptr_t)uc->uc_mcontext.gregs[REG_RSP];
#elif defined(__i386__)
	*pc = (uintptr_t)uc->uc_mcontext.gregs[REG_EIP];
	*sp = (uintptr_t)uc->uc_mcontext.gregs[REG_ESP];
#elif defined(__arm__)
	*pc = (uintptr_t)uc->uc_mcontext.arm_pc;
	*sp = (uintptr_t)uc->uc_mcontext.arm_sp;
#elif defined(__aarch64__)
	*pc = (uintptr_t)uc->uc_mcontext.pc;
	*sp = (uintptr_t)uc->uc_mcontext.sp;
#else
	(void)uc;
	*pc = 0;
	*sp = 0;
#endif
}

/* The task whose host stack (with its guard page below) holds addr, or NULL. */
static struct tcb *task_of_stack_address(uintptr_t addr)
{
	for (ID id = 1; id <= TNUM_TSKID; id++) {
		const struct tcb *t = tcb_table[id];

		if (t != NULL && t->co.map_base != NULL && addr >= (uintptr_t)t->co.map_base &&
		    addr < (uintptr_t)t->co.stack_lo + t->co.stack_size)
			return tcb_table[id];
	}
	return NULL;
}

/* True if addr is in t's guard page, or sp (the interrupted one) has left t's stack below. */
static bool past_stack_end(const struct tcb *t, uintptr_t addr, uintptr_t sp)
{
	uintptr_t lo = (uintptr_t)t->co.stack_lo;

	return (addr >= (uintptr_t)t->co.map_base && addr < lo) || (sp < lo && sp + FRAME_REACH >= lo);
}

/* Appends t's configured name, or its ID. */
static void put_task_name(struct text *r, const struct tcb *t)
{
	if (t->cfg->name != NULL) {
		put_str(r, t->cfg->name);
	} else {
		put_str(r, "ID ");
		put_uint(r, (unsigned long long)t->id, 10, 1);
	}
}

/* The context as rtos_host_context_name names it, without snprintf. */
static void put_context(struct text *r)
{
	static const char *const kinds[] = {
		[EXEC_ISR] = "isr ", [EXEC_CYC] = "cyclic ", [EXEC_ALM] = "alarm ",
	};

	switch (cpu.kind) {
	case EXEC_TASK:
		put_str(r, "task ");
		if (runtsk != NULL)
			put_task_name(r, runtsk);
		break;
	case EXEC_ISR:
	case EXEC_CYC:
	case EXEC_ALM:
		put_str(r, kinds[cpu.kind]);
		put_uint(r, (unsigned long long)cpu.exec_id, 10, 1);
		break;
	case EXEC_INIT:
		put_str(r, "init");
		break;
	case EXEC_EVENT:
		put_str(r, "a device event");
		break;
	default:
		put_str(r, "the harness (idle)");
		break;
	}
}

/* The signal's name and what its code says. */
static const char *signal_text(int sig, int code)
{
	switch (sig) {
	case SIGSEGV:
		return code == SEGV_ACCERR ? "SIGSEGV (invalid permissions for the address)"
					   : "SIGSEGV (address not mapped)";
	case SIGBUS:
		return code == BUS_ADRALN ? "SIGBUS (misaligned address)" : "SIGBUS (bus error)";
	case SIGFPE:
		return code == FPE_INTDIV ? "SIGFPE (integer division by zero)" :
		       code == FPE_INTOVF ? "SIGFPE (integer overflow)" : "SIGFPE (arithmetic exception)";
	case SIGILL:
		return "SIGILL (illegal instruction)";
	case SIGABRT:
		return "SIGABRT (abort() called)";
	default:
		return "signal";
	}
}

#if CRASH_ASAN
/* ASan's death callback: its report came after ours, the status is ours. */
static void asan_death(void)
{
	if (exit_status != 0)
		_exit(exit_status);
}
#endif

/* Hands the signal to the handler installed before ours, if it is one. */
static void chain(unsigned i, int sig, siginfo_t *si, void *uctx)
{
	const struct sigaction *p = &previous[i];

	if (p->sa_flags & SA_SIGINFO) {
		if (p->sa_sigaction != NULL)
			p->sa_sigaction(sig, si, uctx);
	} else if (p->sa_handler != SIG_DFL && p->sa_handler != SIG_IGN) {
		p->sa_handler(sig);
	}
}

/* The handler: the report, the previous handler's, then the kind's exit status. */
static void crash_signal(int sig, siginfo_t *si, void *uctx)
{
	char line[640], where[512];
	struct text r = { line, 0, sizeof(line) };
	uintptr_t pc, sp, addr = (uintptr_t)si->si_addr;
	struct tcb *t = cpu.kind == EXEC_TASK ? runtsk : NULL;
	bool overflow = false;
	struct sigaction ignore;
	unsigned i;

	/* the stall watch must not take a slow report (addr2line, ASan's) for a stall: the
	 * process ends here, and ASan's report unblocks signals on its way */
	memset(&ignore, 0, sizeof(ignore));
	ignore.sa_handler = SIG_IGN;
	(void)sigaction(SIGALRM, &ignore, NULL);
	context_pc_sp(uctx, &pc, &sp);
	if (sig == SIGSEGV || sig == SIGBUS) {
		struct tcb *owner = task_of_stack_address(sp);

		if (owner == NULL)
			owner = task_of_stack_address(addr);
		if (owner == NULL)
			owner = t;
		if (owner != NULL && past_stack_end(owner, addr, sp)) {
			overflow = true;
			t = owner;
		}
	}
	exit_status = overflow ? RTOS_HOST_EXIT_STACK : RTOS_HOST_EXIT_CRASH;
	if (overflow) {
		put_str(&r, "FATAL: stack overflow: task ");
		put_task_name(&r, t);
		put_str(&r, " ran off the end of its host stack (");
		put_uint(&r, t->co.stack_size, 10, 1);
		put_str(&r, " bytes; its configuration gives it ");
		put_uint(&r, t->cfg->stksz, 10, 1);
		put_str(&r, "): ");
		put_str(&r, signal_text(sig, si->si_code));
		put_str(&r, " at address ");
		put_hex(&r, addr);
	} else {
		put_str(&r, "FATAL: crash: ");
		put_str(&r, signal_text(sig, si->si_code));
		if (sig != SIGABRT) {
			put_str(&r, " at address ");
			put_hex(&r, addr);
		}
		put_str(&r, " in ");
		put_context(&r);
	}
	put_str(&r, " at t=");
	put_uint(&r, now_ns, 10, 1);
	put_str(&r, " ns\n");
	write_all(STDERR_FILENO, line, r.len);
	r.len = 0;
	put_str(&r, overflow ? "FATAL: stack overflow: PC " : "FATAL: crash: PC ");
	put_hex(&r, pc);
	if (sig != SIGABRT && rtos_host_source_line(pc, where, sizeof(where))) {
		put_str(&r, ": ");
		put_str(&r, where);
	} else if (sig == SIGABRT) {
		put_str(&r, " (in abort(); the caller is further up the stack)");
	} else {
		put_str(&r, " (no source line: is addr2line from binutils installed?)");
	}
	put_str(&r, "\n");
	write_all(STDERR_FILENO, line, r.len);
	for (i = 0; i < NFATAL && fatal_signals[i] != sig; i++)
		;
	/* ASan's report (its death callback exits with our status), or a fuzzer's, which
	 * keeps the input that crashed; the default action is not taken: our status stands */
	if (i < NFATAL)
		chain(i, sig, si, uctx);
	_exit(exit_status);
}

/* The alternate signal stack: auto-disarming where the kernel can. */
static bool alt_stack_install(void)
{
	size_t page = (size_t)sysconf(_SC_PAGESIZE);
	char *map = mmap(NULL, ALT_STACK_SIZE + page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
			 -1, 0);
	stack_t ss;

	if (map == MAP_FAILED)
		return false;
	(void)mprotect(map, page, PROT_NONE);   /* a handler overflowing it faults */
	ss.ss_sp = map + page;
	ss.ss_size = ALT_STACK_SIZE;
	ss.ss_flags = (int)SS_AUTODISARM;
	if (sigaltstack(&ss, NULL) == 0) {
		stack_disarms = true;
		return true;
	}
	ss.ss_flags = 0;
	if (sigaltstack(&ss, NULL) == 0)
		return true;
	munmap(map, ALT_STACK_SIZE + page);
	return false;
}

void rtos_host_crash_install(void)
{
	struct sigaction sa;

	if (installed)
		return;
	installed = true;
	find_program();
	if (!alt_stack_install())
		return;
	memset(&sa, 0, sizeof(sa));
	sa.sa_sigaction = crash_signal;
	sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
	sigemptyset(&sa.sa_mask);
	sigaddset(&sa.sa_mask, SIGALRM);   /* no stall report until the handler has ignored it */
	for (unsigned i = 0; i < NFATAL; i++)
		(void)sigaction(fatal_signals[i], &sa, &previous[i]);
#if CRASH_ASAN
	__sanitizer_set_death_callback(asan_death);
#endif
}

bool rtos_host_signal_stack_disarms(void)
{
	return stack_disarms;
}

/* ---- Stack use against the configured size ---- */

void stack_use_record(struct tcb *t, size_t used)
{
	t->stack_used = used;
	if (used <= t->cfg->stksz + RTOS_HOST_STACK_SLACK || kernel_stack_overrun)
		return;
	kernel_stack_overrun = true;
	rtos_host_bug("stack", "task %s used %zu bytes of stack, more than the %zu bytes its configuration "
		      "gives it (stksz) and the host's %u bytes of slack (measured at its service calls)",
		      t->cfg->name != NULL ? t->cfg->name : "?", used, (size_t)t->cfg->stksz,
		      RTOS_HOST_STACK_SLACK);
	ext_ker();
}

size_t rtos_host_task_stack_used(ID tskid)
{
	return tskid >= 1 && tskid <= TNUM_TSKID && tcb_table[tskid] != NULL ? tcb_table[tskid]->stack_used : 0;
}

int rtos_host_end_status(void)
{
	if (kernel_stalled)
		return RTOS_HOST_EXIT_STALL;
	if (kernel_stack_overrun)
		return RTOS_HOST_EXIT_STACK;
	return 0;
}
