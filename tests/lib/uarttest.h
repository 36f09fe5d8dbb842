/*
 * uarttest.h — a test-side host for the UART sensor tests: programs the
 * port's UART through its registers, collects received bytes with their
 * arrival time and line status, and sends host messages.  It frames and
 * checks messages itself (independently of host_sim's lump.c), from the
 * protocol (LEGO's d_uart_mod.c): header bits 7-6 class, 5-3 size code, 2-0 command/mode,
 * check = 0xFF XOR all preceding bytes.
 */
#ifndef TESTS_HOST_SIM_DEVICES_UARTTEST_H
#define TESTS_HOST_SIM_DEVICES_UARTTEST_H

#include "devtest.h"

#define RX_MAX 4096

struct rx_byte {
	uint64_t t;
	uint8_t b;
	uint8_t lsr;
};

struct host {
	unsigned port;
	uint32_t base;
	struct rx_byte rx[RX_MAX];
	unsigned n;
};

static inline void host_baud(struct host *h, uint32_t baud)
{
	uint32_t div = (uint32_t)((ev3_port_uart[h->port].clock_hz + 8U * baud) / (16U * baud));

	wr32(h->base + 0x20, div & 0xFF);
	wr32(h->base + 0x24, div >> 8);
	wr32(h->base + 0x08, 0x07);         /* FCR: FIFO on, both cleared */
	wr32(h->base + 0x08, 0x01);
}

/* UART as d_uart sets it: 8N1, FIFO, 16x, out of reset, TX buffer on. */
static inline void host_init(struct host *h, unsigned port)
{
	h->port = port;
	h->base = (uint32_t)ev3_port_uart[port].base;
	h->n = 0;
	wr32(h->base + 0x30, 0x6001);       /* PWREMU_MGMT: RX, TX out of reset, free */
	wr32(h->base + 0x34, 0);            /* MDR: 16x */
	wr32(h->base + 0x0C, 0x03);         /* LCR: 8N1 */
	wr32(h->base + 0x04, 0);            /* IER: polled */
	host_baud(h, 2400);
	gpio_out(ev3_input_pins[port].tx_buffer_off, 0);
}

/* Drains the RX FIFO into the log. */
static inline void host_poll(struct host *h)
{
	for (;;) {
		uint32_t lsr = rd32(h->base + 0x14);

		if (!(lsr & 1U))
			return;
		if (h->n < RX_MAX) {
			h->rx[h->n].t = hs_now();
			h->rx[h->n].lsr = (uint8_t)lsr;
			h->rx[h->n].b = (uint8_t)rd32(h->base + 0x00);
			h->n++;
		} else {
			(void)rd32(h->base + 0x00);
		}
	}
}

/* Runs ns of virtual time, polling every 500 us. */
static inline void host_run(struct host *h, uint64_t ns)
{
	uint64_t end = hs_now() + ns;

	while (hs_now() < end) {
		uint64_t step = end - hs_now() < 500000U ? end - hs_now() : 500000U;

		hs_sim_run_for(step);
		host_poll(h);
	}
}

/* Sends bytes and waits until they are on the wire (TEMT). */
static inline void host_send(struct host *h, const uint8_t *b, unsigned n)
{
	for (unsigned i = 0; i < n; i++) {
		while (!(rd32(h->base + 0x14) & 0x20U))
			hs_sim_run_for(100000);
		wr32(h->base + 0x00, b[i]);
	}
	while (!(rd32(h->base + 0x14) & 0x40U)) {
		hs_sim_run_for(50000);
		host_poll(h);
	}
}

static inline uint8_t chk(const uint8_t *b, unsigned n)
{
	uint8_t c = 0xFF;

	for (unsigned i = 0; i < n; i++)
		c ^= b[i];
	return c;
}

/* Payload length from a header by the protocol's rule. */
static inline unsigned hdr_len(uint8_t h)
{
	return 1U << ((h >> 3) & 7U);
}

static inline void host_cmd(struct host *h, unsigned cmd, const uint8_t *payload, unsigned len)
{
	uint8_t f[36];
	unsigned lll = 0, n = 0;

	while ((1U << lll) < len)
		lll++;
	f[n++] = (uint8_t)(0x40U | (lll << 3) | cmd);
	for (unsigned i = 0; i < (1U << lll); i++)
		f[n++] = i < len ? payload[i] : 0;
	f[n] = chk(f, n);
	host_send(h, f, n + 1);
}

#endif /* TESTS_HOST_SIM_DEVICES_UARTTEST_H */
