/*
 * asm/div64.h — do_div(n, base): divides the u64 lvalue n in place by the
 * u32 base and evaluates to the u32 remainder.
 */
#ifndef _ASM_DIV64_H
#define _ASM_DIV64_H

#include <linux/types.h>

#define do_div(n, base) ({						\
	u32 __lx_div_base = (base);					\
	u32 __lx_div_rem = (u32)((u64)(n) % __lx_div_base);		\
	(n) = (u64)(n) / __lx_div_base;					\
	__lx_div_rem; })

#endif /* _ASM_DIV64_H */
