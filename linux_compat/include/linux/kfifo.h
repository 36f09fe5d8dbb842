/*
 * linux/kfifo.h — a byte FIFO with one reader and one writer, as Linux's:
 * the size is a power of two, in and out are free-running counters, so one
 * producer (e.g. an IRQ handler) and one consumer (e.g. read()) need no lock.
 *
 * Difference from Linux: elements are bytes (DECLARE_KFIFO/DEFINE_KFIFO
 * refuse other element types at compile time) and there are no record
 * fifos; kfifo_to_user/kfifo_from_user are provided.
 */
#ifndef _LINUX_KFIFO_H
#define _LINUX_KFIFO_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/errno.h>
#include <linux/build_bug.h>
#include <linux/gfp.h>

struct __kfifo {
	unsigned int in;      /* bytes ever put */
	unsigned int out;     /* bytes ever taken */
	unsigned int mask;    /* size - 1 */
	unsigned char *data;
};

struct kfifo {
	struct __kfifo kfifo;
};

/* A fifo with its buffer of size bytes (a power of two) inside. */
#define DECLARE_KFIFO(fifo, type, size)						\
	struct {								\
		struct __kfifo kfifo;						\
		unsigned char buf[(size) + BUILD_BUG_ON_ZERO(sizeof(type) != 1) +	\
				  BUILD_BUG_ON_ZERO(((size) & ((size) - 1)) != 0)];	\
	} fifo
#define INIT_KFIFO(fifo)							\
	((fifo).kfifo = (struct __kfifo){ 0, 0, sizeof((fifo).buf) - 1, (fifo).buf })
#define DEFINE_KFIFO(fifo, type, size)						\
	DECLARE_KFIFO(fifo, type, size) = {					\
		.kfifo = { 0, 0, (size) - 1, (fifo).buf } }

/* Allocates a buffer of size rounded up to a power of two: 0 or -ENOMEM/-EINVAL. */
int __kfifo_alloc(struct __kfifo *fifo, unsigned int size, gfp_t gfp);
/* Frees it (the fifo is left empty and unusable). */
void __kfifo_free(struct __kfifo *fifo);
/* Uses buffer (size rounded down to a power of two): 0 or -EINVAL. */
int __kfifo_init(struct __kfifo *fifo, void *buffer, unsigned int size);
/* Copies up to len bytes in / out; the number copied. */
unsigned int __kfifo_in(struct __kfifo *fifo, const void *buf, unsigned int len);
unsigned int __kfifo_out(struct __kfifo *fifo, void *buf, unsigned int len);
/* As __kfifo_out without removing them. */
unsigned int __kfifo_out_peek(struct __kfifo *fifo, void *buf, unsigned int len);
/* With user memory: 0 or -EFAULT; *copied is the number of bytes moved. */
int __kfifo_to_user(struct __kfifo *fifo, void __user *to, unsigned long len, unsigned int *copied);
int __kfifo_from_user(struct __kfifo *fifo, const void __user *from, unsigned long len,
		      unsigned int *copied);

#define kfifo_alloc(fifo, size, gfp)	__kfifo_alloc(&(fifo)->kfifo, (size), (gfp))
#define kfifo_free(fifo)		__kfifo_free(&(fifo)->kfifo)
#define kfifo_init(fifo, buf, size)	__kfifo_init(&(fifo)->kfifo, (buf), (size))
#define kfifo_in(fifo, buf, n)		__kfifo_in(&(fifo)->kfifo, (buf), (n))
#define kfifo_out(fifo, buf, n)		__kfifo_out(&(fifo)->kfifo, (buf), (n))
#define kfifo_out_peek(fifo, buf, n)	__kfifo_out_peek(&(fifo)->kfifo, (buf), (n))
#define kfifo_to_user(fifo, to, len, copied)	__kfifo_to_user(&(fifo)->kfifo, (to), (len), (copied))
#define kfifo_from_user(fifo, from, len, copied) \
	__kfifo_from_user(&(fifo)->kfifo, (from), (len), (copied))
#define kfifo_put(fifo, val)	({ unsigned char __lx_v = (val); kfifo_in((fifo), &__lx_v, 1); })
#define kfifo_get(fifo, valp)	kfifo_out((fifo), (valp), 1)
#define kfifo_peek(fifo, valp)	kfifo_out_peek((fifo), (valp), 1)
#define kfifo_size(fifo)	((fifo)->kfifo.mask + 1)
#define kfifo_len(fifo)		(READ_ONCE((fifo)->kfifo.in) - READ_ONCE((fifo)->kfifo.out))
#define kfifo_avail(fifo)	(kfifo_size(fifo) - kfifo_len(fifo))
#define kfifo_is_empty(fifo)	(kfifo_len(fifo) == 0)
#define kfifo_is_full(fifo)	(kfifo_len(fifo) > (fifo)->kfifo.mask)
#define kfifo_reset(fifo)	((fifo)->kfifo.in = (fifo)->kfifo.out = 0)
#define kfifo_reset_out(fifo)	((fifo)->kfifo.out = READ_ONCE((fifo)->kfifo.in))
#define kfifo_initialized(fifo)	((fifo)->kfifo.mask != 0)

#endif /* _LINUX_KFIFO_H */
