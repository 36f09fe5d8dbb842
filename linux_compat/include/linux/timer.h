/*
 * linux/timer.h — timer_list: jiffy-resolution timers.
 *
 * Served by linux_compat's tick ISR (linux_compat/src/timer.c): a timer runs
 * at the first tick where jiffies has reached its expiry, in interrupt
 * context (Linux runs them in softirq context: atomic either way), after
 * the hrtimers due at that tick.  While a task holds a spin_lock_bh /
 * local_bh_disable section, timer_list callbacks wait for the next tick.
 */
#ifndef _LINUX_TIMER_H
#define _LINUX_TIMER_H

#include <linux/types.h>
#include <linux/list.h>
#include <linux/jiffies.h>
#include <linux/ktime.h>
#include <linux/kernel.h>
#include <linux_compat/timerheap.h>

struct timer_list {
	unsigned long expires;                  /* in jiffies */
	void (*function)(struct timer_list *);
	u32 flags;
	/* Private to the engine. */
	struct lx_heap_node lx_node;            /* in the queue (while lx_pending) */
	u32 lx_magic;
	u8 lx_pending;
};

#define LX_TIMER_MAGIC		0x746c6973U    /* "tlis": set up by timer_setup / DEFINE_TIMER */

#define TIMER_DEFERRABLE	0x00080000U
#define TIMER_PINNED		0x00100000U
#define TIMER_IRQSAFE		0x00200000U

/* Prepares timer with callback fn; any context. */
void timer_setup(struct timer_list *timer, void (*fn)(struct timer_list *), unsigned int flags);
#define timer_setup_on_stack(timer, fn, flags)	timer_setup((timer), (fn), (flags))
#define destroy_timer_on_stack(timer)		do { } while (0)

#define DEFINE_TIMER(_name, _function)					\
	struct timer_list _name = { .function = (_function), .lx_magic = LX_TIMER_MAGIC }

#define from_timer(var, callback_timer, timer_fieldname) \
	container_of(callback_timer, __typeof__(*var), timer_fieldname)

/* Queues a timer not pending, at timer->expires (reported if already pending). */
void add_timer(struct timer_list *timer);
/* (Re)queues timer at expires; 1 if it was pending, 0 if not. */
int mod_timer(struct timer_list *timer, unsigned long expires);
/* mod_timer that only ever moves a pending timer earlier. */
int timer_reduce(struct timer_list *timer, unsigned long expires);
/* Dequeues timer; 1 if it was pending. */
int del_timer(struct timer_list *timer);
/* del_timer, and the callback is not running on return (reported if called from it). */
int del_timer_sync(struct timer_list *timer);
int lx_del_timer_sync_at(struct timer_list *timer, const char *file, int line);
#define del_timer_sync(timer)	lx_del_timer_sync_at((timer), __FILE__, __LINE__)
#define timer_delete(t)		del_timer(t)
#define timer_delete_sync(t)	del_timer_sync(t)
#define try_to_del_timer_sync(t) del_timer(t)
/* Dequeues and forbids re-arming: here as del_timer_sync. */
#define timer_shutdown_sync(t)	del_timer_sync(t)

/* True if timer is queued. */
static inline int timer_pending(const struct timer_list *timer)
{
	return timer->lx_pending;
}

#endif /* _LINUX_TIMER_H */
