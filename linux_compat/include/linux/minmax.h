/*
 * linux/minmax.h — min, max, clamp and friends, type-checked as in Linux 6.1:
 * comparing values of different types warns ("comparison of distinct pointer
 * types"), which -Werror turns into an error; use min_t/max_t/clamp_t then.
 * Each argument is evaluated exactly once; with constant arguments the result
 * is a constant expression.
 */
#ifndef _LINUX_MINMAX_H
#define _LINUX_MINMAX_H

#include <linux/compiler_types.h>

/* Warns at compile time unless x and y have the same type; evaluates neither. */
#define __lx_types_match(x, y) \
	(!!(sizeof((__typeof__(x) *)1 == (__typeof__(y) *)1)))

#define __lx_pick(x, y, op)	((x) op (y) ? (x) : (y))

#define __lx_pick_once(x, y, op, vx, vy) ({	\
	__typeof__(x) vx = (x);			\
	__typeof__(y) vy = (y);			\
	__lx_pick(vx, vy, op);			\
})

#define __lx_minmax(x, y, op)							\
	__builtin_choose_expr(__lx_types_match(x, y) &&				\
			      __is_constexpr(x) && __is_constexpr(y),		\
			      __lx_pick(x, y, op),				\
			      __lx_pick_once(x, y, op, __UNIQUE_ID(mm_x_), __UNIQUE_ID(mm_y_)))

#define min(x, y)	__lx_minmax(x, y, <)
#define max(x, y)	__lx_minmax(x, y, >)
#define min3(x, y, z)	min((__typeof__(x))min(x, y), z)
#define max3(x, y, z)	max((__typeof__(x))max(x, y), z)

#define min_t(type, x, y)	__lx_minmax((type)(x), (type)(y), <)
#define max_t(type, x, y)	__lx_minmax((type)(x), (type)(y), >)

/* The smaller of x and y that is not zero (zero only if both are). */
#define min_not_zero(x, y) ({					\
	__typeof__(x) __lx_mnz_x = (x);				\
	__typeof__(y) __lx_mnz_y = (y);				\
	__lx_mnz_x == 0 ? __lx_mnz_y :				\
	(__lx_mnz_y == 0 ? __lx_mnz_x : min(__lx_mnz_x, __lx_mnz_y)); })

#define __lx_clamp_once(val, lo, hi, vv, vl, vh) ({			\
	__typeof__(val) vv = (val);					\
	__typeof__(lo) vl = (lo);					\
	__typeof__(hi) vh = (hi);					\
	(void)__lx_types_match(vv, vl);					\
	(void)__lx_types_match(vv, vh);					\
	vv < vl ? vl : (vv > vh ? vh : vv); })

/* val limited to [lo, hi]; all three of the same type. */
#define clamp(val, lo, hi) \
	__lx_clamp_once(val, lo, hi, __UNIQUE_ID(cl_v_), __UNIQUE_ID(cl_l_), __UNIQUE_ID(cl_h_))
#define clamp_t(type, val, lo, hi)	clamp((type)(val), (type)(lo), (type)(hi))
/* clamp with the bounds converted to the type of val. */
#define clamp_val(val, lo, hi)		clamp_t(__typeof__(val), val, lo, hi)

#define swap(a, b) \
	do { __typeof__(a) __lx_swap_tmp = (a); (a) = (b); (b) = __lx_swap_tmp; } while (0)

#endif /* _LINUX_MINMAX_H */
