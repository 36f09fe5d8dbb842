/* linux/typecheck.h — compile-time checks that a value has a given type. */
#ifndef _LINUX_TYPECHECK_H
#define _LINUX_TYPECHECK_H

/* 1, with a compile-time warning (an error under -Werror) unless x has type `type`. */
#define typecheck(type, x) ({			\
	type __lx_tc_dummy;			\
	__typeof__(x) __lx_tc_dummy2;		\
	(void)(&__lx_tc_dummy == &__lx_tc_dummy2); \
	1; })

#endif /* _LINUX_TYPECHECK_H */
