/*
 * linux/tty_flip.h — the flip buffer calls a tty driver makes (declared
 * with the rest of the tty layer in linux/tty.h).
 */
#ifndef _LINUX_TTY_FLIP_H
#define _LINUX_TTY_FLIP_H

#include <linux/tty.h>

#endif /* _LINUX_TTY_FLIP_H */
