/*
 * linux/module.h — modules linked into one image.
 *
 * Each driver is one translation unit that defines KBUILD_MODNAME before
 * including the driver (the hack file does `#define KBUILD_MODNAME "d_pwm"`).
 * That unit gets its own `struct module` (THIS_MODULE).  module_init and
 * module_exit place a pointer to a `struct lx_initcall` in the linker section
 * "lx_initcalls" (marked used; an image linked with --gc-sections must
 * KEEP(*(lx_initcalls)) and KEEP(*(lx_module_params)) and define the
 * __start_/__stop_ symbols, which GNU ld does itself for these C-identifier
 * section names).  No constructors are involved.
 *
 * At boot the linux_compat worker task calls lx_modules_init(): every
 * module_init runs once, in task context, ordered by initcall level (core,
 * postcore, arch, subsys, fs, device = module_init, late) and then by module
 * name (strcmp), so the order never depends on link order.  A failing init
 * is logged and its module_exit is never called.  lx_modules_exit() runs
 * the module_exit of every initialised module in reverse order.
 *
 * At shutdown linux_compat's ATT_TER has the worker call lx_modules_exit()
 * (task context: exits may sleep), as rmmod/power-off would; every boot
 * starts with all modules uninitialised (lx_modules_reset in the ATT_INI),
 * so each boot runs every module_init again.  Unlike insmod, a module's
 * static data is not reloaded between an exit and the next init: a driver's
 * init must set up all its state (as one written for built-in and
 * modular use does), and module parameters keep their last value.
 *
 * A module's object file must be part of the link: an archive member that
 * nothing references is not pulled in, and neither are its initcalls.
 */
#ifndef _LINUX_MODULE_H
#define _LINUX_MODULE_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/stringify.h>
#include <linux/init.h>
#include <linux/export.h>
#include <linux/moduleparam.h>
#include <linux/kernel.h>
#include <linux/errno.h>       /* as Linux's, through linux/err.h */
#include <linux/stat.h>        /* as Linux's: S_IRUGO for module_param */

enum module_state {
	MODULE_STATE_UNFORMED,  /* linked, init not run yet */
	MODULE_STATE_COMING,    /* init running */
	MODULE_STATE_LIVE,      /* init succeeded (or there was none) */
	MODULE_STATE_GOING,     /* exit running */
	MODULE_STATE_FAILED,    /* init returned an error; exit will not run */
};

struct module {
	const char *name;
	enum module_state state;
	int init_result;         /* what init returned (0 if none ran) */
	int refcnt;              /* try_module_get/module_put balance */
	struct module *next_live; /* the live list, most recently initialised first */
};

#define MODULE_NAME_LEN	56

/* Initcall levels, as Linux's built-in initcalls (module_init = device). */
#define LX_INITCALL_CORE	1
#define LX_INITCALL_POSTCORE	2
#define LX_INITCALL_ARCH	3
#define LX_INITCALL_SUBSYS	4
#define LX_INITCALL_FS		5
#define LX_INITCALL_DEVICE	6
#define LX_INITCALL_LATE	7

struct lx_initcall {
	struct module *module;
	int (*init)(void);       /* NULL in a module_exit entry */
	void (*exit)(void);      /* NULL in a module_init entry */
	int level;
};

#define LX_INITCALL_SECTION	"lx_initcalls"

#ifdef KBUILD_MODNAME
static struct module __this_module __maybe_unused = {
	.name = KBUILD_MODNAME,
};
#define THIS_MODULE	(&__this_module)
#else
#define THIS_MODULE	((struct module *)0)
#endif

#define __lx_initcall_entry(fn, initfn, exitfn, lvl)				\
	static const struct lx_initcall __lx_initcall_##fn = {			\
		THIS_MODULE, (initfn), (exitfn), (lvl) };			\
	static const struct lx_initcall *const __lx_initcall_ptr_##fn		\
	__used __section(LX_INITCALL_SECTION) = &__lx_initcall_##fn

#ifdef KBUILD_MODNAME
#define __lx_define_initcall(fn, lvl)	__lx_initcall_entry(fn, fn, NULL, lvl)
#define __lx_module_exit(fn)		__lx_initcall_entry(fn, NULL, fn, LX_INITCALL_DEVICE)
#else
#define __lx_define_initcall(fn, lvl) \
	_Static_assert(0, "define KBUILD_MODNAME before using module_init/initcalls")
#define __lx_module_exit(fn) \
	_Static_assert(0, "define KBUILD_MODNAME before using module_exit")
#endif

#define __lx_module_init(fn)	__lx_define_initcall(fn, LX_INITCALL_DEVICE)

/*
 * A hack file includes its driver after naming, with these macros, the
 * pointers through which it calls the driver's init and exit itself; the
 * driver's module_init/module_exit then define those pointers instead of
 * registering.  The hack defines nothing else before the driver, so the
 * driver's own `#define pr_fmt` and names come first, as under kbuild;
 * driver_common.h, included after the driver, restores the registering forms.
 */
#ifdef LX_HACK_DRIVER_EXIT
#define module_exit(fn)		static void (*const LX_HACK_DRIVER_EXIT)(void) = fn
#else
#define module_exit(fn)		__lx_module_exit(fn)
#endif
#ifdef LX_HACK_DRIVER_INIT
#define module_init(fn)		static int (*const LX_HACK_DRIVER_INIT)(void) = fn
#else
#define module_init(fn)		__lx_module_init(fn)
#endif
#define core_initcall(fn)	__lx_define_initcall(fn, LX_INITCALL_CORE)
#define postcore_initcall(fn)	__lx_define_initcall(fn, LX_INITCALL_POSTCORE)
#define arch_initcall(fn)	__lx_define_initcall(fn, LX_INITCALL_ARCH)
#define subsys_initcall(fn)	__lx_define_initcall(fn, LX_INITCALL_SUBSYS)
#define fs_initcall(fn)		__lx_define_initcall(fn, LX_INITCALL_FS)
#define device_initcall(fn)	__lx_define_initcall(fn, LX_INITCALL_DEVICE)
#define late_initcall(fn)	__lx_define_initcall(fn, LX_INITCALL_LATE)

/* Module information: documentation only (nothing reads it at run time). */
#define __lx_modinfo(tag, info) \
	static const char __UNIQUE_ID(modinfo_##tag)[] __maybe_unused = #tag "=" info
#define MODULE_LICENSE(_license)	__lx_modinfo(license, _license)
#define MODULE_AUTHOR(_author)		__lx_modinfo(author, _author)
#define MODULE_DESCRIPTION(desc)	__lx_modinfo(description, desc)
#define MODULE_VERSION(_version)	__lx_modinfo(version, _version)
#define MODULE_ALIAS(_alias)		__lx_modinfo(alias, _alias)
#define MODULE_SOFTDEP(dep)		__lx_modinfo(softdep, dep)
#define MODULE_FIRMWARE(fw)		__lx_modinfo(firmware, fw)
#define MODULE_INFO(tag, info)		__lx_modinfo(tag, info)
/* Removed in Linux 5.12; 2.6-era drivers still use it. */
#define MODULE_SUPPORTED_DEVICE(dev)	__lx_modinfo(supported_device, dev)
#define MODULE_DEVICE_TABLE(type, name) \
	static const void *const __UNIQUE_ID(devtable_##type) __maybe_unused = &(name)
#define MODULE_IMPORT_NS(ns)

/* Takes a reference on mod (NULL = built-in: always succeeds); false if the module is not live. */
bool try_module_get(struct module *mod);
/* Drops a reference taken by try_module_get/__module_get. */
void module_put(struct module *mod);
/* Takes a reference unconditionally. */
void __module_get(struct module *mod);
/* The module's name ("kernel" for NULL). */
const char *module_name(const struct module *mod);
/* The number of references held on mod. */
int module_refcount(struct module *mod);

/*
 * Runs every module_init once (order above); called by the linux_compat
 * worker task at boot before it serves work.  Returns the number of inits
 * that failed.  Calling it again initialises only modules not yet initialised.
 */
int lx_modules_init(void);
/* Runs module_exit of every live module in reverse init order; modules become uninitialised. */
void lx_modules_exit(void);
/* Marks every module uninitialised without running anything (linux_compat's boot reset). */
void lx_modules_reset(void);
/* The struct module linked under name, or NULL. */
struct module *lx_module_find(const char *name);

#endif /* _LINUX_MODULE_H */
