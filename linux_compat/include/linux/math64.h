/* linux/math64.h — 64-bit division helpers (plain C division on both targets). */
#ifndef _LINUX_MATH64_H
#define _LINUX_MATH64_H

#include <linux/types.h>
#include <asm/div64.h>

/* dividend / divisor, unsigned 64 by 32. */
static inline u64 div_u64(u64 dividend, u32 divisor) { return dividend / divisor; }
/* dividend / divisor, signed 64 by 32. */
static inline s64 div_s64(s64 dividend, s32 divisor) { return dividend / divisor; }
/* dividend / divisor, unsigned 64 by 64. */
static inline u64 div64_u64(u64 dividend, u64 divisor) { return dividend / divisor; }
/* dividend / divisor, signed 64 by 64. */
static inline s64 div64_s64(s64 dividend, s64 divisor) { return dividend / divisor; }
/* dividend / divisor with the remainder stored in *remainder. */
static inline u64 div_u64_rem(u64 dividend, u32 divisor, u32 *remainder)
{
	*remainder = (u32)(dividend % divisor);
	return dividend / divisor;
}
/* signed dividend / divisor with the remainder stored in *remainder. */
static inline s64 div_s64_rem(s64 dividend, s32 divisor, s32 *remainder)
{
	*remainder = (s32)(dividend % divisor);
	return dividend / divisor;
}
#define div64_ul(x, y)	div64_u64((x), (y))

#endif /* _LINUX_MATH64_H */
