/*
 * asm/types.h — the fixed-width kernel types (__u8 ... __s64, u8 ... s64).
 *
 * As Linux's int-ll64 model: 64-bit types are long long on every target.
 */
#ifndef _ASM_TYPES_H
#define _ASM_TYPES_H

typedef signed char		__s8;
typedef unsigned char		__u8;
typedef signed short		__s16;
typedef unsigned short		__u16;
typedef signed int		__s32;
typedef unsigned int		__u32;
__extension__ typedef signed long long	 __s64;
__extension__ typedef unsigned long long __u64;

#ifdef __KERNEL__
typedef __s8	s8;
typedef __u8	u8;
typedef __s16	s16;
typedef __u16	u16;
typedef __s32	s32;
typedef __u32	u32;
typedef __s64	s64;
typedef __u64	u64;
#endif

#endif /* _ASM_TYPES_H */
