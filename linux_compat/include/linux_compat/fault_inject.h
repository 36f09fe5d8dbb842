/*
 * linux_compat/fault_inject.h — allocation-failure injection, like Linux's
 * failslab (Documentation/fault-injection): make kmalloc and everything built
 * on it (kzalloc, kmemdup, kstrdup, vmalloc, kfifo_alloc, __get_free_pages...)
 * return NULL on purpose, so that a driver's error paths can be tested.
 *
 * Two modes, set from test code before a boot (the setting survives boots,
 * the allocation count restarts at each):
 *   - nth:         the nth allocation attempt after the boot fails (1 = the
 *                  first), and only that one - walking n over 1..count drives
 *                  an init through each of its failure points;
 *   - probability: each attempt fails with probability percent/100, drawn
 *                  from a deterministic generator seeded with seed (same seed,
 *                  same failures), at most times failures (-1: no limit).
 * An injected failure is counted in the heap statistics' failures and prints
 * no warning (as failslab with verbose=0).
 */
#ifndef _LINUX_COMPAT_FAULT_INJECT_H
#define _LINUX_COMPAT_FAULT_INJECT_H

#include <stdbool.h>
#include <linux/types.h>

/* Fails the nth allocation attempt of every boot (0: off). */
void lx_fail_alloc_nth(unsigned long nth);
/* Fails attempts with probability percent (0..100) from seed, at most times (-1: unlimited); 0: off. */
void lx_fail_alloc_random(unsigned int percent, uint32_t seed, long times);
/* Turns injection off. */
void lx_fail_alloc_off(void);
/* Allocation attempts since the boot (what nth counts). */
unsigned long lx_alloc_attempts(void);
/* Failures injected since the boot. */
unsigned long lx_alloc_injected_failures(void);

/* For kmalloc: counts an attempt and tells whether to fail it.  Interrupts locked. */
bool lx_fail_alloc_should_fail_locked(void);
/* Boot: restarts the attempt count and the generator (the setting stays). */
void lx_fail_alloc_boot(void);

#endif /* _LINUX_COMPAT_FAULT_INJECT_H */
