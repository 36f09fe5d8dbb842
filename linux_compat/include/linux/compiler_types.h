/*
 * linux/compiler_types.h — sparse annotations and GCC attribute shorthands.
 *
 * The address-space and lock-context annotations (__user, __iomem, __rcu,
 * __acquires, ...) are checked by sparse (__CHECKER__) and expand to nothing
 * in normal builds, as in Linux.  Attribute macros that newlib's sys/cdefs.h
 * also defines are spelled exactly as newlib spells them, so that either
 * header may come first.
 */
#ifndef _LINUX_COMPILER_TYPES_H
#define _LINUX_COMPILER_TYPES_H

#ifdef __CHECKER__
# define __user		__attribute__((noderef, address_space(__user)))
# define __kernel	__attribute__((address_space(0)))
# define __iomem	__attribute__((noderef, address_space(__iomem)))
# define __percpu	__attribute__((noderef, address_space(__percpu)))
# define __rcu		__attribute__((noderef, address_space(__rcu)))
# define __force	__attribute__((force))
# define __nocast	__attribute__((nocast))
# define __safe		__attribute__((safe))
# define __acquires(x)	__attribute__((context(x, 0, 1)))
# define __releases(x)	__attribute__((context(x, 1, 0)))
# define __acquire(x)	__context__(x, 1)
# define __release(x)	__context__(x, -1)
# define __cond_lock(x, c) ((c) ? ({ __acquire(x); 1; }) : 0)
# define __must_hold(x)	__attribute__((context(x, 1, 1)))
#else
# define __user
# define __kernel
# define __iomem
# define __percpu
# define __rcu
# define __force
# define __nocast
# define __safe
# define __acquires(x)
# define __releases(x)
# define __acquire(x)	((void)0)
# define __release(x)	((void)0)
# define __cond_lock(x, c) (c)
# define __must_hold(x)
#endif

#ifndef __always_inline
#define __always_inline		__inline__ __attribute__((__always_inline__))
#endif
#ifndef __packed
#define __packed		__attribute__((__packed__))
#endif
#ifndef __aligned
#define __aligned(x)		__attribute__((__aligned__(x)))
#endif
#ifndef __section
#define __section(x)		__attribute__((__section__(x)))
#endif
#ifndef __used
#define __used			__attribute__((__used__))
#endif
#ifndef __pure
#define __pure			__attribute__((__pure__))
#endif
#ifndef __noinline
#define __noinline		__attribute__ ((__noinline__))
#endif
#ifndef noinline
#define noinline		__attribute__((__noinline__))
#endif
#ifndef __attribute_const__
#define __attribute_const__	__attribute__ ((__const__))
#endif

#define __maybe_unused		__attribute__((__unused__))
#define __always_unused		__attribute__((__unused__))
#define __must_check		__attribute__((__warn_unused_result__))
#define __weak			__attribute__((__weak__))
#define __cold			__attribute__((__cold__))
#define __noreturn		__attribute__((__noreturn__))
#define __printf(a, b)		__attribute__((__format__(printf, a, b)))
#define __scanf(a, b)		__attribute__((__format__(scanf, a, b)))
#define __deprecated
#define __malloc		__attribute__((__malloc__))
#define __alias(symbol)		__attribute__((__alias__(#symbol)))
#define __visible		__attribute__((__externally_visible__))
#define __nonstring		__attribute__((__nonstring__))
#define __read_mostly
#define __ro_after_init
#define __cacheline_aligned	__aligned(32)
#define ____cacheline_aligned	__aligned(32)
#define notrace
#define inline_for_stack	noinline
#define __fallthrough		__attribute__((__fallthrough__))
#ifndef fallthrough
#define fallthrough		__attribute__((__fallthrough__))
#endif

/* Whether two expressions have the same type (qualifiers ignored). */
#define __same_type(a, b)	__builtin_types_compatible_p(__typeof__(a), __typeof__(b))

/* Unique identifiers for macro-local variables. */
#define ___PASTE(a, b)		a##b
#define __PASTE(a, b)		___PASTE(a, b)
#define __UNIQUE_ID(prefix)	__PASTE(__PASTE(__UNIQUE_ID_, prefix), __COUNTER__)

/*
 * 1 if x is an integer constant expression, else 0; x is not evaluated.
 * (void *)(x * 0) is a null pointer constant only for a constant x, and only
 * then does the conditional take the type int *.
 */
#define __is_constexpr(x) \
	_Generic((1 ? (void *)((long)(x) * 0l) : (int *)0), int *: 1, default: 0)

#endif /* _LINUX_COMPILER_TYPES_H */
