/*
 * linux_compat/platform.h — what each target gives linux_compat's generic
 * core: one implementation in src/host/ (the simulated brick) and one in
 * src/am1808/ (the real one).  Nothing else in linux_compat depends on the
 * target.
 */
#ifndef _LINUX_COMPAT_PLATFORM_H
#define _LINUX_COMPAT_PLATFORM_H

#include <stddef.h>
#include <linux/types.h>

/* The CPU-visible window of the physical register range [phys, phys + size),
 * or NULL if there are no registers there.  Host: the window of the
 * installed register model; AM1808: the physical address (flat mapping). */
void *lx_platform_io_window(uintptr_t phys, size_t size);

/* Emits one report line "<what> at <file>:<line>: <detail>" (without the
 * location when file is NULL).  Host: a bug report that fails the test
 * unless expected; AM1808: a syslog line at LOG_EMERG. */
void lx_platform_report(const char *what, const char *file, int line, const char *detail);

/* Stops the system after a fatal report.  Host: aborts the process;
 * AM1808: masks interrupts and spins. */
void lx_platform_halt(void) __attribute__((__noreturn__));

/* Writes the name of the interrupt context the CPU is in ("interrupt
 * context", with the host kernel's name for it on the host). */
void lx_platform_describe_interrupt(char *buf, size_t len);

/* The boot command line ("" if none): its "module.param=value" words set
 * module parameters before the modules are initialised.  Host: the one the
 * simulated board hands over (rtos_host_boot_args); AM1808: the one the
 * firmware's start-up passed to lx_compat_set_boot_args. */
const char *lx_platform_boot_args(void);

#endif /* _LINUX_COMPAT_PLATFORM_H */
