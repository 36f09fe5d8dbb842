/* linux/container_of.h — from a member pointer to its enclosing structure. */
#ifndef _LINUX_CONTAINER_OF_H
#define _LINUX_CONTAINER_OF_H

#include <stddef.h>
#include <linux/compiler_types.h>

/* The structure of type `type` whose `member` ptr points to; ptr's type is checked.
 * The check names the member through __lx_mptr rather than a null pointer: both are
 * unevaluated, but static analysers read ((type *)0)->member as a dereference. */
#define container_of(ptr, type, member) ({					\
	void *__lx_mptr = (void *)(ptr);					\
	_Static_assert(__same_type(*(ptr), ((type *)__lx_mptr)->member) ||	\
		       __same_type(*(ptr), void),				\
		       "pointer type mismatch in container_of()");		\
	((type *)((char *)__lx_mptr - offsetof(type, member))); })

/* container_of that keeps a NULL pointer NULL. */
#define container_of_safe(ptr, type, member) ({				\
	__typeof__(ptr) __lx_cptr = (ptr);					\
	__lx_cptr ? container_of(__lx_cptr, type, member) : (type *)0; })

#endif /* _LINUX_CONTAINER_OF_H */
