/*
 * kfifo.c — the element FIFO of linux/kfifo.h (counts in elements of
 * esize bytes).  The writer publishes in only after the data, the reader out
 * only after copying (barrier() on this one CPU), so one of each needs no lock.
 */
#include <linux/kfifo.h>
#include <linux/kernel.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/uaccess.h>

/* Largest power of two not above n (n > 0). */
static unsigned int pow2_floor(unsigned int n)
{
	return 1U << (31 - __builtin_clz(n));
}

int __kfifo_alloc(struct __kfifo *fifo, unsigned int size, size_t esize, gfp_t gfp)
{
	fifo->in = fifo->out = 0;
	fifo->mask = 0;
	fifo->esize = (unsigned int)esize;
	fifo->data = NULL;
	if (size < 2 || size > (1U << 31) || esize == 0)
		return -EINVAL;
	size = pow2_floor(size) == size ? size : pow2_floor(size) << 1;
	if (esize > SIZE_MAX / size)
		return -EINVAL;
	fifo->data = kmalloc_array(size, esize, gfp);
	if (!fifo->data)
		return -ENOMEM;
	fifo->mask = size - 1;
	return 0;
}

void __kfifo_free(struct __kfifo *fifo)
{
	kfree(fifo->data);
	fifo->in = fifo->out = 0;
	fifo->mask = 0;
	fifo->data = NULL;
}

int __kfifo_init(struct __kfifo *fifo, void *buffer, unsigned int size, size_t esize)
{
	fifo->in = fifo->out = 0;
	fifo->esize = (unsigned int)esize;
	fifo->data = buffer;
	if (esize)
		size /= (unsigned int)esize;
	if (!buffer || size < 2) {
		fifo->mask = 0;
		return -EINVAL;
	}
	fifo->mask = pow2_floor(size) - 1;
	return 0;
}

/* Copies len elements between buf and the ring at element off (wrapping). */
static void ring_copy(struct __kfifo *fifo, unsigned int off, void *buf, unsigned int len, bool in)
{
	size_t esize = fifo->esize;
	unsigned char *data = fifo->data;
	unsigned int size = fifo->mask + 1;
	unsigned int first;

	off &= fifo->mask;
	first = min(len, size - off);
	if (in) {
		memcpy(data + off * esize, buf, first * esize);
		memcpy(data, (unsigned char *)buf + first * esize, (len - first) * esize);
	} else {
		memcpy(buf, data + off * esize, first * esize);
		memcpy((unsigned char *)buf + first * esize, data, (len - first) * esize);
	}
}

unsigned int __kfifo_in(struct __kfifo *fifo, const void *buf, unsigned int len)
{
	unsigned int avail = fifo->mask + 1 - (fifo->in - READ_ONCE(fifo->out));

	len = min(len, avail);
	if (len == 0 || fifo->mask == 0)
		return 0;
	ring_copy(fifo, fifo->in, (void *)buf, len, true);
	barrier();
	WRITE_ONCE(fifo->in, fifo->in + len);
	return len;
}

unsigned int __kfifo_out_peek(struct __kfifo *fifo, void *buf, unsigned int len)
{
	unsigned int used = READ_ONCE(fifo->in) - fifo->out;

	len = min(len, used);
	if (len == 0)
		return 0;
	barrier();
	ring_copy(fifo, fifo->out, buf, len, false);
	return len;
}

unsigned int __kfifo_out(struct __kfifo *fifo, void *buf, unsigned int len)
{
	len = __kfifo_out_peek(fifo, buf, len);
	barrier();
	WRITE_ONCE(fifo->out, fifo->out + len);
	return len;
}

/* Copies len elements at ring element off to or from user memory; returns
 * the number of whole elements not copied (Linux's kfifo_copy_to/from_user). */
static unsigned int ring_copy_user(struct __kfifo *fifo, unsigned int off, void __user *ubuf,
				   unsigned int len, bool to_user)
{
	size_t esize = fifo->esize;
	unsigned char *data = fifo->data;
	unsigned int first;
	unsigned long left;

	off &= fifo->mask;
	first = min(len, fifo->mask + 1 - off);
	if (to_user)
		left = copy_to_user(ubuf, data + off * esize, first * esize);
	else
		left = copy_from_user(data + off * esize, (const void __user *)ubuf, first * esize);
	if (left)
		return (unsigned int)DIV_ROUND_UP(left + (len - first) * esize, esize);
	if (to_user)
		left = copy_to_user((unsigned char __user *)ubuf + first * esize, data, (len - first) * esize);
	else
		left = copy_from_user(data, (const unsigned char __user *)ubuf + first * esize,
				      (len - first) * esize);
	return (unsigned int)DIV_ROUND_UP(left, esize);
}

int __kfifo_to_user(struct __kfifo *fifo, void __user *to, unsigned long len, unsigned int *copied)
{
	unsigned int n, missed;

	*copied = 0;
	if (fifo->esize == 0)
		return -EINVAL;
	n = (unsigned int)min_t(unsigned long, len / fifo->esize, READ_ONCE(fifo->in) - fifo->out);
	if (n == 0)
		return 0;
	barrier();
	missed = ring_copy_user(fifo, fifo->out, to, n, true);
	n -= missed;
	barrier();
	WRITE_ONCE(fifo->out, fifo->out + n);
	*copied = n * fifo->esize;
	return missed ? -EFAULT : 0;
}

int __kfifo_from_user(struct __kfifo *fifo, const void __user *from, unsigned long len,
		      unsigned int *copied)
{
	unsigned int n, missed;

	*copied = 0;
	if (fifo->esize == 0)
		return -EINVAL;
	n = (unsigned int)min_t(unsigned long, len / fifo->esize,
				fifo->mask + 1 - (fifo->in - READ_ONCE(fifo->out)));
	if (n == 0 || fifo->mask == 0)
		return 0;
	missed = ring_copy_user(fifo, fifo->in, (void __user *)from, n, false);
	n -= missed;
	barrier();
	WRITE_ONCE(fifo->in, fifo->in + n);
	*copied = n * fifo->esize;
	return missed ? -EFAULT : 0;
}
