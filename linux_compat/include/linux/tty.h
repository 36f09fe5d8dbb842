/*
 * linux/tty.h — what serial drivers take from the tty layer here: the
 * terminal settings (linux/termios.h) and, as 2.6's tty.h through linux/fs.h,
 * struct file and struct semaphore.  ev3lx has no tty devices; drivers
 * reach their ports through their own interfaces.
 */
#ifndef _LINUX_TTY_H
#define _LINUX_TTY_H

#include <linux/fs.h>
#include <linux/semaphore.h>	/* 2.6's tty.h -> linux/fs.h -> linux/semaphore.h */
#include <linux/termios.h>

#endif
