/*
 * mutex.c — Linux mutexes on the wait core, with owner checks.
 */
#include <linux/mutex.h>
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux_compat/waitcore.h>
#include <linux_compat/context.h>
#include <linux_compat/report.h>
#include <sil.h>
#include <kernel.h>

/* Initialises lock as unlocked. */
void lx_mutex_init(struct mutex *lock, const char *name)
{
	lock->free = 1;
	lock->waiters.head = lock->waiters.tail = NULL;
	lock->owner = TSK_NONE;
	lock->name = name;
}

/* Reports use from interrupt context; true if the context is a task. */
static bool in_task_context(struct mutex *lock, const char *what, const char *file, int line)
{
	char why[96];

	if (!lx_in_interrupt())
		return true;
	lx_context_forbids_sleep(why, sizeof(why));
	lx_report("mutex used in interrupt context", file, line, "%s on %s in %s", what,
		  lock->name ? lock->name : "?", why);
	return false;
}

/* Common lock path: 0 when owned, else the error. */
static int lock_common(struct mutex *lock, bool interruptible, const char *what,
		       const char *file, int line)
{
	ID self = lx_current_tskid();
	int ret;

	if (self != TSK_NONE && lock->owner == self) {
		lx_report("mutex deadlock", file, line, "%s: task %d already holds %s", what,
			  (int)self, lock->name ? lock->name : "?");
		return -EDEADLK;
	}
	ret = lx_count_acquire(&lock->free, &lock->waiters, U64_MAX, interruptible,
			       what, file, line);
	if (ret == 0)
		lock->owner = self;
	return ret;
}

/* Locks, sleeping as needed. */
void lx_mutex_lock_at(struct mutex *lock, const char *file, int line)
{
	(void)lock_common(lock, false, "mutex_lock()", file, line);
}

/* Locks; 0 or -EINTR. */
int lx_mutex_lock_interruptible_at(struct mutex *lock, const char *file, int line)
{
	return lock_common(lock, true, "mutex_lock_interruptible()", file, line);
}

/* 1 if acquired without sleeping. */
int lx_mutex_trylock_at(struct mutex *lock, const char *file, int line)
{
	(void)in_task_context(lock, "mutex_trylock()", file, line);
	if (!lx_count_tryacquire(&lock->free))
		return 0;
	lock->owner = lx_current_tskid();
	return 1;
}

/* Unlocks (hands over to the oldest waiter). */
void lx_mutex_unlock_at(struct mutex *lock, const char *file, int line)
{
	ID self = lx_current_tskid();

	(void)in_task_context(lock, "mutex_unlock()", file, line);
	if (lock->free) {
		lx_report("mutex_unlock of an unlocked mutex", file, line, "%s",
			  lock->name ? lock->name : "?");
		return;
	}
	if (lock->owner != self)
		lx_report("mutex_unlock by a task that does not hold it", file, line,
			  "%s held by task %d, unlocked by task %d", lock->name ? lock->name : "?",
			  (int)lock->owner, (int)self);
	lock->owner = TSK_NONE;
	lx_count_release(&lock->free, &lock->waiters);
}

/* True while held. */
bool mutex_is_locked(struct mutex *lock)
{
	return lock->free == 0;
}

void (mutex_lock)(struct mutex *lock)
{
	lx_mutex_lock_at(lock, NULL, 0);
}

int (mutex_lock_interruptible)(struct mutex *lock)
{
	return lx_mutex_lock_interruptible_at(lock, NULL, 0);
}

int (mutex_lock_killable)(struct mutex *lock)
{
	return lx_mutex_lock_interruptible_at(lock, NULL, 0);
}

void (mutex_unlock)(struct mutex *lock)
{
	lx_mutex_unlock_at(lock, NULL, 0);
}

int (mutex_trylock)(struct mutex *lock)
{
	return lx_mutex_trylock_at(lock, NULL, 0);
}
