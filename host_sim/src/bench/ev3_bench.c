/*
 * ev3_bench.c — the full-brick speed run (ev3_bench.h).  The host side is
 * plain register accesses, as a polling driver makes them, between 1 ms
 * slices of virtual time.
 */
#define _POSIX_C_SOURCE 200112L
#include <string.h>
#include <time.h>
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/psc.h"
#include "host_sim/syscfg.h"
#include "host_sim/scenario.h"
#include "host_sim/bench.h"
#include "host_sim/devices/ev3_brick.h"

static const struct rtos_cfg bench_cfg = { .name = "ev3_bench" };

#define WINDOWS 8U
static struct {
	uintptr_t page;
	uint8_t *window;
} windows[WINDOWS];             /* pages looked up in this boot */
static unsigned last_window;    /* the one used last: a poll loop stays on one page */

/* The CPU-visible address of a register (windows are per 4 KiB page). */
static void *reg_addr(uintptr_t phys)
{
	uintptr_t page = phys & ~(uintptr_t)0xFFF;
	unsigned i;

	if (windows[last_window].window && windows[last_window].page == page)
		return windows[last_window].window + (phys & 0xFFF);
	for (i = 0; i < WINDOWS && windows[i].window; i++)
		if (windows[i].page == page)
			break;
	if (i == WINDOWS)
		i = 0;
	if (!windows[i].window || windows[i].page != page) {
		windows[i].page = page;
		windows[i].window = rtos_host_map_io(page, 0x1000);
	}
	last_window = i;
	return windows[i].window + (phys & 0xFFF);
}

/* 32-bit register read through the window. */
static uint32_t reg_rd(uintptr_t phys)
{
	return sil_rew_mem(reg_addr(phys));
}

/* 32-bit register write through the window. */
static void reg_wr(uintptr_t phys, uint32_t v)
{
	sil_wrw_mem(reg_addr(phys), v);
}

/* 16-bit register write through the window. */
static void reg_wr16(uintptr_t phys, uint16_t v)
{
	sil_wrh_mem(reg_addr(phys), v);
}

/* Drives a GPIO as an output at level, as a driver does. */
static void gpio_drive(unsigned pin, int level)
{
	uintptr_t pair = HS_GPIO_BASE + HS_GPIO_PAIR_OFFSET(pin);
	uint32_t bit = HS_GPIO_PAIR_BIT(pin);

	reg_wr(pair + (level ? HS_GPIO_SET_DATA : HS_GPIO_CLR_DATA), bit);
	reg_wr(pair + HS_GPIO_DIR, reg_rd(pair + HS_GPIO_DIR) & ~bit);
}

/* Floats a GPIO (DIR = input). */
static void gpio_release(unsigned pin)
{
	uintptr_t pair = HS_GPIO_BASE + HS_GPIO_PAIR_OFFSET(pin);

	reg_wr(pair + HS_GPIO_DIR, reg_rd(pair + HS_GPIO_DIR) | HS_GPIO_PAIR_BIT(pin));
}

/* Sets a UART divisor for baud and flushes its FIFOs. */
static void uart_baud(uintptr_t base, uint32_t clock, uint32_t baud)
{
	uint32_t div = (clock + 8U * baud) / (16U * baud);

	reg_wr(base + 0x20, div & 0xFFU);
	reg_wr(base + 0x24, div >> 8);
	reg_wr(base + 0x08, 0x07);
	reg_wr(base + 0x08, 0x01);
}

struct bench_host {
	uintptr_t base;
	uint32_t clock;
	bool streaming;
	uint64_t next_nack;
	uint64_t bytes;
};

/* One millisecond of host work on a port: drain RX, ACK a finished
 * handshake, keep the stream alive. */
static void host_service(struct bench_host *h, unsigned port)
{
	struct uart_sensor *s = ev3_input_uart_sensor(port);

	while (reg_rd(h->base + 0x14) & 1U) {
		(void)reg_rd(h->base + 0x00);
		h->bytes++;
	}
	if (!s)
		return;
	if (!h->streaming && uart_sensor_get_state(s) == UART_SENSOR_WAIT_ACK) {
		reg_wr(h->base + 0x00, 0x04);
		while (!(reg_rd(h->base + 0x14) & 0x40U))
			hs_sim_run_for(500000);
		uart_baud(h->base, h->clock, 57600);
		h->streaming = true;
		h->next_nack = hs_now();
	}
	if (h->streaming && hs_now() >= h->next_nack) {
		reg_wr(h->base + 0x00, 0x02);
		h->next_nack += 100000000ULL;
	}
	if (h->streaming && uart_sensor_get_state(s) != UART_SENSOR_DATA) {
		h->streaming = false;
		uart_baud(h->base, h->clock, 2400);
	}
}

/* Seconds on a host clock. */
static double clock_s(clockid_t id)
{
	struct timespec ts;

	clock_gettime(id, &ts);
	return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

ER ev3_bench_full_brick(double virtual_s, uint64_t seed, struct ev3_bench_result *r)
{
	static const uint8_t types[4] = { 29, 32, 30, 33 };
	static const uint16_t duty[4] = { 10000, 7000, 5000, 10000 };
	struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &bench_cfg, .board = &board, .seed = seed };
	struct bench_host hosts[4];
	uint64_t end;
	double t0, c0;
	ER er;

	if (!r || !(virtual_s > 0) || virtual_s > 1e6)
		return E_PAR;
	memset(r, 0, sizeof(*r));
	t0 = clock_s(CLOCK_MONOTONIC);
	c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
	er = hs_sim_boot(&scn);
	if (er != E_OK)
		return er;
	memset(windows, 0, sizeof(windows));    /* windows of this boot, not a previous one */
	/* PWM as d_pwm leaves it: powered, time bases running, 10 000-count periods */
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_EHRPWM), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_ECAP), HS_PSC_ENABLE);
	reg_wr(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK0, HS_KICK0_UNLOCK);
	reg_wr(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK1, HS_KICK1_UNLOCK);
	reg_wr(HS_SYSCFG0_BASE + HS_SYSCFG0_CFGCHIP(1),
	       reg_rd(HS_SYSCFG0_BASE + HS_SYSCFG0_CFGCHIP(1)) | HS_CFGCHIP1_TBCLKSYNC);
	reg_wr(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK0, 0);
	reg_wr(HS_SYSCFG0_BASE + HS_SYSCFG0_KICK1, 0);
	reg_wr16(HS_EHRPWM1_BASE + 0x00, 0x0030);
	reg_wr16(HS_EHRPWM1_BASE + 0x0A, 9999);
	reg_wr16(HS_EHRPWM1_BASE + 0x16, 0x0021);
	reg_wr16(HS_EHRPWM1_BASE + 0x18, 0x0201);
	reg_wr16(HS_EHRPWM1_BASE + 0x14, duty[0]);
	reg_wr16(HS_EHRPWM1_BASE + 0x12, duty[1]);
	reg_wr16(HS_ECAP0_BASE + 0x2A, 0x0690);
	reg_wr(HS_ECAP0_BASE + 0x08, 9999);
	reg_wr(HS_ECAP0_BASE + 0x0C, duty[2]);
	reg_wr16(HS_ECAP1_BASE + 0x2A, 0x0690);
	reg_wr(HS_ECAP1_BASE + 0x08, 9999);
	reg_wr(HS_ECAP1_BASE + 0x0C, duty[3]);
	for (unsigned p = 0; p < 4; p++) {
		const struct ev3_output_pins *op = &ev3_output_pins[p];

		ev3_attach_motor(p, p < 2 ? HS_MOTOR_LARGE : HS_MOTOR_MEDIUM, NULL);
		if (p & 1U) {           /* B and D in reverse */
			gpio_release(op->dir0);
			gpio_drive(op->dir1, 1);
		} else {
			gpio_drive(op->dir0, 1);
			gpio_release(op->dir1);
		}
		hosts[p] = (struct bench_host){ ev3_port_uart[p].base, ev3_port_uart[p].clock_hz, false, 0, 0 };
		reg_wr(hosts[p].base + 0x30, 0x6001);
		reg_wr(hosts[p].base + 0x0C, 0x03);
		uart_baud(hosts[p].base, hosts[p].clock, 2400);
		gpio_drive(ev3_input_pins[p].tx_buffer_off, 0);
		ev3_attach_uart_sensor(p, types[p], NULL);
	}
	{
		struct uart_sensor_scene sc = *uart_sensor_scene(ev3_input_uart_sensor(1));

		sc.rate_dps = 45.0;     /* the gyro turns, so its frames change */
		ev3_set_scene(1, &sc);
	}
	end = hs_now() + (uint64_t)(virtual_s * 1e9);
	while (hs_now() < end) {
		hs_sim_run_for(1000000);
		for (unsigned p = 0; p < 4; p++)
			host_service(&hosts[p], p);
	}
	r->virtual_s = virtual_s;
	for (unsigned p = 0; p < 4; p++) {
		r->sensor_bytes += hosts[p].bytes;
		r->data_frames += uart_sensor_get_stats(ev3_input_uart_sensor(p))->data_frames;
		r->tacho_counts[p] = hs_motor_tacho_counts(ev3_output_motor(p));
	}
	hs_sim_shutdown();
	r->wall_s = clock_s(CLOCK_MONOTONIC) - t0;
	r->cpu_s = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
	r->speedup = r->wall_s > 0 ? r->virtual_s / r->wall_s : 0;
	r->cpu_speedup = r->cpu_s > 0 ? r->virtual_s / r->cpu_s : 0;
	return E_OK;
}
