/* linux/bottom_half.h — holding off timer_list callbacks (Linux's softirqs). */
#ifndef _LINUX_BH_H
#define _LINUX_BH_H

#include <linux_compat/sched.h>

#define local_bh_disable()	lx_bh_disable()
#define local_bh_enable()	lx_bh_enable()

#endif /* _LINUX_BH_H */
