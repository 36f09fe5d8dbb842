/*
 * linux/compiler.h — branch hints, compiler barriers, READ_ONCE/WRITE_ONCE.
 *
 * Uniprocessor ARM926 and the single-CPU host kernel: a compiler barrier is
 * all that orders memory between a task and an interrupt on the same CPU.
 */
#ifndef _LINUX_COMPILER_H
#define _LINUX_COMPILER_H

#include <linux/compiler_types.h>

#define likely(x)	__builtin_expect(!!(x), 1)
#define unlikely(x)	__builtin_expect(!!(x), 0)

#define barrier()	__asm__ __volatile__("" : : : "memory")
#define barrier_data(ptr) __asm__ __volatile__("" : : "r"(ptr) : "memory")

#define unreachable()	__builtin_unreachable()

/* One access of exactly the object's size, never torn, merged or repeated. */
#define READ_ONCE(x)	(*(const volatile __typeof__(x) *)&(x))
#define WRITE_ONCE(x, val) \
	do { *(volatile __typeof__(x) *)&(x) = (val); } while (0)

#define OPTIMIZER_HIDE_VAR(var) __asm__ ("" : "=r" (var) : "0" (var))

#define __must_be_array(a) \
	(sizeof(char[1 - 2 * !!__same_type((a), &(a)[0])]) - 1)

#define RELOC_HIDE(ptr, off) ((__typeof__(ptr))((unsigned long)(ptr) + (off)))

#endif /* _LINUX_COMPILER_H */
