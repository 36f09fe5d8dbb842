/*
 * linux/rcupdate.h — RCU on one CPU without preemptible readers: a read-side
 * section is an atomic section (no task switch inside it), so waiting for a
 * grace period is waiting for every task to leave such sections, which has
 * happened by the time another task (the updater) runs.
 */
#ifndef _LINUX_RCUPDATE_H
#define _LINUX_RCUPDATE_H

#include <linux/compiler.h>
#include <linux/preempt.h>

#define rcu_read_lock()			preempt_disable()
#define rcu_read_unlock()		preempt_enable()
#define rcu_read_lock_bh()		preempt_disable()
#define rcu_read_unlock_bh()		preempt_enable()
#define rcu_dereference(p)		READ_ONCE(p)
#define rcu_dereference_protected(p, c)	(p)
#define rcu_dereference_raw(p)		READ_ONCE(p)
#define rcu_access_pointer(p)		READ_ONCE(p)
#define rcu_assign_pointer(p, v)	do { barrier(); WRITE_ONCE((p), (v)); } while (0)
#define RCU_INIT_POINTER(p, v)		((p) = (v))
#define RCU_INITIALIZER(v)		(v)

/* A grace period: every reader section began before now has ended (trivially, from a task). */
static inline void synchronize_rcu(void)	{ barrier(); }
static inline void rcu_barrier(void)		{ barrier(); }

#endif /* _LINUX_RCUPDATE_H */
