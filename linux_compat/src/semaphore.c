/*
 * semaphore.c — Linux counting semaphores on linux_compat's wait core.
 */
#include <linux/semaphore.h>
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux/jiffies.h>
#include <linux_compat/waitcore.h>
#include <linux_compat/report.h>

/* Sets the count; the semaphore must have no waiters. */
void sema_init(struct semaphore *sem, int val)
{
	if (sem == NULL)
		return;
	if (val < 0) {
		lx_report("sema_init", NULL, 0, "negative count %d (set to 0)", val);
		val = 0;
	}
	sem->count = (unsigned int)val;
	sem->waiters.head = sem->waiters.tail = NULL;
}

/* down with the caller's location for reports. */
void lx_down_at(struct semaphore *sem, const char *file, int line)
{
	(void)lx_count_acquire(&sem->count, &sem->waiters, U64_MAX, false, "down()", file, line);
}

/* down_interruptible with the caller's location: 0 or -EINTR. */
int lx_down_interruptible_at(struct semaphore *sem, const char *file, int line)
{
	return lx_count_acquire(&sem->count, &sem->waiters, U64_MAX, true,
				"down_interruptible()", file, line);
}

/* down_timeout with the caller's location: 0 or -ETIME. */
int lx_down_timeout_at(struct semaphore *sem, long timeout, const char *file, int line)
{
	uint64_t deadline = lx_deadline_after_ms(timeout < 0 ? 0 : (long)jiffies_to_msecs((unsigned long)timeout));
	int ret = lx_count_acquire(&sem->count, &sem->waiters, deadline, false,
				   "down_timeout()", file, line);

	return ret == 0 ? 0 : -ETIME;
}

/* Acquires, sleeping as long as needed. */
void (down)(struct semaphore *sem)
{
	lx_down_at(sem, NULL, 0);
}

/* Acquires; 0 or -EINTR. */
int (down_interruptible)(struct semaphore *sem)
{
	return lx_down_interruptible_at(sem, NULL, 0);
}

/* As down_interruptible. */
int (down_killable)(struct semaphore *sem)
{
	return lx_down_interruptible_at(sem, NULL, 0);
}

/* Acquires within timeout jiffies: 0 or -ETIME. */
int (down_timeout)(struct semaphore *sem, long timeout)
{
	return lx_down_timeout_at(sem, timeout, NULL, 0);
}

/* 0 if acquired without sleeping, 1 if not; any context. */
int down_trylock(struct semaphore *sem)
{
	return lx_count_tryacquire(&sem->count) ? 0 : 1;
}

/* Hands the semaphore to the oldest waiter or counts up; any context. */
void up(struct semaphore *sem)
{
	lx_count_release(&sem->count, &sem->waiters);
}
