/*
 * linux/idr.h — ID allocators (Linux 6.1's include/linux/idr.h), the IDA
 * part: the smallest free ID in a range, as drivers number their devices
 * ("motor%d").  Implemented by linux_compat/src/idr.c over a bitmap of
 * LX_IDA_MAX IDs (Linux's grows without bound); any context, as Linux's
 * with GFP_ATOMIC.
 */
#ifndef __IDR_H__
#define __IDR_H__

#include <linux/bitops.h>
#include <linux/gfp.h>
#include <linux/spinlock.h>
#include <linux/types.h>

#define LX_IDA_MAX	256

struct ida {
	spinlock_t lock;
	unsigned long bits[BITS_TO_LONGS(LX_IDA_MAX)];
};

#define IDA_INIT(name)	{ .lock = __SPIN_LOCK_UNLOCKED(name.lock) }
#define DEFINE_IDA(name)	struct ida name = IDA_INIT(name)

static inline void ida_init(struct ida *ida)
{
	unsigned int i;

	spin_lock_init(&ida->lock);
	for (i = 0; i < BITS_TO_LONGS(LX_IDA_MAX); i++)
		ida->bits[i] = 0;
}

/* The smallest free ID in [min, max], taken: it, or -ENOSPC (none free below
 * LX_IDA_MAX) or -EINVAL (min > max, min < 0). */
int ida_alloc_range(struct ida *ida, unsigned int min, unsigned int max, gfp_t gfp);
/* Gives id back (an ID not taken is reported). */
void ida_free(struct ida *ida, unsigned int id);
/* Gives every ID back. */
void ida_destroy(struct ida *ida);

static inline int ida_alloc(struct ida *ida, gfp_t gfp)
{
	return ida_alloc_range(ida, 0, ~0U, gfp);
}
static inline int ida_alloc_min(struct ida *ida, unsigned int min, gfp_t gfp)
{
	return ida_alloc_range(ida, min, ~0U, gfp);
}
static inline int ida_alloc_max(struct ida *ida, unsigned int max, gfp_t gfp)
{
	return ida_alloc_range(ida, 0, max, gfp);
}
static inline bool ida_is_empty(const struct ida *ida)
{
	return find_next_bit(ida->bits, LX_IDA_MAX, 0) >= LX_IDA_MAX;
}

#endif /* __IDR_H__ */
