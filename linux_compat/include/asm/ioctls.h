/*
 * asm/ioctls.h — the tty ioctl numbers (asm-generic's values).
 */
#ifndef _ASM_IOCTLS_H
#define _ASM_IOCTLS_H

#define TCGETS		0x5401
#define TCSETS		0x5402
#define TCFLSH		0x540B
#define TIOCSETD	0x5423
#define TIOCGETD	0x5424

#endif /* _ASM_IOCTLS_H */
