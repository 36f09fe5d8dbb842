/*
 * linux/uaccess.h — copying between kernel and user memory.
 *
 * ev3lx has one address space, so "user memory" is memory the calling
 * task's protection domain may access: every copy first checks the range
 * with the RTOS's prb_mem (TPM_READ for the source of copy_from_user,
 * TPM_WRITE for the destination of copy_to_user) - never a blind memcpy.
 * One prb_mem call when the whole range is accessible; otherwise the
 * accessible prefix is found by bisection (O(log n) probes), copied, and the
 * rest reported, with Linux's results:
 * - copy_from_user / copy_to_user / clear_user: the number of bytes NOT
 *   copied (0 = all); copy_from_user zero-fills what it could not copy.
 * - get_user / put_user: 0 or -EFAULT (get_user stores 0 on failure).
 * - strncpy_from_user: the string length, count if no NUL in count bytes, or -EFAULT.
 * - access_ok(addr, size) (also 2.6.33's access_ok(type, addr, size)):
 *   whether the calling task may access the range (VERIFY_WRITE: write).
 * get_fs/set_fs (2.6.33's address limit, per task): after set_fs(KERNEL_DS)
 * the copies also accept kernel memory the task's domain may not touch - how
 * a hack hands the driver a buffer of its own (on HRP2 a service routine's
 * stack is not in the caller's domain); restore the old limit afterwards.
 * The domain check still comes first, so user copies cost nothing extra.
 * They may sleep in Linux (page faults): calling them outside task context
 * or in an atomic section is reported as a context bug, and outside task
 * context (there is no calling domain) nothing is copied.
 * (linux_compat/src/uaccess.c)
 */
#ifndef __LINUX_UACCESS_H__
#define __LINUX_UACCESS_H__

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/errno.h>

#define VERIFY_READ	0
#define VERIFY_WRITE	1

/* The address limit of the calling task (2.6.33's set_fs/get_fs). */
typedef struct {
	unsigned long seg;
} mm_segment_t;

#define KERNEL_DS		((mm_segment_t){ 0UL })
#define USER_DS			((mm_segment_t){ 1UL })
#define segment_eq(a, b)	((a).seg == (b).seg)
#define uaccess_kernel()	segment_eq(get_fs(), KERNEL_DS)

/* The calling task's address limit (USER_DS outside task context). */
mm_segment_t get_fs(void);
/* Sets the calling task's address limit (ignored outside task context). */
void set_fs(mm_segment_t fs);

/* Copies n bytes of user memory at from to to; returns the bytes not copied. */
unsigned long copy_from_user(void *to, const void __user *from, unsigned long n);
/* Copies n bytes at from to user memory at to; returns the bytes not copied. */
unsigned long copy_to_user(void __user *to, const void *from, unsigned long n);
/* Zeroes n bytes of user memory; returns the bytes not cleared. */
unsigned long clear_user(void __user *to, unsigned long n);
/* Copies a NUL-terminated user string of at most count bytes (see above). */
long strncpy_from_user(char *dst, const char __user *src, long count);
/* Length of a user string including its NUL, 0 if unreadable, > n if longer than n. */
long strnlen_user(const char __user *str, long n);
/* True if the calling task may access [addr, addr + size) (write != 0: for writing). */
bool lx_access_ok(const void __user *addr, unsigned long size, int write);
/* get_user/put_user back ends: size bytes to/from the kernel value at val; 0 or -EFAULT. */
int lx_get_user(void *val, const void __user *ptr, size_t size);
int lx_put_user(const void *val, void __user *ptr, size_t size);

#define __copy_from_user(to, from, n)	copy_from_user((to), (from), (n))
#define __copy_to_user(to, from, n)	copy_to_user((to), (from), (n))
#define __clear_user(to, n)		clear_user((to), (n))

#define __lx_access_ok2(addr, size)		lx_access_ok((addr), (unsigned long)(size), 0)
#define __lx_access_ok3(type, addr, size)	lx_access_ok((addr), (unsigned long)(size), (type))
#define __lx_access_ok_sel(_1, _2, _3, name, ...)	name
#define access_ok(...) \
	__lx_access_ok_sel(__VA_ARGS__, __lx_access_ok3, __lx_access_ok2, 0, 0)(__VA_ARGS__)

/* An unsigned integer type as wide as x (for get_user's value). */
#define __lx_inttype(x) \
	__typeof__(__builtin_choose_expr(sizeof(x) > sizeof(unsigned long), 0ULL, 0UL))

#define get_user(x, ptr) ({						\
	__lx_inttype(*(ptr)) __lx_gu_val = 0;				\
	int __lx_gu_err = lx_get_user(&__lx_gu_val, (ptr), sizeof(*(ptr)));	\
	(x) = (__force __typeof__(*(ptr)))__lx_gu_val;			\
	__lx_gu_err;							\
})

#define put_user(x, ptr) ({						\
	__typeof__(*(ptr)) __lx_pu_val = (x);				\
	lx_put_user(&__lx_pu_val, (ptr), sizeof(*(ptr)));		\
})

#define __get_user(x, ptr)	get_user((x), (ptr))
#define __put_user(x, ptr)	put_user((x), (ptr))

#endif /* __LINUX_UACCESS_H__ */
