/*
 * linux_compat/hack.h — what a hack file includes right after its driver:
 * module_init/module_exit register again, now for the hack's own init and
 * exit (before the driver, LX_HACK_DRIVER_INIT/_EXIT turned the driver's into
 * pointers the hack calls, see linux/module.h).  Linux names only, so a hack
 * whose driver defines TOPPERS-like names (TRUE, SIZE, ID, ...) itself can
 * use it; driver_common.h adds linux_compat's RTOS-side interfaces.
 */
#ifndef _LINUX_COMPAT_HACK_H
#define _LINUX_COMPAT_HACK_H

#include <linux/module.h>

#undef module_init
#undef module_exit
#define module_init(fn)		__lx_module_init(fn)
#define module_exit(fn)		__lx_module_exit(fn)

#endif /* _LINUX_COMPAT_HACK_H */
