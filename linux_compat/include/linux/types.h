/*
 * linux/types.h — the kernel's basic types.
 *
 * Linux code is compiled without the C library's headers (-nostdinc), so the
 * C99 fixed-width names are defined here, as Linux's own linux/types.h does,
 * from the compiler's predefined types.  They, ssize_t, loff_t and friends
 * agree with the C library's own definitions on every build (glibc x86_64 and
 * armel, newlib): a hosted test program may see both.  Addresses (phys_addr_t, dma_addr_t) are
 * as wide as a pointer: 32 bits on the AM1808, 64 on a 64-bit host where the
 * "physical" address of a buffer is its host address.
 */
#ifndef _LINUX_TYPES_H
#define _LINUX_TYPES_H

#include <stddef.h>
#include <stdbool.h>
#include <asm/types.h>
#include <asm/bitsperlong.h>
#include <linux/compiler_types.h>

#ifdef __CHECKER__
#define __bitwise	__attribute__((bitwise))
#else
#define __bitwise
#endif
#define __bitwise__	__bitwise

typedef __INT8_TYPE__		int8_t;
typedef __INT16_TYPE__		int16_t;
typedef __INT32_TYPE__		int32_t;
typedef __INT64_TYPE__		int64_t;
typedef __UINT8_TYPE__		uint8_t;
typedef __UINT16_TYPE__		uint16_t;
typedef __UINT32_TYPE__		uint32_t;
typedef __UINT64_TYPE__		uint64_t;
typedef __INTPTR_TYPE__		intptr_t;
typedef __UINTPTR_TYPE__	uintptr_t;
typedef __u8			u_int8_t;
typedef __u16			u_int16_t;
typedef __u32			u_int32_t;

typedef __u16 __bitwise __le16;
typedef __u16 __bitwise __be16;
typedef __u32 __bitwise __le32;
typedef __u32 __bitwise __be32;
typedef __u64 __bitwise __le64;
typedef __u64 __bitwise __be64;
typedef __u16 __bitwise __sum16;
typedef __u32 __bitwise __wsum;

/* ssize_t: the signed counterpart of size_t, exactly as the C libraries derive it. */
#define unsigned signed
typedef __SIZE_TYPE__ ssize_t;
#undef unsigned

typedef int64_t		loff_t;     /* long long in Linux; int64_t matches glibc's loff_t */
typedef unsigned short	umode_t;
typedef unsigned long	pgoff_t;
typedef unsigned int	__bitwise gfp_t;
typedef unsigned int	__bitwise slab_flags_t;
typedef unsigned int	__bitwise fmode_t;

#if __SIZEOF_POINTER__ == 8
typedef u64		phys_addr_t;
typedef u64		dma_addr_t;
#else
typedef u32		phys_addr_t;
typedef u32		dma_addr_t;
#endif
typedef phys_addr_t	resource_size_t;
typedef phys_addr_t	irq_hw_number_t;

typedef unsigned char	u_char;
typedef unsigned short	u_short;
typedef unsigned int	u_int;
typedef unsigned long	u_long;
typedef unsigned char	unchar;
typedef unsigned short	ushort;
typedef unsigned int	uint;
typedef unsigned long	ulong;

#define DECLARE_BITMAP(name, bits) \
	unsigned long name[((bits) + BITS_PER_LONG - 1) / BITS_PER_LONG]

typedef struct {
	int counter;
} atomic_t;

#define ATOMIC_INIT(i)	{ (i) }

struct list_head {
	struct list_head *next, *prev;
};

struct hlist_head {
	struct hlist_node *first;
};

struct hlist_node {
	struct hlist_node *next, **pprev;
};

#endif /* _LINUX_TYPES_H */
