/*
 * kfifo.c — the byte FIFO of linux/kfifo.h.  The writer publishes in only
 * after the data, the reader out only after copying (barrier() on this one
 * CPU), so one of each needs no lock.
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

int __kfifo_alloc(struct __kfifo *fifo, unsigned int size, gfp_t gfp)
{
	fifo->in = fifo->out = 0;
	fifo->mask = 0;
	fifo->data = NULL;
	if (size < 2 || size > (1U << 31))
		return -EINVAL;
	size = pow2_floor(size) == size ? size : pow2_floor(size) << 1;
	fifo->data = kmalloc(size, gfp);
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

int __kfifo_init(struct __kfifo *fifo, void *buffer, unsigned int size)
{
	fifo->in = fifo->out = 0;
	fifo->data = buffer;
	if (!buffer || size < 2) {
		fifo->mask = 0;
		return -EINVAL;
	}
	fifo->mask = pow2_floor(size) - 1;
	return 0;
}

/* Copies len bytes between buf and the ring at offset off (wrapping). */
static void ring_copy(struct __kfifo *fifo, unsigned int off, void *buf, unsigned int len, bool in)
{
	unsigned int size = fifo->mask + 1;
	unsigned int first;

	off &= fifo->mask;
	first = min(len, size - off);
	if (in) {
		memcpy(fifo->data + off, buf, first);
		memcpy(fifo->data, (unsigned char *)buf + first, len - first);
	} else {
		memcpy(buf, fifo->data + off, first);
		memcpy((unsigned char *)buf + first, fifo->data, len - first);
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

int __kfifo_to_user(struct __kfifo *fifo, void __user *to, unsigned long len, unsigned int *copied)
{
	unsigned char chunk[64];
	unsigned int done = 0, n;

	while (done < len) {
		n = __kfifo_out_peek(fifo, chunk, (unsigned int)min_t(unsigned long, len - done, sizeof(chunk)));
		if (n == 0)
			break;
		if (copy_to_user((unsigned char __user *)to + done, chunk, n)) {
			*copied = done;
			return -EFAULT;
		}
		WRITE_ONCE(fifo->out, fifo->out + n);
		done += n;
	}
	*copied = done;
	return 0;
}

int __kfifo_from_user(struct __kfifo *fifo, const void __user *from, unsigned long len,
		      unsigned int *copied)
{
	unsigned char chunk[64];
	unsigned int done = 0, n, avail;

	while (done < len) {
		avail = fifo->mask + 1 - (fifo->in - READ_ONCE(fifo->out));
		n = (unsigned int)min3(len - done, (unsigned long)sizeof(chunk), (unsigned long)avail);
		if (n == 0)
			break;
		if (copy_from_user(chunk, (const unsigned char __user *)from + done, n)) {
			*copied = done;
			return -EFAULT;
		}
		(void)__kfifo_in(fifo, chunk, n);
		done += n;
	}
	*copied = done;
	return 0;
}
