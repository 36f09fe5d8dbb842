/*
 * linux/mutex.h — sleeping mutual exclusion with an owner (task context only).
 *
 * Built on the semaphore wait core: FIFO hand-over to the oldest waiter.
 * Misuse Linux's mutex debugging would catch is reported: locking a mutex
 * the task already holds (deadlock), unlocking one it does not hold or an
 * unlocked one, and any use from interrupt context.
 */
#ifndef _LINUX_MUTEX_H
#define _LINUX_MUTEX_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux_compat/sched.h>

struct mutex {
	unsigned int free;           /* 1 = unlocked */
	struct lx_waitlist waiters;
	int owner;                   /* the holding task (a TOPPERS ID), 0 (TSK_NONE) if unlocked */
	const char *name;
};

#define __MUTEX_INITIALIZER(lockname) \
	{ .free = 1, .waiters = { NULL, NULL }, .owner = 0, .name = #lockname }
#define DEFINE_MUTEX(mutexname)	struct mutex mutexname = __MUTEX_INITIALIZER(mutexname)

/* Initialises lock as unlocked. */
void lx_mutex_init(struct mutex *lock, const char *name);
#define mutex_init(lock)	lx_mutex_init((lock), #lock)
#define mutex_destroy(lock)	do { (void)(lock); } while (0)

/* Locks, sleeping as needed (file/line: call site for reports). */
void lx_mutex_lock_at(struct mutex *lock, const char *file, int line);
/* Locks; 0, or -EINTR if released by rel_wai. */
int __must_check lx_mutex_lock_interruptible_at(struct mutex *lock, const char *file, int line);
/* Unlocks; reports unlocking by a non-owner or of an unlocked mutex. */
void lx_mutex_unlock_at(struct mutex *lock, const char *file, int line);
/* Locks without sleeping: 1 if acquired, 0 if not (the opposite of down_trylock). */
int lx_mutex_trylock_at(struct mutex *lock, const char *file, int line);

void mutex_lock(struct mutex *lock);
int __must_check mutex_lock_interruptible(struct mutex *lock);
int __must_check mutex_lock_killable(struct mutex *lock);
void mutex_unlock(struct mutex *lock);
int mutex_trylock(struct mutex *lock);
/* True while some task holds lock. */
bool mutex_is_locked(struct mutex *lock);

#define mutex_lock(lock)		lx_mutex_lock_at((lock), __FILE__, __LINE__)
#define mutex_lock_nested(lock, sub)	lx_mutex_lock_at((lock), __FILE__, __LINE__)
#define mutex_lock_interruptible(lock)	lx_mutex_lock_interruptible_at((lock), __FILE__, __LINE__)
#define mutex_lock_killable(lock)	lx_mutex_lock_interruptible_at((lock), __FILE__, __LINE__)
#define mutex_unlock(lock)		lx_mutex_unlock_at((lock), __FILE__, __LINE__)
#define mutex_trylock(lock)		lx_mutex_trylock_at((lock), __FILE__, __LINE__)

#endif /* _LINUX_MUTEX_H */
