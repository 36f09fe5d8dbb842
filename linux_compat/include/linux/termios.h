/*
 * linux/termios.h — the kernel's terminal settings, as Linux's reaches them
 * (uapi/linux/termios.h -> asm/termios.h -> asm/termbits.h): struct ktermios
 * and its flags (asm/termbits.h), the tty ioctls (asm/ioctls.h).
 */
#ifndef _LINUX_TERMIOS_H
#define _LINUX_TERMIOS_H

#include <asm/termbits.h>
#include <asm/ioctls.h>

/* TIOCSERGETLSR's answer: the transmitter is empty (asm-generic/ioctls.h). */
#ifndef TIOCSER_TEMT
#define TIOCSER_TEMT	0x01
#endif

#endif
