/*
 * linux/moduleparam.h — module parameters, set from the configuration.
 *
 * module_param(name, type, perm) registers the variable `name` under
 * KBUILD_MODNAME in the linker section "lx_module_params" (see
 * linux/module.h for why a section).  Before the module's init runs,
 * lx_module_param_set(module, param, "value") parses the text as Linux's
 * param_set_<type> would and stores it; afterwards the value is fixed
 * (there is no sysfs, so perm is recorded but grants nothing).
 *
 * Types: charp, int, uint, bool, invbool, short, ushort, long, ulong, byte.
 */
#ifndef _LINUX_MODULEPARAM_H
#define _LINUX_MODULEPARAM_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/stringify.h>

enum lx_param_type {
	LX_PARAM_charp,
	LX_PARAM_int,
	LX_PARAM_uint,
	LX_PARAM_bool,
	LX_PARAM_invbool,
	LX_PARAM_short,
	LX_PARAM_ushort,
	LX_PARAM_long,
	LX_PARAM_ulong,
	LX_PARAM_byte,
};

/* The C type of each parameter type, for the compile-time type check. */
#define __lx_param_ctype_charp		char *
#define __lx_param_ctype_int		int
#define __lx_param_ctype_uint		unsigned int
#define __lx_param_ctype_bool		bool
#define __lx_param_ctype_invbool	bool
#define __lx_param_ctype_short		short
#define __lx_param_ctype_ushort		unsigned short
#define __lx_param_ctype_long		long
#define __lx_param_ctype_ulong		unsigned long
#define __lx_param_ctype_byte		unsigned char
/* stdbool's `bool` is a macro for _Bool, so module_param(x, bool, ...) arrives here as _Bool. */
#define __lx_param_ctype__Bool		bool
#define LX_PARAM__Bool			LX_PARAM_bool

struct lx_module_param {
	const char *module;      /* KBUILD_MODNAME */
	const char *name;        /* parameter name as the user sets it */
	enum lx_param_type type;
	void *arg;               /* the variable */
	umode_t perm;
};

/* The linker section holding pointers to every struct lx_module_param. */
#define LX_MODULE_PARAM_SECTION	"lx_module_params"

#define __lx_param_entry(pname, var, type, perm)				\
	static inline __lx_param_ctype_##type * __maybe_unused			\
	__lx_param_check_##pname(void) { return &(var); }			\
	static const struct lx_module_param __lx_param_##pname = {		\
		KBUILD_MODNAME, __stringify(pname), LX_PARAM_##type,		\
		(void *)&(var), (perm) };					\
	static const struct lx_module_param *const __lx_param_ptr_##pname	\
	__used __section(LX_MODULE_PARAM_SECTION) = &__lx_param_##pname

/* A parameter `name` for the variable of the same name. */
#define module_param(name, type, perm)	__lx_param_entry(name, name, type, perm)
/* A parameter `name` for the variable `value`. */
#define module_param_named(name, value, type, perm) \
	__lx_param_entry(name, value, type, perm)
#define module_param_unsafe(name, type, perm)	module_param(name, type, perm)
#define MODULE_PARM_DESC(parm, desc) \
	static const char __lx_parm_desc_##parm[] __maybe_unused = desc

#endif /* _LINUX_MODULEPARAM_H */
