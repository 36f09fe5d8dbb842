/* linux/spinlock_types.h — spinlock_t and its static initialisers. */
#ifndef _LINUX_SPINLOCK_TYPES_H
#define _LINUX_SPINLOCK_TYPES_H

#include <linux/types.h>

typedef struct spinlock {
	volatile u8 locked;          /* held: a second acquisition is a reported deadlock */
	u8 irq_disabled;             /* spin_lock_irq / _bh saved state below is live */
	unsigned long saved_flags;   /* interrupt state for spin_unlock_irq / _bh */
	const char *name;
} spinlock_t;

typedef spinlock_t raw_spinlock_t;

typedef struct {
	spinlock_t lock;
} rwlock_t;

#define __SPIN_LOCK_UNLOCKED(lockname)	{ .locked = 0, .name = #lockname }
#define DEFINE_SPINLOCK(x)		spinlock_t x = __SPIN_LOCK_UNLOCKED(x)
#define DEFINE_RAW_SPINLOCK(x)		DEFINE_SPINLOCK(x)
#define __RW_LOCK_UNLOCKED(lockname)	{ .lock = __SPIN_LOCK_UNLOCKED(lockname) }
#define DEFINE_RWLOCK(x)		rwlock_t x = __RW_LOCK_UNLOCKED(x)

#endif /* _LINUX_SPINLOCK_TYPES_H */
