/*
 * linux/signal.h — there are no POSIX signals in the RTOS: the types and
 * numbers exist so that drivers including this header compile; nothing
 * delivers a signal (signal_pending() is always false, linux/sched.h).
 */
#ifndef _LINUX_SIGNAL_H
#define _LINUX_SIGNAL_H

#include <linux/types.h>
#include <asm/siginfo.h>

#define SIGHUP		1
#define SIGINT		2
#define SIGQUIT		3
#define SIGKILL		9
#define SIGUSR1		10
#define SIGSEGV		11
#define SIGUSR2		12
#define SIGPIPE		13
#define SIGALRM		14
#define SIGTERM		15
#define SIGCHLD		17
#define SIGCONT		18
#define SIGSTOP		19
#define SIGIO		29
#define SIGPOLL		SIGIO

#endif /* _LINUX_SIGNAL_H */
