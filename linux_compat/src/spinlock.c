/*
 * spinlock.c — interrupt masking (local_irq_*) and spin locks on one CPU.
 *
 * spin_lock_irqsave masks interrupts (the CPSR I/F bits on the AM1808) and
 * makes one bookkeeping call (interrupt-off depth and preempt count,
 * linux_compat/context.h); the lock word is checked for recursion and free
 * unlocks only with LX_DEBUG_SPINLOCK.
 */
#include <linux/spinlock.h>
#include <linux/kernel.h>
#include <linux_compat/context.h>
#include <linux_compat/irqmask.h>
#include <linux_compat/report.h>
#include <linux_compat/sched.h>
#include <sil.h>

#if !defined(EV3LX_AM1808)
/* Host: the host kernel's interrupt mask (sil.h's host target). */
unsigned long lx_irq_mask_save(void)
{
	return sil_host_loc_int();
}

void lx_irq_mask_restore(unsigned long saved)
{
	sil_host_unl_int((uint_t)saved);
}
#endif

static bool irq_disabled_by_disable;   /* local_irq_disable is in effect */
static unsigned long irq_disable_saved; /* state to return to at local_irq_enable */

/* Masks all interrupts; returns the previous state. */
unsigned long arch_local_irq_save(void)
{
	unsigned long flags = lx_irq_mask_save();

	lx_irqs_off_enter();
	return flags;
}

/* Returns to the interrupt state flags describes. */
void arch_local_irq_restore(unsigned long flags)
{
	lx_irqs_off_exit();
	lx_irq_mask_restore(flags);
	lx_deferred_wakeups_run();
}

/* Masks interrupts until local_irq_enable (does not nest). */
void arch_local_irq_disable(void)
{
	unsigned long flags;

	if (irq_disabled_by_disable)
		return;
	flags = arch_local_irq_save();
	irq_disable_saved = flags;
	irq_disabled_by_disable = true;
}

/* Ends local_irq_disable: back to the state before it. */
void arch_local_irq_enable(void)
{
	if (!irq_disabled_by_disable)
		return;
	irq_disabled_by_disable = false;
	arch_local_irq_restore(irq_disable_saved);
}

/* Initialises lock as unlocked. */
void lx_spin_lock_init(spinlock_t *lock, const char *name)
{
	lock->locked = 0;
	lock->irq_disabled = 0;
	lock->saved_flags = 0;
	lock->name = name;
}

#if LX_DEBUG_SPINLOCK
/* Marks lock held, reporting the deadlock a held lock would be. */
static void take(spinlock_t *lock, const char *file, int line)
{
	char why[96];

	if (lock->locked) {
		lx_context_forbids_sleep(why, sizeof(why));
		lx_report("spinlock recursion (deadlock)", file, line,
			  "lock %s is already held; taken again in %s - did a task take it "
			  "without disabling the interrupt that also takes it?",
			  lock->name ? lock->name : "?", why);
	}
	lock->locked = 1;
}

/* Marks lock free, reporting an unlock of a free lock. */
static void give(spinlock_t *lock, const char *file, int line)
{
	if (!lock->locked)
		lx_report("spin_unlock of an unlocked lock", file, line, "lock %s",
			  lock->name ? lock->name : "?");
	lock->locked = 0;
}
#else
/* Marks lock held (unchecked). */
static inline void take(spinlock_t *lock, const char *file, int line)
{
	(void)file;
	(void)line;
	lock->locked = 1;
}

/* Marks lock free (unchecked). */
static inline void give(spinlock_t *lock, const char *file, int line)
{
	(void)file;
	(void)line;
	lock->locked = 0;
}
#endif

/* Atomic section + lock. */
void lx_spin_lock(spinlock_t *lock, const char *file, int line)
{
	lx_atomic_enter(true);
	take(lock, file, line);
}

/* Unlock + end of atomic section. */
void lx_spin_unlock(spinlock_t *lock, const char *file, int line)
{
	give(lock, file, line);
	lx_atomic_exit(true);
}

/* Takes lock if free. */
int lx_spin_trylock(spinlock_t *lock)
{
	lx_atomic_enter(true);
	if (lock->locked) {
		lx_atomic_exit(true);
		return 0;
	}
	lock->locked = 1;
	return 1;
}

/* Interrupts masked, then the lock. */
unsigned long lx_spin_lock_irqsave(spinlock_t *lock, const char *file, int line)
{
	unsigned long flags = lx_irq_mask_save();

	lx_irqs_off_atomic_enter();
	take(lock, file, line);
	return flags;
}

/* The lock, then the interrupt state back. */
void lx_spin_unlock_irqrestore(spinlock_t *lock, unsigned long flags, const char *file, int line)
{
	give(lock, file, line);
	lx_irqs_off_atomic_exit();
	lx_irq_mask_restore(flags);
	/* A wake_up under the lock takes effect here, Linux's preemption point. */
	lx_deferred_wakeups_run();
}

/* Interrupts masked (state kept in the lock), then the lock. */
void lx_spin_lock_irq(spinlock_t *lock, const char *file, int line)
{
	unsigned long flags = arch_local_irq_save();

	lx_spin_lock(lock, file, line);
	lock->saved_flags = flags;
	lock->irq_disabled = 1;
}

/* Releases a lock taken by spin_lock_irq; interrupts back as before it. */
void lx_spin_unlock_irq(spinlock_t *lock, const char *file, int line)
{
	unsigned long flags = lock->saved_flags;
	bool masked = lock->irq_disabled;

	lock->irq_disabled = 0;
	lx_spin_unlock(lock, file, line);
	if (masked)
		arch_local_irq_restore(flags);
	else
		lx_report("spin_unlock_irq without spin_lock_irq", file, line, "lock %s",
			  lock->name ? lock->name : "?");
}

/* timer_list callbacks held off, then the lock. */
void lx_spin_lock_bh(spinlock_t *lock, const char *file, int line)
{
	lx_bh_disable();
	lx_spin_lock(lock, file, line);
}

/* The lock, then timer_list callbacks allowed again. */
void lx_spin_unlock_bh(spinlock_t *lock, const char *file, int line)
{
	lx_spin_unlock(lock, file, line);
	lx_bh_enable();
}
