/*
 * idr.c — the IDA (linux/idr.h states the contract): a bitmap of IDs under
 * its spin lock.
 */
#include <linux/idr.h>
#include <linux/errno.h>
#include <linux/kernel.h>
#include <linux_compat/report.h>

int ida_alloc_range(struct ida *ida, unsigned int min, unsigned int max, gfp_t gfp)
{
	unsigned long flags, id;

	if (min > max || (int)min < 0)
		return -EINVAL;
	if (max >= LX_IDA_MAX)
		max = LX_IDA_MAX - 1;
	spin_lock_irqsave(&ida->lock, flags);
	id = find_next_zero_bit(ida->bits, (unsigned long)max + 1, min);
	if (id > max) {
		spin_unlock_irqrestore(&ida->lock, flags);
		return -ENOSPC;
	}
	__set_bit(id, ida->bits);
	spin_unlock_irqrestore(&ida->lock, flags);
	return (int)id;
}

void ida_free(struct ida *ida, unsigned int id)
{
	unsigned long flags;
	bool was;

	spin_lock_irqsave(&ida->lock, flags);
	was = id < LX_IDA_MAX && test_bit(id, ida->bits);
	if (was)
		__clear_bit(id, ida->bits);
	spin_unlock_irqrestore(&ida->lock, flags);
	if (!was)
		lx_warn(__FILE__, __LINE__, "ida_free called for id=%u which is not allocated.", id);
}

void ida_destroy(struct ida *ida)
{
	unsigned long flags;
	unsigned int i;

	spin_lock_irqsave(&ida->lock, flags);
	for (i = 0; i < BITS_TO_LONGS(LX_IDA_MAX); i++)
		ida->bits[i] = 0;
	spin_unlock_irqrestore(&ida->lock, flags);
}
