/* asm/uaccess.h — user memory access (linux/uaccess.h; 2.6.33 drivers include this one). */
#ifndef _ASMARM_UACCESS_H
#define _ASMARM_UACCESS_H

#include <linux/uaccess.h>

#endif /* _ASMARM_UACCESS_H */
