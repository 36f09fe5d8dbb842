/*
 * waitcore.c — counted sleeping acquisition (semaphores, mutexes, completions).
 */
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux_compat/waitcore.h>
#include <linux_compat/context.h>
#include <linux_compat/report.h>
#include <rtos_cfg.h>
#include <sil.h>

/* A unit, sleeping until granted, the deadline, or (if interruptible) rel_wai. */
int lx_count_acquire(unsigned int *count, struct lx_waitlist *wl, uint64_t deadline_ns,
		     bool interruptible, const char *what, const char *file, int line)
{
	struct lx_waiter w;
	int ret;
	SIL_PRE_LOC;

	if (!lx_might_sleep_check(what, file, line))
		return lx_count_tryacquire(count) ? 0 : -EINTR;
	lx_waiter_init(&w);
	SIL_LOC_INT();
	if (*count > 0 && lx_waitlist_empty(wl)) {
		(*count)--;
		SIL_UNL_INT();
		return 0;
	}
	lx_waitlist_add_locked(wl, &w);
	SIL_UNL_INT();
	for (;;) {
		ret = lx_waiter_sleep(&w, deadline_ns);
		if (ret == 0 || ret == -ETIME || interruptible)
			break;
	}
	if (ret != 0) {
		SIL_LOC_INT();
		if (w.woken)
			ret = 0;    /* granted just as the wait ended: keep it */
		else
			lx_waitlist_remove_locked(wl, &w);
		SIL_UNL_INT();
	}
	return ret;
}

/* A unit if one is free. */
bool lx_count_tryacquire(unsigned int *count)
{
	bool taken = false;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	if (*count > 0) {
		(*count)--;
		taken = true;
	}
	SIL_UNL_INT();
	return taken;
}

/* Grants the oldest waiter, else counts up. */
void lx_count_release(unsigned int *count, struct lx_waitlist *wl)
{
	struct lx_waiter *w;
	ID tskid = TSK_NONE;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	w = lx_waitlist_pop_locked(wl);
	if (w != NULL) {
		tskid = w->tskid;
		w->woken = true;   /* w may vanish once the lock is released */
	} else if (*count < UINT_MAX) {
		(*count)++;
	}
	SIL_UNL_INT();
	if (tskid != TSK_NONE)
		lx_wake_task(tskid);
}

/* Grants every waiter. */
unsigned int lx_waitlist_wake_all(struct lx_waitlist *wl)
{
	ID woken[TNUM_TSKID];
	unsigned int n = 0, i;
	struct lx_waiter *w;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	while ((w = lx_waitlist_pop_locked(wl)) != NULL) {
		w->woken = true;
		if (n < TNUM_TSKID)
			woken[n++] = w->tskid;
	}
	SIL_UNL_INT();
	for (i = 0; i < n; i++)
		lx_wake_task(woken[i]);
	return n;
}
