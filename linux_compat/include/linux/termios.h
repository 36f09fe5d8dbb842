/*
 * linux/termios.h — the kernel's terminal settings (struct ktermios) and the
 * c_cflag / c_iflag bits of the generic termbits ARM uses (Linux's
 * include/uapi/asm-generic/termbits.h), for serial drivers' set_termios.
 */
#ifndef _LINUX_TERMIOS_H
#define _LINUX_TERMIOS_H

#include <linux/types.h>

typedef unsigned char	cc_t;
typedef unsigned int	speed_t;
typedef unsigned int	tcflag_t;

#define NCCS 19
struct ktermios {
	tcflag_t c_iflag;
	tcflag_t c_oflag;
	tcflag_t c_cflag;
	tcflag_t c_lflag;
	cc_t c_line;
	cc_t c_cc[NCCS];
	speed_t c_ispeed;
	speed_t c_ospeed;
};

/* c_iflag */
#define IGNBRK	0000001
#define BRKINT	0000002
#define IGNPAR	0000004
#define PARMRK	0000010
#define INPCK	0000020
#define ISTRIP	0000040

/* c_cflag */
#define CBAUD	0010017
#define CSIZE	0000060
#define   CS5	0000000
#define   CS6	0000020
#define   CS7	0000040
#define   CS8	0000060
#define CSTOPB	0000100
#define CREAD	0000200
#define PARENB	0000400
#define PARODD	0001000
#define HUPCL	0002000
#define CLOCAL	0004000
#define CMSPAR	010000000000
#define CRTSCTS	020000000000

/* TIOCSERGETLSR's answer: the transmitter is empty (asm-generic/ioctls.h). */
#define TIOCSER_TEMT	0x01

#endif
