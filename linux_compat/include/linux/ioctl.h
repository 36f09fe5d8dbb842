/* linux/ioctl.h — _IO/_IOR/_IOW/_IOWR (see asm-generic/ioctl.h for the encoding). */
#ifndef _LINUX_IOCTL_H
#define _LINUX_IOCTL_H

#include <asm/ioctl.h>

#endif /* _LINUX_IOCTL_H */
