/*
 * test_da8xx_reach.c — <mach/da8xx.h> alone makes visible what TI's 2.6.33
 * one reaches through its includes (LEGO's am1808.h includes only it, and
 * d_pwm declares its handlers right after): irqreturn_t and request_irq
 * (linux/interrupt.h), EXPORT_SYMBOL and THIS_MODULE (linux/module.h).
 * Also <linux/circ_buf.h>'s index macros, as LEGO's d_iic uses them.
 */
#define KBUILD_MODNAME "da8xx_reach"
#include <mach/da8xx.h>

static irqreturn_t board_handler(int irq, void *dev)
{
	(void)irq;
	(void)dev;
	return IRQ_HANDLED;
}

int board_counter;
EXPORT_SYMBOL(board_counter);

#include <linux/circ_buf.h>
#include "tap.h"

int main(void)
{
	irqreturn_t (*handler)(int, void *) = board_handler;
	int (*request)(unsigned int, irq_handler_t, unsigned long, const char *, void *) = request_irq;
	struct circ_buf ring = { .buf = NULL, .head = 5, .tail = 2 };

	tap_plan(7);
	ok(handler(0, NULL) == IRQ_HANDLED, "irqreturn_t and IRQ_HANDLED through mach/da8xx.h alone");
	ok(request != NULL, "request_irq declared");
	ok(THIS_MODULE != NULL && board_counter == 0, "THIS_MODULE and EXPORT_SYMBOL through mach/da8xx.h");
	is_int(CIRC_CNT(ring.head, ring.tail, 8), 3, "CIRC_CNT: three bytes between tail 2 and head 5");
	is_int(CIRC_SPACE(ring.head, ring.tail, 8), 4, "CIRC_SPACE: four free, one slot kept empty");
	is_int(CIRC_CNT_TO_END(1, 6, 8), 2, "CIRC_CNT_TO_END: a wrapped buffer reads to the array's end first");
	is_int(CIRC_SPACE_TO_END(6, 1, 8), 2, "CIRC_SPACE_TO_END: free slots up to the end (tail at 1)");
	return tap_done();
}
