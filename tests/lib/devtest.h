/*
 * devtest.h — register helpers shared by the device-model tests: boot the
 * simulated EV3 with every device model, and reach registers the way a
 * driver does (sil_*_mem on the windows rtos_host_map_io returns).
 */
#ifndef TESTS_HOST_SIM_DEVICES_DEVTEST_H
#define TESTS_HOST_SIM_DEVICES_DEVTEST_H

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/syscfg.h"
#include "host_sim/psc.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"

#define MS 1000000ULL

static inline uint32_t rd32(uint32_t phys)
{
	return sil_rew_mem(rtos_host_map_io(phys, 4));
}

static inline void wr32(uint32_t phys, uint32_t v)
{
	sil_wrw_mem(rtos_host_map_io(phys, 4), v);
}

static inline uint16_t rd16(uint32_t phys)
{
	return sil_reh_mem(rtos_host_map_io(phys, 2));
}

static inline void wr16(uint32_t phys, uint16_t v)
{
	sil_wrh_mem(rtos_host_map_io(phys, 2), v);
}

/* GPIO register block of a pin (DaVinci layout: pairs of banks). */
static inline uint32_t gpio_pair(unsigned pin)
{
	return HS_GPIO_BASE + HS_GPIO_PAIR_OFFSET(pin);
}

static inline uint32_t gpio_bit(unsigned pin)
{
	return HS_GPIO_PAIR_BIT(pin);
}

/* Drives a GPIO as an output at level (SET/CLR_DATA first, then DIR). */
static inline void gpio_out(unsigned pin, int level)
{
	wr32(gpio_pair(pin) + (level ? HS_GPIO_SET_DATA : HS_GPIO_CLR_DATA), gpio_bit(pin));
	wr32(gpio_pair(pin) + HS_GPIO_DIR, rd32(gpio_pair(pin) + HS_GPIO_DIR) & ~gpio_bit(pin));
}

/* Floats a GPIO (DIR = input). */
static inline void gpio_float(unsigned pin)
{
	wr32(gpio_pair(pin) + HS_GPIO_DIR, rd32(gpio_pair(pin) + HS_GPIO_DIR) | gpio_bit(pin));
}

/* IN_DATA level of a pin. */
static inline int gpio_in(unsigned pin)
{
	return (rd32(gpio_pair(pin) + HS_GPIO_IN_DATA) & gpio_bit(pin)) != 0;
}

/* An empty application: the models are driven from the test itself. */
static const struct rtos_cfg devtest_cfg = { .name = "devtest" };

/* Boots the board with all EV3 device models. */
static inline void devtest_boot(uint64_t seed, const char *vcd)
{
	static struct hs_board_cfg board;
	struct hs_scenario scn = { .rtos = &devtest_cfg, .board = &board, .seed = seed, .vcd_path = vcd };

	board.devices = ev3_board_devices;
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("hs_sim_boot failed");
}

/* Powers and starts the PWM modules as d_pwm does (PSC1, TBCLKSYNC), sets
 * up eHRPWM1 and both eCAPs with a 10 000-count period. */
static inline void devtest_pwm_setup(void)
{
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_EHRPWM), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_ECAP), HS_PSC_ENABLE);
	wr32(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK0, HS_KICK0_UNLOCK);
	wr32(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK1, HS_KICK1_UNLOCK);
	wr32(HS_SYSCFG0_BASE + HS_SYSCFG0_CFGCHIP(1), rd32(HS_SYSCFG0_BASE + HS_SYSCFG0_CFGCHIP(1)) | HS_CFGCHIP1_TBCLKSYNC);
	wr32(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK0, 0);
	wr32(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK1, 0);
	wr16(HS_EHRPWM1_BASE + 0x00, 0x0030);   /* TBCTL: up-count, /1 /1 */
	wr16(HS_EHRPWM1_BASE + 0x0A, 9999);     /* TBPRD */
	wr16(HS_EHRPWM1_BASE + 0x0E, 0x0000);   /* CMPCTL: shadowed, load at zero */
	wr16(HS_EHRPWM1_BASE + 0x16, 0x0021);   /* AQCTLA: low at zero, high at CMPA */
	wr16(HS_EHRPWM1_BASE + 0x18, 0x0201);   /* AQCTLB: low at zero, high at CMPB */
	wr16(HS_EHRPWM1_BASE + 0x12, 0);
	wr16(HS_EHRPWM1_BASE + 0x14, 0);
	for (uint32_t base = HS_ECAP0_BASE; base <= HS_ECAP1_BASE; base += 0x1000U) {
		wr16(base + 0x2A, 0x0690);      /* ECCTL2: APWM, active low, free-running */
		wr32(base + 0x00, 0);
		wr32(base + 0x04, 0);
		wr32(base + 0x08, 9999);        /* CAP1: period */
		wr32(base + 0x0C, 0);           /* CAP2: compare */
	}
}

/* Sets the duty (0..10000) of output port 0..3 as d_pwm does. */
static inline void devtest_duty(unsigned port, uint16_t duty)
{
	switch (port) {
	case 0: wr16(HS_EHRPWM1_BASE + 0x14, duty); break;     /* EPWM1B */
	case 1: wr16(HS_EHRPWM1_BASE + 0x12, duty); break;     /* EPWM1A */
	case 2: wr32(HS_ECAP0_BASE + 0x0C, duty); break;
	default: wr32(HS_ECAP1_BASE + 0x0C, duty); break;
	}
}

/* H-bridge: 1 forward, -1 reverse, 2 brake, 0 coast (LEGO's d_pwm.c). */
static inline void devtest_bridge(unsigned port, int mode)
{
	const struct ev3_output_pins *p = &ev3_output_pins[port];

	switch (mode) {
	case 1: gpio_out(p->dir0, 1); gpio_float(p->dir1); break;
	case -1: gpio_float(p->dir0); gpio_out(p->dir1, 1); break;
	case 2: gpio_out(p->dir0, 1); gpio_out(p->dir1, 1); break;
	default: gpio_out(p->dir0, 0); gpio_out(p->dir1, 0); break;
	}
}

#endif /* TESTS_HOST_SIM_DEVICES_DEVTEST_H */
