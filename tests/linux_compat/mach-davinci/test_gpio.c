/*
 * test_gpio.c — DaVinci GPIO through linux_compat, against a register model
 * with DaVinci's semantics (fake_mmio.h): the legacy gpio calls at the
 * register level, and the bank-interrupt dispatcher - several pins pending
 * in one bank interrupt are acknowledged with one write-1-to-clear of
 * exactly that bank's bits, before any handler runs, and only the pending
 * pins' handlers run, lowest first; rising-only and falling-only triggers
 * are honoured; masking and freeing reprogram triggers, BINTEN and the line.
 */
#include "lx_test.h"
#include "fake_mmio.h"
#include <linux/gpio.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux_compat/context.h>

#define PAIR_REG(pin, reg)	(HS_GPIO_PAIR_OFFSET(pin) + (reg))
#define PIN_BIT(pin)		HS_GPIO_PAIR_BIT(pin)

/* Pins: three in bank 5 (GP5_8, GP5_11, GP5_13), one in bank 4 sharing bank 5's registers. */
#define PIN_A	GPIO_TO_PIN(5, 8)
#define PIN_B	GPIO_TO_PIN(5, 11)
#define PIN_C	GPIO_TO_PIN(5, 13)
#define PIN_D	GPIO_TO_PIN(4, 6)

static char log_buf[256];
static bool acked_before_handler = true, context_ok = true;

static irqreturn_t pin_handler(int irq, void *dev)
{
	unsigned int pin = (unsigned int)irq_to_gpio((unsigned int)irq);
	char word[16];

	if (fake_gpio_peek(PAIR_REG(pin, FG_STAT)) & PIN_BIT(pin))
		acked_before_handler = false;
	if (lx_current_irq() != irq || !lx_in_interrupt() || dev != (void *)(uintptr_t)pin)
		context_ok = false;
	snprintf(word, sizeof(word), "%s%u", log_buf[0] ? " " : "", pin);
	strncat(log_buf, word, sizeof(log_buf) - strlen(log_buf) - 1);
	return IRQ_HANDLED;
}

static int request_pin_irq(unsigned int pin, unsigned long flags)
{
	return request_irq((unsigned int)gpio_to_irq(pin), pin_handler, flags, "pin", (void *)(uintptr_t)pin);
}

static void test_gpiolib(void)
{
	unsigned int set_writes_before;
	unsigned int i, set_idx = 0, dir_idx = 0;

	ok(lx_gpio_base == (void *)fake.mem[FAKE_GPIO], "the GPIO block was mapped at boot");
	is_int(GPIO(5, 11), 91, "GPIO(bank, bit) = 16 * bank + bit");
	is_int(GPIO(91), 91, "GPIO(x) = x");
	ok(gpio_is_valid(143) && !gpio_is_valid(144) && !gpio_is_valid(-1), "gpio_is_valid: 0..143");
	is_int(gpio_request(PIN_B, "tacho"), 0, "gpio_request");
	is_int(gpio_request(PIN_B, "again"), -EBUSY, "a second request: -EBUSY");
	is_str(gpio_label(PIN_B), "tacho", "the label is kept");
	is_int(gpio_request(144, "x"), -EINVAL, "an invalid pin: -EINVAL");
	gpio_free(PIN_B);
	rtos_host_expect_bugs(true);
	gpio_free(PIN_B);
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "gpio_free") != NULL, "freeing a free pin warns");

	fake.nlog = 0;
	set_writes_before = fake_writes_to(FAKE_GPIO, PAIR_REG(PIN_B, FG_SET), NULL);
	is_int(gpio_direction_output(PIN_B, 1), 0, "gpio_direction_output(1)");
	for (i = 0; i < fake.nlog; i++) {
		if (fake.log[i].write && fake.log[i].offset == PAIR_REG(PIN_B, FG_SET))
			set_idx = i + 1;
		if (fake.log[i].write && fake.log[i].offset == PAIR_REG(PIN_B, FG_DIR))
			dir_idx = i + 1;
	}
	ok(set_idx && dir_idx && set_idx < dir_idx, "the level is set (SET_DATA) before the pin drives (DIR)");
	is_int(fake_writes_to(FAKE_GPIO, PAIR_REG(PIN_B, FG_SET), NULL), set_writes_before + 1, "one SET_DATA write");
	ok(!(fake_gpio_peek(PAIR_REG(PIN_B, FG_DIR)) & PIN_BIT(PIN_B)), "DIR bit cleared: output");
	ok(fake_gpio_peek(PAIR_REG(PIN_B, FG_OUT)) & PIN_BIT(PIN_B), "OUT_DATA bit set");
	is_int(gpio_get_direction(PIN_B), 0, "gpio_get_direction: output");

	fake.nlog = 0;
	gpio_set_value(PIN_B, 0);
	ok(fake.nlog == 1 && fake.log[0].write && fake.log[0].width == 4 &&
	   fake.log[0].offset == PAIR_REG(PIN_B, FG_CLR) && fake.log[0].value == PIN_BIT(PIN_B),
	   "gpio_set_value(0) is exactly one 32-bit CLR_DATA write of the pin's bit");
	ok(!(fake_gpio_peek(PAIR_REG(PIN_B, FG_OUT)) & PIN_BIT(PIN_B)), "OUT_DATA bit cleared");
	fake.nlog = 0;
	gpio_set_value(PIN_B, 7);
	ok(fake.nlog == 1 && fake.log[0].offset == PAIR_REG(PIN_B, FG_SET), "gpio_set_value(non-zero) writes SET_DATA");

	is_int(gpio_direction_input(PIN_B), 0, "gpio_direction_input");
	ok(fake_gpio_peek(PAIR_REG(PIN_B, FG_DIR)) & PIN_BIT(PIN_B), "DIR bit set: input");
	fake.gpio_in[PIN_B / 32] = PIN_BIT(PIN_B);
	fake.nlog = 0;
	is_int(gpio_get_value(PIN_B), 1, "gpio_get_value reads IN_DATA (1)");
	ok(fake.nlog == 1 && !fake.log[0].write && fake.log[0].offset == PAIR_REG(PIN_B, FG_IN),
	   "with one IN_DATA read");
	fake.gpio_in[PIN_B / 32] = ~PIN_BIT(PIN_B);
	is_int(gpio_get_value(PIN_B), 0, "gpio_get_value reads IN_DATA (0)");

	is_int(gpio_to_irq(PIN_B), 101 + 91, "gpio_to_irq = 101 + gpio");
	is_int(irq_to_gpio(192), 91, "irq_to_gpio inverts it");
	is_int(gpio_to_irq(144), -EINVAL, "gpio_to_irq of an invalid pin: -EINVAL");

	rtos_host_expect_bugs(true);
	gpio_set_value(200, 1);
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "200") != NULL, "gpio_set_value on an invalid pin is reported");
}

static void test_bank_dispatch(void)
{
	unsigned int irq_a = (unsigned int)gpio_to_irq(PIN_A);
	uint32_t last = 0;
	unsigned int stat_writes;
	uint32_t bank5_bits = PIN_BIT(PIN_A) | PIN_BIT(PIN_B) | PIN_BIT(PIN_C);

	ok(!rtos_host_irq_enabled(IRQ_DA8XX_GPIO5), "bank 5's line starts disabled");
	is_int(request_pin_irq(PIN_B, 0), 0, "request_irq on GP5_11 (no trigger flags)");
	ok((fake.rising[2] & PIN_BIT(PIN_B)) && (fake.falling[2] & PIN_BIT(PIN_B)),
	   "no type given: both edges (DaVinci's default)");
	ok(fake_gpio_peek(0x08) & (1U << 5), "BINTEN bit 5 set");
	ok(rtos_host_irq_enabled(IRQ_DA8XX_GPIO5), "bank 5's RTOS line enabled");

	is_int(request_pin_irq(PIN_A, 0), 0, "request_irq on GP5_8");
	is_int(set_irq_type(irq_a, IRQ_TYPE_EDGE_RISING), 0, "then set_irq_type(rising), as d_pwm does");
	ok((fake.rising[2] & PIN_BIT(PIN_A)) && !(fake.falling[2] & PIN_BIT(PIN_A)), "rising only");
	is_int(request_pin_irq(PIN_C, IRQF_TRIGGER_FALLING), 0, "request_irq on GP5_13 with IRQF_TRIGGER_FALLING");
	ok(!(fake.rising[2] & PIN_BIT(PIN_C)) && (fake.falling[2] & PIN_BIT(PIN_C)), "falling only");
	is_int(request_pin_irq(PIN_D, IRQF_TRIGGER_RISING | IRQF_TRIGGER_FALLING), 0, "request_irq on GP4_6 (both)");
	ok(fake_gpio_peek(0x08) & (1U << 4), "BINTEN bit 4 set");
	is_int(irq_set_irq_type(irq_a, IRQ_TYPE_LEVEL_HIGH), -EINVAL, "pin IRQs refuse level triggers");

	/* Several edges while interrupts are locked: one bank interrupt each for banks 4 and 5. */
	fake.nlog = 0;
	log_buf[0] = '\0';
	loc_cpu();
	fake_gpio_edge(PIN_C, true);     /* rising on a falling-only pin: ignored */
	fake_gpio_edge(PIN_A, false);    /* falling on a rising-only pin: ignored */
	fake_gpio_edge(PIN_C, false);    /* these three are latched */
	fake_gpio_edge(PIN_B, true);
	fake_gpio_edge(PIN_A, true);
	fake_gpio_edge(PIN_D, true);
	ok(fake_gpio_peek(PAIR_REG(PIN_A, FG_STAT)) == (bank5_bits | PIN_BIT(PIN_D)),
	   "INTSTAT holds the four enabled edges only");
	is_str(log_buf, "", "nothing dispatched while locked");
	unl_cpu();
	is_str(log_buf, "70 88 91 93",
	       "one interrupt per bank: bank 4's pin, then bank 5's pending pins lowest first");
	ok(acked_before_handler, "every pin's INTSTAT bit was cleared before its handler ran");
	ok(context_ok, "each handler ran in interrupt context with its own irq and dev_id");
	stat_writes = fake_writes_to(FAKE_GPIO, PAIR_REG(PIN_A, FG_STAT), &last);
	is_int(stat_writes, 2, "INTSTAT written twice: once per bank interrupt");
	is_u64(last, bank5_bits, "bank 5 acknowledged exactly its three pending bits with one W1C write");
	is_u64(fake_gpio_peek(PAIR_REG(PIN_A, FG_STAT)), 0, "nothing left pending");

	/* A single edge: one handler. */
	log_buf[0] = '\0';
	fake_gpio_edge(PIN_B, false);
	is_str(log_buf, "91", "a falling edge on a both-edges pin: its handler alone");

	/* Masking a pin clears its triggers; its edges are not latched. */
	disable_irq((unsigned int)gpio_to_irq(PIN_B));
	ok(!(fake.rising[2] & PIN_BIT(PIN_B)) && !(fake.falling[2] & PIN_BIT(PIN_B)),
	   "disable_irq clears the pin's triggers");
	log_buf[0] = '\0';
	fake_gpio_edge(PIN_B, true);
	is_str(log_buf, "", "no call while disabled");
	enable_irq((unsigned int)gpio_to_irq(PIN_B));
	ok((fake.rising[2] & PIN_BIT(PIN_B)) && (fake.falling[2] & PIN_BIT(PIN_B)),
	   "enable_irq restores both edges");

	(void)free_irq((unsigned int)gpio_to_irq(PIN_A), (void *)(uintptr_t)PIN_A);
	(void)free_irq((unsigned int)gpio_to_irq(PIN_B), (void *)(uintptr_t)PIN_B);
	ok(rtos_host_irq_enabled(IRQ_DA8XX_GPIO5), "bank 5 stays enabled while a pin IRQ remains");
	(void)free_irq((unsigned int)gpio_to_irq(PIN_C), (void *)(uintptr_t)PIN_C);
	ok(!(fake_gpio_peek(0x08) & (1U << 5)), "the last pin freed: BINTEN bit 5 cleared");
	ok(!rtos_host_irq_enabled(IRQ_DA8XX_GPIO5), "and bank 5's line disabled");
	ok(fake_gpio_peek(0x08) & (1U << 4), "bank 4 untouched");
	(void)free_irq((unsigned int)gpio_to_irq(PIN_D), (void *)(uintptr_t)PIN_D);
}

/*
 * An edge latched on a pin just before disable_irq (interrupts locked, the
 * bank interrupt not yet taken) reaches the handler once after enable_irq,
 * as in Linux: the bank handler finds the pin disabled and marks it pending
 * (IRQS_PENDING), and enable_irq replays a pending edge-triggered IRQ
 * (kernel/irq/resend.c, check_irq_resend; DaVinci's GPIO chip cannot
 * retrigger, so Linux resends in software, from a tasklet).  The same
 * whether another pin of the bank keeps the bank line enabled (the edge is
 * taken and acknowledged while the pin is disabled) or not (it waits in
 * INTSTAT).
 */
static void test_edge_before_disable(void)
{
	unsigned int irq_a = (unsigned int)gpio_to_irq(PIN_A), irq_b = (unsigned int)gpio_to_irq(PIN_B);

	is_int(request_pin_irq(PIN_A, IRQF_TRIGGER_RISING), 0, "GP5_8 keeps bank 5's line enabled");
	is_int(request_pin_irq(PIN_B, 0), 0, "GP5_11 (both edges)");
	log_buf[0] = '\0';
	loc_cpu();
	fake_gpio_edge(PIN_B, true);
	disable_irq_nosync(irq_b);
	unl_cpu();
	is_str(log_buf, "", "an edge latched before disable_irq: no call while disabled");
	is_u64(fake_gpio_peek(PAIR_REG(PIN_B, FG_STAT)) & PIN_BIT(PIN_B), 0,
	       "the bank interrupt acknowledged it (its bank mate is enabled)");
	enable_irq(irq_b);
	dly_tsk(2);
	is_str(log_buf, "91", "enable_irq replays it: the handler runs once");
	log_buf[0] = '\0';
	disable_irq(irq_b);
	enable_irq(irq_b);
	dly_tsk(2);
	is_str(log_buf, "", "replayed once only: another disable/enable calls nothing");

	(void)free_irq(irq_a, (void *)(uintptr_t)PIN_A);
	loc_cpu();
	fake_gpio_edge(PIN_B, false);
	disable_irq_nosync(irq_b);
	unl_cpu();
	is_str(log_buf, "", "alone in its bank: no call while disabled either");
	enable_irq(irq_b);
	dly_tsk(2);
	is_str(log_buf, "91", "and enable_irq delivers it once");
	log_buf[0] = '\0';
	disable_irq(irq_b);
	fake_gpio_edge(PIN_B, true);
	enable_irq(irq_b);
	dly_tsk(2);
	is_str(log_buf, "", "an edge while disabled is not latched (triggers off): nothing to replay");
	(void)free_irq(irq_b, (void *)(uintptr_t)PIN_B);
}

static void body(void)
{
	test_gpiolib();
	test_bank_dispatch();
	test_edge_before_disable();
}

int main(void)
{
	tap_plan(66);
	fake_mmio_install();
	ok(lx_test_run(body), "test task ran to completion");
	rtos_host_set_mmio_handler(NULL);
	return tap_done();
}
