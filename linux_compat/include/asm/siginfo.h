/*
 * asm/siginfo.h — signal information codes (no signals are ever delivered;
 * see linux/signal.h).
 */
#ifndef _ASM_SIGINFO_H
#define _ASM_SIGINFO_H

#define SI_USER		0
#define SI_KERNEL	0x80
#define POLL_IN		1
#define POLL_OUT	2
#define POLL_MSG	3
#define POLL_ERR	4
#define POLL_PRI	5
#define POLL_HUP	6

#endif /* _ASM_SIGINFO_H */
