/*
 * linux/bitops.h — bit operations on unsigned long bitmaps.
 *
 * set_bit & co. are atomic as in Linux: on this uniprocessor each is one
 * read-modify-write with interrupts masked, so an IRQ handler and a task can
 * share a bitmap.  The __ forms are the non-atomic ones.  ffs/fls count from
 * 1 (0: no bit), __ffs/__fls from 0 (undefined for 0), as in Linux.
 */
#ifndef _LINUX_BITOPS_H
#define _LINUX_BITOPS_H

#include <linux/types.h>
#include <linux/bits.h>
#include <linux/irqflags.h>
#include <asm/bitsperlong.h>

#define BITS_TO_LONGS(nr)	(((nr) + BITS_PER_LONG - 1) / BITS_PER_LONG)
#define BITS_TO_BYTES(nr)	(((nr) + BITS_PER_BYTE - 1) / BITS_PER_BYTE)

static inline void __set_bit(unsigned long nr, volatile unsigned long *addr)
{
	addr[BIT_WORD(nr)] |= BIT_MASK(nr);
}

static inline void __clear_bit(unsigned long nr, volatile unsigned long *addr)
{
	addr[BIT_WORD(nr)] &= ~BIT_MASK(nr);
}

static inline void __change_bit(unsigned long nr, volatile unsigned long *addr)
{
	addr[BIT_WORD(nr)] ^= BIT_MASK(nr);
}

static inline bool test_bit(unsigned long nr, const volatile unsigned long *addr)
{
	return (addr[BIT_WORD(nr)] & BIT_MASK(nr)) != 0;
}

/* Sets bit nr; its old value. */
static inline bool __test_and_set_bit(unsigned long nr, volatile unsigned long *addr)
{
	bool old = test_bit(nr, addr);

	__set_bit(nr, addr);
	return old;
}

/* Clears bit nr; its old value. */
static inline bool __test_and_clear_bit(unsigned long nr, volatile unsigned long *addr)
{
	bool old = test_bit(nr, addr);

	__clear_bit(nr, addr);
	return old;
}

static inline bool __test_and_change_bit(unsigned long nr, volatile unsigned long *addr)
{
	bool old = test_bit(nr, addr);

	__change_bit(nr, addr);
	return old;
}

/* The atomic forms: the non-atomic one with interrupts masked. */
#define LX_BITOP_ATOMIC(type, name, ret)					\
static inline type name(unsigned long nr, volatile unsigned long *addr)		\
{										\
	unsigned long flags;							\
	type r;									\
										\
	local_irq_save(flags);							\
	r = ret(nr, addr);							\
	local_irq_restore(flags);						\
	return r;								\
}
LX_BITOP_ATOMIC(bool, test_and_set_bit, __test_and_set_bit)
LX_BITOP_ATOMIC(bool, test_and_clear_bit, __test_and_clear_bit)
LX_BITOP_ATOMIC(bool, test_and_change_bit, __test_and_change_bit)
#undef LX_BITOP_ATOMIC

static inline void set_bit(unsigned long nr, volatile unsigned long *addr)
{
	(void)test_and_set_bit(nr, addr);
}

static inline void clear_bit(unsigned long nr, volatile unsigned long *addr)
{
	(void)test_and_clear_bit(nr, addr);
}

static inline void change_bit(unsigned long nr, volatile unsigned long *addr)
{
	(void)test_and_change_bit(nr, addr);
}

/* First set bit, from 1; 0 if none (a macro: the C library declares ffs too). */
#define ffs(x)	__builtin_ffs(x)

/* Last set bit, from 1; 0 if none. */
static inline int fls(unsigned int x)
{
	return x ? 32 - __builtin_clz(x) : 0;
}

static inline int fls64(u64 x)
{
	return x ? 64 - __builtin_clzll(x) : 0;
}

/* Index of the lowest set bit (word must not be 0). */
static inline unsigned long __ffs(unsigned long word)
{
	return (unsigned long)__builtin_ctzl(word);
}

/* Index of the highest set bit (word must not be 0). */
static inline unsigned long __fls(unsigned long word)
{
	return BITS_PER_LONG - 1 - (unsigned long)__builtin_clzl(word);
}

/* Index of the lowest clear bit (word must not be ~0UL). */
static inline unsigned long ffz(unsigned long word)
{
	return __ffs(~word);
}

static inline unsigned int hweight32(u32 w)
{
	return (unsigned int)__builtin_popcount(w);
}

static inline unsigned int hweight8(u8 w)
{
	return hweight32(w);
}

static inline unsigned int hweight16(u16 w)
{
	return hweight32(w);
}

static inline unsigned long hweight64(u64 w)
{
	return (unsigned long)__builtin_popcountll(w);
}

static inline unsigned long hweight_long(unsigned long w)
{
	return (unsigned long)__builtin_popcountl(w);
}

/* The next set bit at or after offset, or size if none. */
static inline unsigned long find_next_bit(const unsigned long *addr, unsigned long size,
					  unsigned long offset)
{
	for (; offset < size; offset++)
		if (test_bit(offset, addr))
			return offset;
	return size;
}

/* The next clear bit at or after offset, or size if none. */
static inline unsigned long find_next_zero_bit(const unsigned long *addr, unsigned long size,
					       unsigned long offset)
{
	for (; offset < size; offset++)
		if (!test_bit(offset, addr))
			return offset;
	return size;
}

#define find_first_bit(addr, size)	find_next_bit((addr), (size), 0)
#define find_first_zero_bit(addr, size)	find_next_zero_bit((addr), (size), 0)

#define for_each_set_bit(bit, addr, size)					\
	for ((bit) = find_first_bit((addr), (size)); (bit) < (size);		\
	     (bit) = find_next_bit((addr), (size), (bit) + 1))

#define for_each_clear_bit(bit, addr, size)					\
	for ((bit) = find_first_zero_bit((addr), (size)); (bit) < (size);	\
	     (bit) = find_next_zero_bit((addr), (size), (bit) + 1))

static inline u32 rol32(u32 word, unsigned int shift)
{
	return (word << (shift & 31)) | (word >> ((-shift) & 31));
}

static inline u32 ror32(u32 word, unsigned int shift)
{
	return (word >> (shift & 31)) | (word << ((-shift) & 31));
}

#endif /* _LINUX_BITOPS_H */
