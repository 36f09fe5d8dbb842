/*
 * linux_compat/debug.h — build switches for linux_compat's debugging checks,
 * as Linux's CONFIG_DEBUG_ATOMIC_SLEEP and CONFIG_DEBUG_SPINLOCK.
 *
 * LX_DEBUG_ATOMIC_SLEEP (1: on)
 *   might_sleep() and every call that may sleep (copy_*_user, kmalloc with
 *   GFP_KERNEL, request_irq, misc_register, ...) report a call from a context
 *   that may not sleep, naming the context; for that the atomic depth is kept
 *   per context (task / interrupt) and per kind (spin lock / preempt_disable).
 *   Off: might_sleep() and those annotations are nothing, and one preempt
 *   count is kept, as Linux without the option.  In both builds the calls that
 *   really sleep (msleep, schedule_timeout, down, wait_event, mutex_lock,
 *   flush_work, ...) refuse to sleep in atomic context and report it, as
 *   Linux's "scheduling while atomic" does without any debug option.
 * LX_DEBUG_SPINLOCK (1: on)
 *   Taking a spin lock that is held (the task/interrupt deadlock an SMP
 *   machine would hit) and unlocking a free one are reported.  Off: the lock
 *   word is still kept (spin_trylock, spin_is_locked) but nothing is checked.
 *
 * Both default to on: the host configurations, whose tests rely on the
 * reports.  The AM1808 library is built with both off (mk/am1808.mk), and so
 * is the bench's production variant (mk/bench.mk).
 */
#ifndef _LINUX_COMPAT_DEBUG_H
#define _LINUX_COMPAT_DEBUG_H

#ifndef LX_DEBUG_ATOMIC_SLEEP
#define LX_DEBUG_ATOMIC_SLEEP	1
#endif

#ifndef LX_DEBUG_SPINLOCK
#define LX_DEBUG_SPINLOCK	1
#endif

#endif /* _LINUX_COMPAT_DEBUG_H */
