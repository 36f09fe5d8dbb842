/*
 * linux/semaphore.h — counting semaphores, implemented natively (a count
 * and a FIFO list of sleeping tasks; linux_compat/src/semaphore.c).
 *
 * down_trylock and up are legal in every context - interrupt handlers,
 * timer callbacks, with interrupts or the CPU locked - which TOPPERS's own
 * semaphores forbid.  The down variants sleep and may be called only where
 * sleeping is legal (reported otherwise, and they then return without the
 * semaphore: -EINTR / -ETIME for the int forms).  "Interruptible" means
 * released by rel_wai (there are no signals).
 */
#ifndef _LINUX_SEMAPHORE_H
#define _LINUX_SEMAPHORE_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux_compat/sched.h>

struct semaphore {
	unsigned int count;
	struct lx_waitlist waiters;   /* FIFO: up grants the oldest waiter */
};

#define __SEMAPHORE_INITIALIZER(name, n)	{ .count = (n), .waiters = { NULL, NULL } }
/* Linux >= 6.4 / 6.1 stable: DEFINE_SEMAPHORE(name) is a binary semaphore; an explicit count is accepted too. */
#define DEFINE_SEMAPHORE(name, ...) \
	struct semaphore name = __SEMAPHORE_INITIALIZER(name, __lx_sema_count(__VA_ARGS__))
#define __lx_sema_count(...)		__lx_sema_count_pick(, ##__VA_ARGS__, 1)
#define __lx_sema_count_pick(dummy, n, ...)	(n)

/* Sets the count to val with no waiters. */
void sema_init(struct semaphore *sem, int val);
/* Removed in 2.6.37: sema_init(sem, 1) / sema_init(sem, 0). */
#define init_MUTEX(sem)		sema_init((sem), 1)
#define init_MUTEX_LOCKED(sem)	sema_init((sem), 0)

/* Acquires, sleeping as long as needed. */
void down(struct semaphore *sem);
/* Acquires; 0, or -EINTR if released by rel_wai. */
int __must_check down_interruptible(struct semaphore *sem);
/* As down_interruptible (no signals exist to kill a task). */
int __must_check down_killable(struct semaphore *sem);
/* Acquires within timeout jiffies: 0, or -ETIME. */
int __must_check down_timeout(struct semaphore *sem, long timeout);
/* Acquires without sleeping: 0 if acquired, 1 if not (the opposite of mutex_trylock).  Any context. */
int __must_check down_trylock(struct semaphore *sem);
/* Releases: hands the semaphore to the oldest waiter, else counts up.  Any context. */
void up(struct semaphore *sem);

/* Call-site forms: a context report names the caller's file and line. */
void lx_down_at(struct semaphore *sem, const char *file, int line);
int __must_check lx_down_interruptible_at(struct semaphore *sem, const char *file, int line);
int __must_check lx_down_timeout_at(struct semaphore *sem, long timeout, const char *file, int line);
#define down(sem)			lx_down_at((sem), __FILE__, __LINE__)
#define down_interruptible(sem)		lx_down_interruptible_at((sem), __FILE__, __LINE__)
#define down_killable(sem)		lx_down_interruptible_at((sem), __FILE__, __LINE__)
#define down_timeout(sem, t)		lx_down_timeout_at((sem), (t), __FILE__, __LINE__)

#endif /* _LINUX_SEMAPHORE_H */
