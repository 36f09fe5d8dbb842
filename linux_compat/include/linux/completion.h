/*
 * linux/completion.h — completions: complete() from any context (interrupt
 * handlers included) wakes one waiter or is remembered; complete_all()
 * releases every present and future waiter until reinit_completion().
 */
#ifndef _LINUX_COMPLETION_H
#define _LINUX_COMPLETION_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux_compat/sched.h>

struct completion {
	unsigned int done;           /* completions not yet consumed; UINT_MAX after complete_all */
	struct lx_waitlist waiters;
};

#define COMPLETION_INITIALIZER(work)	{ .done = 0, .waiters = { NULL, NULL } }
#define COMPLETION_INITIALIZER_ONSTACK(work) COMPLETION_INITIALIZER(work)
#define DECLARE_COMPLETION(work)	struct completion work = COMPLETION_INITIALIZER(work)
#define DECLARE_COMPLETION_ONSTACK(work) DECLARE_COMPLETION(work)

/* Sets x to "not done" with no waiters. */
void init_completion(struct completion *x);
/* Sets x to "not done" again (waiters must be gone). */
void reinit_completion(struct completion *x);
/* Wakes the oldest waiter, or records one completion.  Any context. */
void complete(struct completion *x);
/* Completes x for every waiter, present and future.  Any context. */
void complete_all(struct completion *x);

/* Call-site forms (context reports name the caller). */
void lx_wait_for_completion_at(struct completion *x, const char *file, int line);
unsigned long lx_wait_for_completion_timeout_at(struct completion *x, unsigned long timeout,
						const char *file, int line);
int lx_wait_for_completion_interruptible_at(struct completion *x, const char *file, int line);
long lx_wait_for_completion_interruptible_timeout_at(struct completion *x, unsigned long timeout,
						     const char *file, int line);

/* Sleeps until x is completed. */
void wait_for_completion(struct completion *x);
/* ... at most timeout jiffies: the jiffies left (at least 1), or 0 on timeout. */
unsigned long __must_check wait_for_completion_timeout(struct completion *x, unsigned long timeout);
/* ... or until rel_wai: 0 or -ERESTARTSYS. */
int __must_check wait_for_completion_interruptible(struct completion *x);
/* ... with timeout: jiffies left, 0 on timeout, -ERESTARTSYS if released. */
long __must_check wait_for_completion_interruptible_timeout(struct completion *x, unsigned long timeout);
/* Consumes a completion without sleeping: true if there was one.  Any context. */
bool try_wait_for_completion(struct completion *x);
/* True if a wait would not sleep. */
bool completion_done(struct completion *x);

#define wait_for_completion(x)		lx_wait_for_completion_at((x), __FILE__, __LINE__)
#define wait_for_completion_io(x)	lx_wait_for_completion_at((x), __FILE__, __LINE__)
#define wait_for_completion_killable(x) lx_wait_for_completion_interruptible_at((x), __FILE__, __LINE__)
#define wait_for_completion_timeout(x, t) lx_wait_for_completion_timeout_at((x), (t), __FILE__, __LINE__)
#define wait_for_completion_io_timeout(x, t) lx_wait_for_completion_timeout_at((x), (t), __FILE__, __LINE__)
#define wait_for_completion_interruptible(x) \
	lx_wait_for_completion_interruptible_at((x), __FILE__, __LINE__)
#define wait_for_completion_interruptible_timeout(x, t) \
	lx_wait_for_completion_interruptible_timeout_at((x), (t), __FILE__, __LINE__)
#define wait_for_completion_killable_timeout(x, t) \
	lx_wait_for_completion_interruptible_timeout_at((x), (t), __FILE__, __LINE__)

#endif /* _LINUX_COMPLETION_H */
