/*
 * test_fiq.c — asm/fiq.h: the FIQ as the highest-priority interrupt.  A line
 * routed to the FIQ (enable_fiq) runs the FIQ handler, in interrupt context,
 * instead of its IRQ handlers; local_fiq_disable holds a FIQ pending until
 * local_fiq_enable; disable_fiq gives the line back to its IRQ handlers;
 * claim_fiq asks the owner to relinquish (-EBUSY if it refuses) and
 * release_fiq gives the FIQ back; set_fiq_regs/get_fiq_regs keep the
 * registers.  LEGO's I2C engine (its davinci-iic.c) runs as such a FIQ on
 * TIMER64P1's TINT34.
 */
#include "lx_test.h"
#include <asm/fiq.h>
#include <linux/interrupt.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>

static char log_buf[64];
static bool fiq_in_interrupt;

static void log_add(const char *s)
{
	strncat(log_buf, s, sizeof(log_buf) - strlen(log_buf) - 1);
}

static void fiq_handler(void)
{
	log_add("F");
	fiq_in_interrupt = lx_in_interrupt();
}

static irqreturn_t irq_handler(int irq, void *dev)
{
	log_add("i");
	return IRQ_HANDLED;
}

static int owner_answer;
static char owner_log[16];

static int owner_op(void *dev_id, int relinquish)
{
	strncat(owner_log, relinquish ? "R" : "B", sizeof(owner_log) - strlen(owner_log) - 1);
	return owner_answer;
}

static void raise_and_log(unsigned int line, const char *expect, const char *what)
{
	log_buf[0] = '\0';
	rtos_host_irq_raise(line);
	is_str(log_buf, expect, "%s", what);
}

static void body(void)
{
	static int dev;
	struct fiq_handler first = { .name = "first", .fiq_op = owner_op };
	struct fiq_handler second = { .name = "second" };
	struct pt_regs regs = { { 0 } }, back = { { 0 } };

	is_int(request_irq(IRQ_DA8XX_TINT34_1, irq_handler, 0, "tint34", &dev), 0, "an IRQ handler on TINT34_1");
	raise_and_log(IRQ_DA8XX_TINT34_1, "i", "as an IRQ its handler runs");
	set_fiq_handler((void *)fiq_handler, 4);
	enable_fiq(IRQ_DA8XX_TINT34_1);
	raise_and_log(IRQ_DA8XX_TINT34_1, "F", "routed to the FIQ: the FIQ handler runs instead");
	ok(fiq_in_interrupt, "in interrupt context");
	local_fiq_disable();
	raise_and_log(IRQ_DA8XX_TINT34_1, "", "masked (local_fiq_disable): nothing runs");
	log_buf[0] = '\0';
	local_fiq_enable();
	is_str(log_buf, "F", "local_fiq_enable takes the pending FIQ at once");
	set_fiq_handler(NULL, 0);
	set_fiq_c_handler(fiq_handler);
	raise_and_log(IRQ_DA8XX_TINT34_1, "F", "set_fiq_c_handler (LEGO's kernel) sets the same handler");
	disable_fiq(IRQ_DA8XX_TINT34_1);
	ok(!rtos_host_irq_enabled(IRQ_DA8XX_TINT34_1), "disable_fiq masks the line");
	free_irq(IRQ_DA8XX_TINT34_1, &dev);

	is_int(claim_fiq(&first), 0, "claim_fiq with no owner");
	owner_answer = 1;
	is_int(claim_fiq(&second), 1, "the owner refuses to relinquish: its answer comes back");
	owner_answer = 0;
	is_int(claim_fiq(&second), 0, "the owner relinquishes: second owns the FIQ");
	release_fiq(&second);
	is_str(owner_log, "RRB", "asked twice to relinquish, then given the FIQ back");
	release_fiq(&first);
	regs.ARM_r8 = 0x1234;
	regs.ARM_sp = 0xffff001c;
	set_fiq_regs(&regs);
	get_fiq_regs(&back);
	ok(back.ARM_r8 == 0x1234 && back.ARM_sp == 0xffff001c, "set_fiq_regs/get_fiq_regs keep r8..r14");
}

int main(void)
{
	tap_plan(14);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
