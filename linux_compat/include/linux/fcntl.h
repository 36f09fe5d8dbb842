/*
 * linux/fcntl.h — open flags as struct file's f_flags carries them.
 * Values (and spellings, so glibc's <fcntl.h> may come first) are those of
 * Linux's asm-generic/fcntl.h.
 */
#ifndef _LINUX_FCNTL_H
#define _LINUX_FCNTL_H

#ifndef O_ACCMODE
#define O_ACCMODE	   0003
#define O_RDONLY	     00
#define O_WRONLY	     01
#define O_RDWR		     02
#endif
#ifndef O_CREAT
#define O_CREAT		   0100
#define O_EXCL		   0200
#define O_NOCTTY	   0400
#define O_TRUNC		  01000
#define O_APPEND	  02000
#define O_NONBLOCK	  04000
#define O_NDELAY	O_NONBLOCK
#endif
#ifndef O_DSYNC
#define O_DSYNC		 010000
#endif
#ifndef O_CLOEXEC
#define O_CLOEXEC	02000000
#endif

#endif /* _LINUX_FCNTL_H */
