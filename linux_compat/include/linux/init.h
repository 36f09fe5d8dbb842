/*
 * linux/init.h — section annotations for init and exit code and data.
 *
 * Everything links into one image that never frees its init sections, so
 * the annotations keep Linux's meaning for readers but change no placement.
 * module_init/module_exit are in linux/module.h.
 */
#ifndef _LINUX_INIT_H
#define _LINUX_INIT_H

#include <linux/compiler.h>
#include <linux/types.h>

#define __init		__cold
#define __exit		__cold
#define __initdata
#define __exitdata
#define __initconst
#define __exit_call
#define __ref
#define __refdata
#define __refconst
#define __meminit
#define __meminitdata

/* Removed in Linux 3.8; kept for 2.6-era drivers (no hotplug distinction). */
#define __devinit
#define __devinitdata
#define __devinitconst
#define __devexit
#define __devexitdata
#define __devexit_p(fn)	(fn)
#define __cpuinit
#define __cpuinitdata

#endif /* _LINUX_INIT_H */
