/*
 * test_gpio_host_sim.c — linux_compat's GPIO layer against host_sim's GPIO
 * model (the register model the drivers run on): pins driven by the outside
 * world reach gpio_get_value and, through INTSTAT/BINTEN and the bank
 * interrupt, the pin IRQ handlers at the virtual time of the edge;
 * gpio_direction_output drives the pin; edges of several pins in one bank
 * interrupt are each delivered once, lowest pin first.
 */
#include "lx_test.h"
#include <linux/gpio.h>
#include <linux/interrupt.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"

#define TACHO	GPIO_TO_PIN(5, 11)
#define OTHER	GPIO_TO_PIN(5, 8)
#define MOTOR	GPIO_TO_PIN(3, 15)

static unsigned int calls[NR_IRQS];
static char order[64];
static uint64_t tacho_time;

static irqreturn_t edge_handler(int irq, void *dev)
{
	char w[8];

	calls[irq]++;
	if ((unsigned int)irq_to_gpio((unsigned int)irq) == TACHO)
		tacho_time = rtos_host_now();
	snprintf(w, sizeof(w), "%s%d", order[0] ? " " : "", irq_to_gpio((unsigned int)irq));
	strncat(order, w, sizeof(order) - strlen(order) - 1);
	return IRQ_HANDLED;
}

static void body(void)
{
	unsigned int tacho_irq = (unsigned int)gpio_to_irq(TACHO);
	unsigned int other_irq = (unsigned int)gpio_to_irq(OTHER);
	bool level = false;
	uint64_t t0;

	is_int(gpio_request(TACHO, "tacho"), 0, "gpio_request");
	is_int(gpio_direction_input(TACHO), 0, "input");
	hs_gpio_set_input(TACHO, 1);
	is_int(gpio_get_value(TACHO), 1, "gpio_get_value sees the pin driven high");
	hs_gpio_set_input(TACHO, 0);
	is_int(gpio_get_value(TACHO), 0, "and low");

	is_int(gpio_direction_output(MOTOR, 1), 0, "gpio_direction_output(1)");
	ok(hs_gpio_soc_output(MOTOR, &level) && level, "the SoC now drives the pin high");
	gpio_set_value(MOTOR, 0);
	ok(hs_gpio_soc_output(MOTOR, &level) && !level, "gpio_set_value(0) drives it low");

	is_int(request_irq(tacho_irq, edge_handler, 0, "tacho", NULL), 0, "request_irq (both edges)");
	is_int(request_irq(other_irq, edge_handler, IRQF_TRIGGER_RISING, "other", NULL), 0,
	       "request_irq (rising)");
	t0 = rtos_host_now();
	hs_gpio_set_input(TACHO, 1);
	is_int(calls[tacho_irq], 1, "a rising edge reaches the handler");
	in_range(tacho_time - t0, 0, 1000, "within a microsecond of the edge (register access costs only)");
	hs_gpio_set_input(TACHO, 0);
	is_int(calls[tacho_irq], 2, "a falling edge too");
	hs_gpio_set_input(OTHER, 1);
	hs_gpio_set_input(OTHER, 0);
	is_int(calls[other_irq], 1, "rising-only: the falling edge is ignored");

	order[0] = '\0';
	loc_cpu();
	hs_gpio_set_input(TACHO, 1);
	hs_gpio_set_input(OTHER, 1);
	unl_cpu();
	is_str(order, "88 91", "two pins pending in one bank interrupt: each handler once, lowest first");

	disable_irq(tacho_irq);
	hs_gpio_set_input(TACHO, 0);
	is_int(calls[tacho_irq], 3, "no call while disabled");
	enable_irq(tacho_irq);
	hs_gpio_set_input(TACHO, 1);
	is_int(calls[tacho_irq], 4, "calls again after enable_irq");
	(void)free_irq(tacho_irq, NULL);
	(void)free_irq(other_irq, NULL);
	ok(!rtos_host_irq_enabled(IRQ_DA8XX_GPIO5), "bank line disabled after the last free_irq");
	gpio_free(TACHO);
}

int main(void)
{
	tap_plan(19);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
