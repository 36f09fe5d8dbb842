/*
 * linux/spinlock.h — spin locks on a uniprocessor.
 *
 * As Linux on one CPU: spin_lock disables preemption (in a task: dispatching,
 * so no other task runs until the unlock) and counts as an atomic section;
 * the _irqsave/_irq forms also mask interrupts with SIL_LOC_INT, the _bh
 * forms hold off timer_list callbacks.  Unlike a non-debug Linux UP build, the
 * lock word is kept: taking a lock that is already held (the task/IRQ
 * deadlock an SMP machine would hit) and unlocking a free lock are reported.
 * Readers/writer locks are plain spin locks here.
 */
#ifndef _LINUX_SPINLOCK_H
#define _LINUX_SPINLOCK_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/typecheck.h>
#include <linux/preempt.h>
#include <linux/irqflags.h>
#include <linux/bottom_half.h>
#include <linux/spinlock_types.h>
#include <linux/atomic.h>
#include <linux_compat/context.h>
#include <linux_compat/irqmask.h>
#include <linux_compat/sched.h>

/* Initialises lock as unlocked. */
void lx_spin_lock_init(spinlock_t *lock, const char *name);
/* Opens an atomic section and takes lock (reports a held lock); file/line: call site. */
void lx_spin_lock(spinlock_t *lock, const char *file, int line);
/* Releases lock and closes the atomic section. */
void lx_spin_unlock(spinlock_t *lock, const char *file, int line);
/* Takes lock if free: 1, else 0. */
int lx_spin_trylock(spinlock_t *lock);
/* Masks interrupts, then takes lock; returns the interrupt state to restore. */
unsigned long lx_spin_lock_irqsave(spinlock_t *lock, const char *file, int line);
/* Releases lock, then restores the interrupt state. */
void lx_spin_unlock_irqrestore(spinlock_t *lock, unsigned long flags, const char *file, int line);
/* spin_lock with interrupts masked / timer_list callbacks held off, state kept in the lock. */
void lx_spin_lock_irq(spinlock_t *lock, const char *file, int line);
void lx_spin_unlock_irq(spinlock_t *lock, const char *file, int line);
void lx_spin_lock_bh(spinlock_t *lock, const char *file, int line);
void lx_spin_unlock_bh(spinlock_t *lock, const char *file, int line);

#define spin_lock_init(lock)		lx_spin_lock_init((lock), #lock)
#define spin_lock(lock)			lx_spin_lock((lock), __FILE__, __LINE__)
#define spin_unlock(lock)		lx_spin_unlock((lock), __FILE__, __LINE__)
#define spin_trylock(lock)		lx_spin_trylock(lock)
#if LX_DEBUG_SPINLOCK || LX_DEBUG_ATOMIC_SLEEP
#define spin_lock_irqsave(lock, flags) \
	do { typecheck(unsigned long, flags); \
	     (flags) = lx_spin_lock_irqsave((lock), __FILE__, __LINE__); } while (0)
#define spin_unlock_irqrestore(lock, flags) \
	do { typecheck(unsigned long, flags); \
	     lx_spin_unlock_irqrestore((lock), (flags), __FILE__, __LINE__); } while (0)
#else
/*
 * The production build (no lock checks, one preempt count, as a non-debug
 * uniprocessor Linux): spin_lock_irqsave is inline — interrupts masked, the
 * interrupt-off depth and the preempt count up (with interrupts masked no
 * dispatcher call is needed) — and so is the common unlock; an unbalanced one
 * takes the out-of-line path, which reports it.
 */
static __always_inline unsigned long lx_spin_lock_irqsave_up(spinlock_t *lock)
{
	unsigned long flags = lx_irq_mask_save();

	lx_irqs_off_atomic_enter_up();
	lock->locked = 1;
	return flags;
}

static __always_inline void lx_spin_unlock_irqrestore_up(spinlock_t *lock, unsigned long flags,
							  const char *file, int line)
{
	if (unlikely(lx_ctx.irqs_off == 0 || lx_ctx.preempt == 0 ||
		     (lx_ctx.preempt == 1 && lx_ctx.dispatch_disabled_by_us))) {
		lx_spin_unlock_irqrestore(lock, flags, file, line);
		return;
	}
	lock->locked = 0;
	lx_ctx.preempt--;
	lx_ctx.irqs_off--;
	lx_irq_mask_restore(flags);
	/* a wake_up under the lock takes effect here, Linux's preemption point */
	if (unlikely(lx_deferred_wake_pending))
		lx_deferred_wakeups_run();
}

#define spin_lock_irqsave(lock, flags) \
	do { typecheck(unsigned long, flags); \
	     (flags) = lx_spin_lock_irqsave_up(lock); } while (0)
#define spin_unlock_irqrestore(lock, flags) \
	do { typecheck(unsigned long, flags); \
	     lx_spin_unlock_irqrestore_up((lock), (flags), __FILE__, __LINE__); } while (0)
#endif
#define spin_lock_irq(lock)		lx_spin_lock_irq((lock), __FILE__, __LINE__)
#define spin_unlock_irq(lock)		lx_spin_unlock_irq((lock), __FILE__, __LINE__)
#define spin_lock_bh(lock)		lx_spin_lock_bh((lock), __FILE__, __LINE__)
#define spin_unlock_bh(lock)		lx_spin_unlock_bh((lock), __FILE__, __LINE__)
#define spin_lock_nested(lock, sub)	spin_lock(lock)
#define spin_lock_irqsave_nested(lock, flags, sub) spin_lock_irqsave(lock, flags)
#define spin_is_locked(lock)		((lock)->locked != 0)
#define assert_spin_locked(lock)	WARN_ON(!spin_is_locked(lock))
#define lockdep_assert_held(lock)	do { (void)(lock); } while (0)

#define raw_spin_lock_init(lock)		spin_lock_init(lock)
#define raw_spin_lock(lock)			spin_lock(lock)
#define raw_spin_unlock(lock)			spin_unlock(lock)
#define raw_spin_lock_irqsave(lock, flags)	spin_lock_irqsave(lock, flags)
#define raw_spin_unlock_irqrestore(lock, flags)	spin_unlock_irqrestore(lock, flags)
#define raw_spin_lock_irq(lock)			spin_lock_irq(lock)
#define raw_spin_unlock_irq(lock)		spin_unlock_irq(lock)

/* Readers never exclude each other (a task and an interrupt may both read):
 * the read side is an atomic section without the lock word. */
#define rwlock_init(rw)			spin_lock_init(&(rw)->lock)
#define read_lock(rw)			do { (void)(rw); lx_atomic_enter(true); } while (0)
#define read_unlock(rw)			do { (void)(rw); lx_atomic_exit(true); } while (0)
#define read_lock_irqsave(rw, flags) \
	do { (void)(rw); local_irq_save(flags); lx_atomic_enter(true); } while (0)
#define read_unlock_irqrestore(rw, flags) \
	do { (void)(rw); lx_atomic_exit(true); local_irq_restore(flags); } while (0)
#define read_lock_irq(rw)		do { (void)(rw); local_irq_disable(); lx_atomic_enter(true); } while (0)
#define read_unlock_irq(rw)		do { (void)(rw); lx_atomic_exit(true); local_irq_enable(); } while (0)
#define read_lock_bh(rw)		do { (void)(rw); local_bh_disable(); lx_atomic_enter(true); } while (0)
#define read_unlock_bh(rw)		do { (void)(rw); lx_atomic_exit(true); local_bh_enable(); } while (0)
#define write_lock(rw)			spin_lock(&(rw)->lock)
#define write_unlock(rw)		spin_unlock(&(rw)->lock)
#define write_lock_irqsave(rw, flags)	spin_lock_irqsave(&(rw)->lock, flags)
#define write_unlock_irqrestore(rw, flags) spin_unlock_irqrestore(&(rw)->lock, flags)
#define write_lock_irq(rw)		spin_lock_irq(&(rw)->lock)
#define write_unlock_irq(rw)		spin_unlock_irq(&(rw)->lock)
#define write_lock_bh(rw)		spin_lock_bh(&(rw)->lock)
#define write_unlock_bh(rw)		spin_unlock_bh(&(rw)->lock)

#endif /* _LINUX_SPINLOCK_H */
