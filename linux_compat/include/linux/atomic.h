/*
 * linux/atomic.h — atomic_t operations, atomic against interrupts on one
 * CPU: each read-modify-write runs with interrupts masked (local_irq_save).
 * Legal in any context.  Plain reads and writes are single accesses.
 */
#ifndef _LINUX_ATOMIC_H
#define _LINUX_ATOMIC_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/irqflags.h>

/* The lock around every read-modify-write: interrupts masked, as on a UP Linux kernel. */
#define __lx_atomic_rmw(stmt) \
	({ unsigned long __lx_flags; local_irq_save(__lx_flags); stmt; local_irq_restore(__lx_flags); })

static inline int atomic_read(const atomic_t *v)	{ return READ_ONCE(v->counter); }
static inline void atomic_set(atomic_t *v, int i)	{ WRITE_ONCE(v->counter, i); }

/* v += i; returns the new value. */
static inline int atomic_add_return(int i, atomic_t *v)
{
	int r;

	__lx_atomic_rmw(r = (v->counter += i));
	return r;
}
/* v += i; returns the old value. */
static inline int atomic_fetch_add(int i, atomic_t *v)
{
	int r;

	__lx_atomic_rmw((r = v->counter, v->counter += i));
	return r;
}
/* If v == old, v = new; returns the old value. */
static inline int atomic_cmpxchg(atomic_t *v, int old, int new_value)
{
	int r;

	__lx_atomic_rmw((r = v->counter, (void)(r == old ? (v->counter = new_value) : 0)));
	return r;
}
/* v = new; returns the old value. */
static inline int atomic_xchg(atomic_t *v, int new_value)
{
	int r;

	__lx_atomic_rmw((r = v->counter, v->counter = new_value));
	return r;
}
/* v &= i / v |= i / v ^= i / v &= ~i. */
static inline void atomic_and(int i, atomic_t *v)	{ __lx_atomic_rmw(v->counter &= i); }
static inline void atomic_or(int i, atomic_t *v)	{ __lx_atomic_rmw(v->counter |= i); }
static inline void atomic_xor(int i, atomic_t *v)	{ __lx_atomic_rmw(v->counter ^= i); }
static inline void atomic_andnot(int i, atomic_t *v)	{ __lx_atomic_rmw(v->counter &= ~i); }
/* v += a unless v == u; true if it added. */
static inline bool atomic_add_unless(atomic_t *v, int a, int u)
{
	bool added;

	__lx_atomic_rmw((added = v->counter != u, (void)(added ? (v->counter += a) : 0)));
	return added;
}
/* If v == *old, v = new and true; else *old = v and false. */
static inline bool atomic_try_cmpxchg(atomic_t *v, int *old, int new_value)
{
	int r = atomic_cmpxchg(v, *old, new_value);
	bool ok = r == *old;

	*old = r;
	return ok;
}

static inline int atomic_sub_return(int i, atomic_t *v)	{ return atomic_add_return(-i, v); }
static inline int atomic_inc_return(atomic_t *v)	{ return atomic_add_return(1, v); }
static inline int atomic_dec_return(atomic_t *v)	{ return atomic_add_return(-1, v); }
static inline int atomic_fetch_sub(int i, atomic_t *v)	{ return atomic_fetch_add(-i, v); }
static inline int atomic_fetch_inc(atomic_t *v)		{ return atomic_fetch_add(1, v); }
static inline int atomic_fetch_dec(atomic_t *v)		{ return atomic_fetch_add(-1, v); }
static inline void atomic_add(int i, atomic_t *v)	{ (void)atomic_add_return(i, v); }
static inline void atomic_sub(int i, atomic_t *v)	{ (void)atomic_add_return(-i, v); }
static inline void atomic_inc(atomic_t *v)		{ (void)atomic_add_return(1, v); }
static inline void atomic_dec(atomic_t *v)		{ (void)atomic_add_return(-1, v); }
static inline bool atomic_dec_and_test(atomic_t *v)	{ return atomic_add_return(-1, v) == 0; }
static inline bool atomic_inc_and_test(atomic_t *v)	{ return atomic_add_return(1, v) == 0; }
static inline bool atomic_sub_and_test(int i, atomic_t *v) { return atomic_add_return(-i, v) == 0; }
static inline bool atomic_add_negative(int i, atomic_t *v) { return atomic_add_return(i, v) < 0; }
static inline bool atomic_inc_not_zero(atomic_t *v)	{ return atomic_add_unless(v, 1, 0); }

#define atomic_read_acquire(v)		atomic_read(v)
#define atomic_set_release(v, i)	atomic_set((v), (i))

/* The Linux barriers: the CPU does not reorder against itself. */
#define smp_mb()			barrier()
#define smp_rmb()			barrier()
#define smp_wmb()			barrier()
#ifndef mb				/* asm/io.h may have defined them */
#define mb()				barrier()
#define rmb()				barrier()
#define wmb()				barrier()
#endif
#define smp_mb__before_atomic()		barrier()
#define smp_mb__after_atomic()		barrier()
#define smp_store_release(p, v)		do { barrier(); WRITE_ONCE(*(p), (v)); } while (0)
#define smp_load_acquire(p)		({ __typeof__(*(p)) __lx_v = READ_ONCE(*(p)); barrier(); __lx_v; })

#endif /* _LINUX_ATOMIC_H */
