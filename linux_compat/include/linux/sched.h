/*
 * linux/sched.h — tasks as Linux sees them: every RTOS task has a
 * task_struct (pid = task ID); `current` is the calling task's.
 *
 * There are no signals: signal_pending() is always false, and an
 * "interruptible" sleep is interrupted only by rel_wai on the task.
 */
#ifndef _LINUX_SCHED_H
#define _LINUX_SCHED_H

#include <linux/types.h>
#include <linux/kernel.h>
#include <linux/jiffies.h>
#include <linux/preempt.h>

#define TASK_RUNNING		0x0000
#define TASK_INTERRUPTIBLE	0x0001
#define TASK_UNINTERRUPTIBLE	0x0002
#define TASK_KILLABLE		(TASK_UNINTERRUPTIBLE | 0x0100)
#define TASK_IDLE		(TASK_UNINTERRUPTIBLE | 0x0400)
#define TASK_NORMAL		(TASK_INTERRUPTIBLE | TASK_UNINTERRUPTIBLE)

#define TASK_COMM_LEN		16
#define MAX_SCHEDULE_TIMEOUT	LONG_MAX

typedef int pid_t;

struct task_struct {
	pid_t pid;                   /* the RTOS task ID (0: non-task context) */
	volatile unsigned int __state;
	char comm[TASK_COMM_LEN];
};

/* The calling task's task_struct. */
struct task_struct *lx_get_current(void);
#define current		lx_get_current()

#define __set_current_state(state_value)	(current->__state = (state_value))
#define set_current_state(state_value) \
	do { current->__state = (state_value); barrier(); } while (0)

/* Sleeps (state set by set_current_state) until wake_up_process or timeout jiffies; jiffies left. */
long schedule_timeout(long timeout);
long schedule_timeout_interruptible(long timeout);
long schedule_timeout_uninterruptible(long timeout);
#define schedule_timeout_killable(t)	schedule_timeout_uninterruptible(t)
#define schedule_timeout_idle(t)	schedule_timeout_uninterruptible(t)
/* Sleeps until wake_up_process (returns at once in TASK_RUNNING). */
void schedule(void);
/* Makes p running again; 1 if it was asleep.  Any context. */
int wake_up_process(struct task_struct *p);
/* Lets other ready tasks of the same priority run. */
void yield(void);

/* Preemption is by priority: there is never a pending reschedule to honour. */
static inline int cond_resched(void)		{ return 0; }
static inline int need_resched(void)		{ return 0; }
static inline int signal_pending(struct task_struct *p)	{ (void)p; return 0; }
static inline int fatal_signal_pending(struct task_struct *p) { (void)p; return 0; }
static inline int signal_pending_state(unsigned int state, struct task_struct *p)
{
	(void)state;
	(void)p;
	return 0;
}
static inline pid_t task_pid_nr(struct task_struct *tsk)	{ return tsk->pid; }

#endif /* _LINUX_SCHED_H */
