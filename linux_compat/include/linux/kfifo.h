/*
 * linux/kfifo.h — typed FIFOs with one reader and one writer, as Linux 6.1's
 * include/linux/kfifo.h defines them: a fifo holds elements of its declared
 * type (bytes for struct kfifo), its size is a power of two, in and out are
 * free-running element counters, so one producer (e.g. an IRQ handler) and
 * one consumer (e.g. read()) need no lock; the _spinlocked forms take a
 * spin lock with interrupts off for several of either.
 *
 * DECLARE_KFIFO(fifo, type, size) embeds the buffer (size a power of two
 * >= 2, else "size of array is negative" as in Linux), DECLARE_KFIFO_PTR /
 * struct kfifo take one from kfifo_alloc or kfifo_init.  Counts passed to
 * and returned by kfifo_in/out are elements; kfifo_to_user/from_user take
 * and report bytes, moving whole elements.
 *
 * Difference from Linux: no record fifos (recsize is always 0), no DMA helpers.
 */
#ifndef _LINUX_KFIFO_H
#define _LINUX_KFIFO_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/errno.h>
#include <linux/gfp.h>
#include <linux/kernel.h>
#include <linux/spinlock.h>

struct __kfifo {
	unsigned int in;      /* elements ever put */
	unsigned int out;     /* elements ever taken */
	unsigned int mask;    /* size in elements - 1 */
	unsigned int esize;   /* bytes per element */
	void *data;
};

/* The fifo header, and typed pointers that carry the element type for the macros. */
#define __STRUCT_KFIFO_COMMON(datatype, ptrtype)				\
	union {									\
		struct __kfifo kfifo;						\
		datatype *type;							\
		const datatype *const_type;					\
		ptrtype *ptr;							\
		ptrtype const *ptr_const;					\
	}

#define __STRUCT_KFIFO(type, size, ptrtype)					\
{										\
	__STRUCT_KFIFO_COMMON(type, ptrtype);					\
	type buf[(((size) < 2) || ((size) & ((size) - 1))) ? -1 : (size)];	\
}
#define STRUCT_KFIFO(type, size)	struct __STRUCT_KFIFO(type, size, type)

#define __STRUCT_KFIFO_PTR(type, ptrtype)					\
{										\
	__STRUCT_KFIFO_COMMON(type, ptrtype);					\
	type buf[0];								\
}
#define STRUCT_KFIFO_PTR(type)		struct __STRUCT_KFIFO_PTR(type, type)

/* The byte fifo with an allocated buffer; any pointer goes in and out. */
struct kfifo __STRUCT_KFIFO_PTR(unsigned char, void);

/* Whether fifo has no buffer of its own (DECLARE_KFIFO_PTR, struct kfifo). */
#define __is_kfifo_ptr(fifo) \
	(sizeof(*(fifo)) == sizeof(STRUCT_KFIFO_PTR(typeof(*(fifo)->type))))

#define DECLARE_KFIFO_PTR(fifo, type)	STRUCT_KFIFO_PTR(type) fifo
#define DECLARE_KFIFO(fifo, type, size)	STRUCT_KFIFO(type, size) fifo

/* Initialises a DECLARE_KFIFO fifo empty over its own buffer. */
#define INIT_KFIFO(fifo)							\
	(void)({								\
		typeof(&(fifo)) __lx_t = &(fifo);				\
		struct __kfifo *__lx_k = &__lx_t->kfifo;			\
		__lx_k->in = 0;							\
		__lx_k->out = 0;						\
		__lx_k->mask = __is_kfifo_ptr(__lx_t) ? 0 : ARRAY_SIZE(__lx_t->buf) - 1; \
		__lx_k->esize = sizeof(*__lx_t->buf);				\
		__lx_k->data = __is_kfifo_ptr(__lx_t) ? NULL : __lx_t->buf;	\
		0;								\
	})

#define DEFINE_KFIFO(fifo, type, size)						\
	DECLARE_KFIFO(fifo, type, size) = (typeof(fifo)) { { {			\
		.in = 0, .out = 0,						\
		.mask = __is_kfifo_ptr(&(fifo)) ? 0 : ARRAY_SIZE((fifo).buf) - 1, \
		.esize = sizeof(*(fifo).buf),					\
		.data = __is_kfifo_ptr(&(fifo)) ? NULL : (fifo).buf,		\
	} } }

/* Allocates size elements of esize bytes (size rounded up to a power of two): 0, -EINVAL or -ENOMEM. */
int __kfifo_alloc(struct __kfifo *fifo, unsigned int size, size_t esize, gfp_t gfp);
/* Frees it (the fifo is left empty and unusable). */
void __kfifo_free(struct __kfifo *fifo);
/* Uses buffer of size bytes (elements rounded down to a power of two): 0 or -EINVAL. */
int __kfifo_init(struct __kfifo *fifo, void *buffer, unsigned int size, size_t esize);
/* Copies up to len elements in / out; the number copied. */
unsigned int __kfifo_in(struct __kfifo *fifo, const void *buf, unsigned int len);
unsigned int __kfifo_out(struct __kfifo *fifo, void *buf, unsigned int len);
/* As __kfifo_out without removing them. */
unsigned int __kfifo_out_peek(struct __kfifo *fifo, void *buf, unsigned int len);
/* With user memory, len and *copied in bytes (whole elements): 0 or -EFAULT. */
int __kfifo_to_user(struct __kfifo *fifo, void __user *to, unsigned long len, unsigned int *copied);
int __kfifo_from_user(struct __kfifo *fifo, const void __user *from, unsigned long len,
		      unsigned int *copied);

#define kfifo_initialized(fifo)	((fifo)->kfifo.mask != 0)
#define kfifo_esize(fifo)	((fifo)->kfifo.esize)
#define kfifo_recsize(fifo)	(0U)
#define kfifo_size(fifo)	((fifo)->kfifo.mask + 1)
#define kfifo_reset(fifo)	(void)({ typeof((fifo) + 1) __lx_t = (fifo);	\
					 __lx_t->kfifo.in = __lx_t->kfifo.out = 0; })
#define kfifo_reset_out(fifo)	(void)({ typeof((fifo) + 1) __lx_t = (fifo);	\
					 __lx_t->kfifo.out = READ_ONCE(__lx_t->kfifo.in); })
#define kfifo_len(fifo)		({ typeof((fifo) + 1) __lx_l = (fifo);		\
				   READ_ONCE(__lx_l->kfifo.in) - READ_ONCE(__lx_l->kfifo.out); })
#define kfifo_is_empty(fifo)	(kfifo_len(fifo) == 0)
#define kfifo_is_full(fifo)	(kfifo_len(fifo) > (fifo)->kfifo.mask)
#define kfifo_avail(fifo)	(kfifo_size(fifo) - kfifo_len(fifo))
#define kfifo_skip(fifo)	(void)({ typeof((fifo) + 1) __lx_t = (fifo);	\
					 if (!kfifo_is_empty(__lx_t)) __lx_t->kfifo.out++; })

#define kfifo_alloc(fifo, size, gfp)						\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   __is_kfifo_ptr(__lx_t) ?						\
		__kfifo_alloc(&__lx_t->kfifo, (size), sizeof(*__lx_t->type), (gfp)) : -EINVAL; })
#define kfifo_free(fifo)							\
	(void)({ typeof((fifo) + 1) __lx_t = (fifo);				\
		 if (__is_kfifo_ptr(__lx_t)) __kfifo_free(&__lx_t->kfifo); })
#define kfifo_init(fifo, buffer, size)						\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   __is_kfifo_ptr(__lx_t) ?						\
		__kfifo_init(&__lx_t->kfifo, (buffer), (size), sizeof(*__lx_t->type)) : -EINVAL; })

/* One element in or out, typed as the fifo's: 1 if it moved, 0 if full / empty. */
#define kfifo_put(fifo, val)							\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   typeof(*__lx_t->const_type) __lx_v = (val);				\
	   __kfifo_in(&__lx_t->kfifo, &__lx_v, 1); })
#define kfifo_get(fifo, val)							\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   typeof(__lx_t->ptr) __lx_p = (val);					\
	   __kfifo_out(&__lx_t->kfifo, __lx_p, 1); })
#define kfifo_peek(fifo, val)							\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   typeof(__lx_t->ptr) __lx_p = (val);					\
	   __kfifo_out_peek(&__lx_t->kfifo, __lx_p, 1); })

/* n elements from buf in / to buf out; the number moved. */
#define kfifo_in(fifo, buf, n)							\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   typeof(__lx_t->ptr_const) __lx_b = (buf);				\
	   __kfifo_in(&__lx_t->kfifo, __lx_b, (n)); })
#define kfifo_out(fifo, buf, n)							\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   typeof(__lx_t->ptr) __lx_b = (buf);					\
	   __kfifo_out(&__lx_t->kfifo, __lx_b, (n)); })
#define kfifo_out_peek(fifo, buf, n)						\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   typeof(__lx_t->ptr) __lx_b = (buf);					\
	   __kfifo_out_peek(&__lx_t->kfifo, __lx_b, (n)); })

/* kfifo_in / kfifo_out holding lock with interrupts off (several writers or readers). */
#define kfifo_in_spinlocked(fifo, buf, n, lock)					\
	({ unsigned long __lx_f; unsigned int __lx_r;				\
	   spin_lock_irqsave((lock), __lx_f);					\
	   __lx_r = kfifo_in((fifo), (buf), (n));				\
	   spin_unlock_irqrestore((lock), __lx_f);				\
	   __lx_r; })
#define kfifo_out_spinlocked(fifo, buf, n, lock)				\
	({ unsigned long __lx_f; unsigned int __lx_r;				\
	   spin_lock_irqsave((lock), __lx_f);					\
	   __lx_r = kfifo_out((fifo), (buf), (n));				\
	   spin_unlock_irqrestore((lock), __lx_f);				\
	   __lx_r; })
#define kfifo_in_spinlocked_noirqsave(fifo, buf, n, lock)			\
	({ unsigned int __lx_r; spin_lock(lock);				\
	   __lx_r = kfifo_in((fifo), (buf), (n)); spin_unlock(lock); __lx_r; })
#define kfifo_out_spinlocked_noirqsave(fifo, buf, n, lock)			\
	({ unsigned int __lx_r; spin_lock(lock);				\
	   __lx_r = kfifo_out((fifo), (buf), (n)); spin_unlock(lock); __lx_r; })
/* The names before 4.x. */
#define kfifo_in_locked(fifo, buf, n, lock)	kfifo_in_spinlocked((fifo), (buf), (n), (lock))
#define kfifo_out_locked(fifo, buf, n, lock)	kfifo_out_spinlocked((fifo), (buf), (n), (lock))
#define kfifo_is_empty_spinlocked(fifo, lock)					\
	({ unsigned long __lx_f; bool __lx_r;					\
	   spin_lock_irqsave((lock), __lx_f);					\
	   __lx_r = kfifo_is_empty(fifo);					\
	   spin_unlock_irqrestore((lock), __lx_f);				\
	   __lx_r; })

#define kfifo_to_user(fifo, to, len, copied)					\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   __kfifo_to_user(&__lx_t->kfifo, (to), (len), (copied)); })
#define kfifo_from_user(fifo, from, len, copied)				\
	({ typeof((fifo) + 1) __lx_t = (fifo);					\
	   __kfifo_from_user(&__lx_t->kfifo, (from), (len), (copied)); })

#endif /* _LINUX_KFIFO_H */
