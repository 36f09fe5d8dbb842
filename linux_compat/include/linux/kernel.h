/*
 * linux/kernel.h — the kernel's everyday helpers, and (as in Linux) the
 * headers it makes reachable: types, compiler, printk, bug, minmax,
 * container_of, limits, kstrtox, might_sleep.
 */
#ifndef _LINUX_KERNEL_H
#define _LINUX_KERNEL_H

#include <stdarg.h>
#include <linux/stddef.h>
#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/stringify.h>
#include <linux/align.h>
#include <linux/limits.h>
#include <linux/typecheck.h>
#include <linux/printk.h>
#include <linux/bug.h>
#include <linux/minmax.h>
#include <linux/container_of.h>
#include <linux/kstrtox.h>
#include <linux/math64.h>
#include <linux_compat/context.h>

#define ARRAY_SIZE(arr)		(sizeof(arr) / sizeof((arr)[0]) + __must_be_array(arr))

#define DIV_ROUND_UP(n, d)	(((n) + (d) - 1) / (d))
#define DIV_ROUND_DOWN_ULL(ll, d) ({ unsigned long long __lx_ll = (ll); __lx_ll / (d); })
#define DIV_ROUND_UP_ULL(ll, d)	DIV_ROUND_DOWN_ULL((unsigned long long)(ll) + (d) - 1, (d))
/* n / d rounded to the nearest integer (halves away from zero). */
#define DIV_ROUND_CLOSEST(x, divisor) ({				\
	__typeof__(x) __lx_x = (x);					\
	__typeof__(divisor) __lx_d = (divisor);				\
	(((__typeof__(x))-1) > 0 || ((__typeof__(divisor))-1) > 0 ||	\
	 (((__lx_x) > 0) == ((__lx_d) > 0))) ?				\
		(((__lx_x) + ((__lx_d) / 2)) / (__lx_d)) :		\
		(((__lx_x) - ((__lx_d) / 2)) / (__lx_d)); })
#define roundup(x, y)		((((x) + ((y) - 1)) / (y)) * (y))
#define rounddown(x, y)		((x) - ((x) % (y)))
#define round_up(x, y)		((((x) - 1) | ((__typeof__(x))((y) - 1))) + 1)
#define round_down(x, y)	((x) & ~((__typeof__(x))((y) - 1)))

#define upper_32_bits(n)	((u32)(((n) >> 16) >> 16))
#define lower_32_bits(n)	((u32)((n) & 0xffffffff))
#define upper_16_bits(n)	((u16)((n) >> 16))
#define lower_16_bits(n)	((u16)((n) & 0xffff))

/* |x| of a signed value, in its own type.  Linux code sees no C library; a
 * hosted test program that has one on its include path gets <stdlib.h>'s abs
 * declared first, so that its own later <stdlib.h> does not collide with the
 * macro. */
#if __has_include(<stdlib.h>)
#include <stdlib.h>
#undef abs
#endif
#define abs(x) ({ __typeof__(x) __lx_abs = (x); __lx_abs < 0 ? -__lx_abs : __lx_abs; })

#define _RET_IP_		((unsigned long)__builtin_return_address(0))
#define _THIS_IP_		({ __label__ __lx_here; __lx_here: (unsigned long)&&__lx_here; })

/* Reports (and fails the test run) if the caller may not sleep here;
 * nothing without LX_DEBUG_ATOMIC_SLEEP (linux_compat/debug.h). */
#define might_sleep()		lx_might_sleep("might_sleep()", __FILE__, __LINE__)
#define might_sleep_if(cond)	do { if (cond) might_sleep(); } while (0)
#define might_resched()		do { } while (0)
#define cant_sleep()		WARN_ON_ONCE(!lx_in_atomic())
#define non_block_start()	do { } while (0)
#define non_block_end()		do { } while (0)

/* The C library's formatters, with Linux's prototypes (no %p extensions). */
__printf(2, 3) int sprintf(char *buf, const char *fmt, ...);
__printf(3, 4) int snprintf(char *buf, size_t size, const char *fmt, ...);
__printf(3, 0) int vsnprintf(char *buf, size_t size, const char *fmt, va_list args);
__printf(2, 0) int vsprintf(char *buf, const char *fmt, va_list args);
__scanf(2, 3) int sscanf(const char *buf, const char *fmt, ...);
/* Like snprintf, but returns the characters actually written (excluding NUL). */
__printf(3, 4) int scnprintf(char *buf, size_t size, const char *fmt, ...);
/* Like vsnprintf, but returns the characters actually written (excluding NUL). */
__printf(3, 0) int vscnprintf(char *buf, size_t size, const char *fmt, va_list args);

/* Linux's panic: reports and stops the system. */
__printf(1, 2) void panic(const char *fmt, ...) __attribute__((__noreturn__, __cold__));

enum system_states {
	SYSTEM_BOOTING,
	SYSTEM_SCHEDULING,
	SYSTEM_RUNNING,
	SYSTEM_HALT,
	SYSTEM_POWER_OFF,
	SYSTEM_RESTART,
};
#define system_state	SYSTEM_RUNNING

#endif /* _LINUX_KERNEL_H */
