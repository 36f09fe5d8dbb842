/*
 * test_kfifo.c — typed kfifos (include/linux/kfifo.h's interface): a fifo
 * of structs declared with DECLARE_KFIFO and INIT_KFIFO, DEFINE_KFIFO,
 * DECLARE_KFIFO_PTR with kfifo_alloc, counts in elements across the wrap,
 * kfifo_put/get/peek typed as the element, kfifo_in/out_spinlocked shared by
 * an IRQ handler and a task, kfifo_to_user/from_user moving whole elements,
 * and the byte fifo (struct kfifo) with kfifo_init.
 */
#include "lx_test.h"
#include <linux/interrupt.h>
#include <linux/kfifo.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux/uaccess.h>
#include <mach/irqs.h>

struct sample {
	u32 seq;
	u16 value;
	u8 port;
};

struct holder {
	int before;
	DECLARE_KFIFO(fifo, struct sample, 8);
	int after;
};

static DEFINE_KFIFO(defined, u16, 4);
static DEFINE_SPINLOCK(fifo_lock);
static struct holder h;
static unsigned int irq_put;

static irqreturn_t producer(int irq, void *dev)
{
	struct sample s = { .seq = 100 + irq_put, .value = 7, .port = 2 };

	irq_put += kfifo_in_spinlocked(&h.fifo, &s, 1, &fifo_lock);
	return IRQ_HANDLED;
}

static void typed_tests(void)
{
	struct sample s, out[8] = { { 0 } };
	unsigned int i;

	INIT_KFIFO(h.fifo);
	is_int((int)kfifo_size(&h.fifo), 8, "DECLARE_KFIFO of 8 structs holds 8");
	is_int((int)kfifo_esize(&h.fifo), (int)sizeof(struct sample), "its element size is the struct's");
	ok(kfifo_initialized(&h.fifo) && kfifo_is_empty(&h.fifo), "INIT_KFIFO: initialised and empty");
	for (i = 0; i < 10; i++) {
		s = (struct sample){ .seq = i, .value = (u16)(i * 10), .port = (u8)i };
		if (!kfifo_put(&h.fifo, s))
			break;
	}
	is_int((int)i, 8, "kfifo_put takes 8 elements, then refuses");
	ok(kfifo_is_full(&h.fifo) && kfifo_len(&h.fifo) == 8 && kfifo_avail(&h.fifo) == 0, "full");
	is_int((int)kfifo_out(&h.fifo, out, 3), 3, "kfifo_out 3 elements");
	ok(out[0].seq == 0 && out[2].value == 20 && out[2].port == 2, "whole structs, in order");
	for (i = 10; i < 13; i++) {
		s = (struct sample){ .seq = i, .value = (u16)(i * 10), .port = (u8)i };
		kfifo_put(&h.fifo, s);
	}
	ok(kfifo_peek(&h.fifo, &s) == 1 && s.seq == 3, "kfifo_peek sees the oldest");
	is_int((int)kfifo_out(&h.fifo, out, 8), 8, "the 8 left, across the wrap");
	ok(out[0].seq == 3 && out[4].seq == 7 && out[5].seq == 10 && out[7].seq == 12 && out[7].value == 120,
	   "in FIFO order across the wrap");
	ok(kfifo_get(&h.fifo, &s) == 0, "kfifo_get on an empty fifo: 0");

	is_int((int)kfifo_size(&defined), 4, "DEFINE_KFIFO of u16");
	ok(kfifo_put(&defined, 0xBEEF) == 1, "kfifo_put of a u16");
	{
		u16 v = 0;

		ok(kfifo_get(&defined, &v) == 1 && v == 0xBEEF, "kfifo_get gives it back whole");
	}
}

static void ptr_tests(void)
{
	DECLARE_KFIFO_PTR(dyn, struct sample);
	struct kfifo bytes;
	unsigned char store[10], b[4] = { 0 };
	struct sample s = { .seq = 5 };

	is_int(kfifo_alloc(&dyn, 5, GFP_KERNEL), 0, "kfifo_alloc of 5 structs");
	is_int((int)kfifo_size(&dyn), 8, "rounded up to 8 elements");
	ok(kfifo_put(&dyn, s) == 1 && kfifo_len(&dyn) == 1, "one element in");
	kfifo_free(&dyn);
	ok(!kfifo_initialized(&dyn), "kfifo_free");

	is_int(kfifo_init(&bytes, store, sizeof(store)), 0, "kfifo_init over 10 bytes");
	is_int((int)kfifo_size(&bytes), 8, "uses 8 of them");
	is_int((int)kfifo_in(&bytes, "abcdef", 6), 6, "struct kfifo takes any pointer");
	kfifo_skip(&bytes);
	ok(kfifo_out(&bytes, b, 2) == 2 && b[0] == 'b' && b[1] == 'c', "kfifo_skip dropped one");
	kfifo_reset(&bytes);
	ok(kfifo_is_empty(&bytes), "kfifo_reset");
}

static void user_tests(void)
{
	struct sample in[3] = { { .seq = 1 }, { .seq = 2 }, { .seq = 3 } }, out[3];
	unsigned int copied = 0;

	INIT_KFIFO(h.fifo);
	is_int(kfifo_from_user(&h.fifo, (const void __user *)in, sizeof(in) - 1, &copied), 0,
	       "kfifo_from_user of 3 structs' bytes less one");
	is_int((int)copied, (int)(2 * sizeof(struct sample)), "moves 2 whole elements");
	is_int((int)kfifo_len(&h.fifo), 2, "2 in the fifo");
	memset(out, 0, sizeof(out));
	is_int(kfifo_to_user(&h.fifo, (void __user *)out, sizeof(out), &copied), 0, "kfifo_to_user");
	ok(copied == 2 * sizeof(struct sample) && out[0].seq == 1 && out[1].seq == 2, "gives them back");
}

static void spinlocked_tests(void)
{
	struct sample s = { 0 };
	unsigned int taken = 0, i;

	INIT_KFIFO(h.fifo);
	is_int(request_irq(IRQ_DA8XX_UARTINT0, producer, 0, "producer", &h), 0, "an IRQ producer");
	for (i = 0; i < 5; i++) {
		rtos_host_irq_raise(IRQ_DA8XX_UARTINT0);
		taken += kfifo_out_spinlocked(&h.fifo, &s, 1, &fifo_lock);
	}
	free_irq(IRQ_DA8XX_UARTINT0, &h);
	is_int((int)irq_put, 5, "the handler put 5 with kfifo_in_spinlocked");
	is_int((int)taken, 5, "the task took 5 with kfifo_out_spinlocked");
	ok(s.seq == 104 && s.port == 2, "the last one whole");
	ok(kfifo_is_empty_spinlocked(&h.fifo, &fifo_lock), "kfifo_is_empty_spinlocked");
	ok(h.before == 0 && h.after == 0, "the embedded fifo stays inside its struct");
}

static void body(void)
{
	typed_tests();
	ptr_tests();
	user_tests();
	spinlocked_tests();
}

int main(void)
{
	tap_plan(35);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
