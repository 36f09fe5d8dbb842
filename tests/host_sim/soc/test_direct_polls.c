/*
 * test_direct_polls.c — the registers the drivers poll take direct accesses
 * (regs.h) when unlogged and 32 bits wide: UART LSR, IIR and RBR, GPIO
 * IN_DATA and INTSTAT, TIMER64P3 TIM12 and TIM34.  The same sequence (bytes
 * looped back, an overrun, a framing error, THRE reported and cleared by
 * IIR, DLAB; pins driven with edge interrupts, INTSTAT cleared bit by bit;
 * the timer counting in 64-bit and dual mode, one-shot) gives the same
 * values at the same virtual times, the same interrupt lines (VCD) and the
 * same UART statistics with those regions unlogged (direct accesses) as
 * with their register log on (the hooks).
 */
#define _XOPEN_SOURCE 700
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "devtest.h"
#include "host_sim/intc.h"
#include "host_sim/regs.h"
#include "host_sim/trace.h"
#include "host_sim/devices/uart16550.h"
#include "devtest_compare.h"
#include "text_files_test.h"

#define U0        HS_UART0_BASE
#define RBR       (U0 + 0x00)
#define IER       (U0 + 0x04)
#define IIR       (U0 + HS_UART_IIR)
#define LCR       (U0 + 0x0C)
#define MCR       (U0 + 0x10)
#define LSR       (U0 + 0x14)
#define T3        HS_TIMER64P3_BASE
#define TIM12     (T3 + 0x10)
#define TIM34     (T3 + 0x14)
#define PRD12     (T3 + 0x18)
#define PRD34     (T3 + 0x1C)
#define TCR       (T3 + 0x20)
#define TGCR      (T3 + 0x24)
#define PIN_A     HS_GPIO(4, 2)     /* pins no EV3 model drives */
#define PIN_B     HS_GPIO(4, 9)
#define PIN_C     HS_GPIO(8, 12)
#define US        1000ULL
#define LINE_UART 1U        /* the interrupt lines an observation records */
#define LINE_GPIO 2U

struct run {
	struct devtest_notes notes;
	struct hs_uart_stats stats;
	char vcd[65536];
	unsigned log_lines;         /* of the register log, if on */
};

static struct run *cur;

/* Records an observation in the current run. */
static void note(const char *what, uint32_t value)
{
	devtest_note(&cur->notes, what, value, (hs_intc_pending(EV3_UART0_INTNO) ? LINE_UART : 0U) |
					       (hs_intc_pending(HS_GPIO_BANK_INTNO(4)) ? LINE_GPIO : 0U));
}

/* UART0 at 115200 baud from 150 MHz, FIFO on with trigger fcr, as d_uart sets it up. */
static void uart_setup(uint32_t fcr)
{
	wr32(U0 + 0x30, 0x6001);
	wr32(LCR, 0x03);
	wr32(U0 + 0x20, 81);
	wr32(U0 + 0x24, 0);
	wr32(IIR, fcr);             /* FCR */
}

/* Polls LSR until DR, noting each poll's value when it changes; then RBR. */
static void uart_take_byte(void)
{
	uint32_t last = 0xFFFFFFFFU, lsr;

	while (!((lsr = rd32(LSR)) & 0x01U)) {
		if (lsr != last)
			note("lsr wait", lsr);
		last = lsr;
		hs_sim_run_for(7 * US);
	}
	note("lsr ready", lsr);
	note("iir", rd32(IIR));
	note("rbr", rd32(RBR));
}

static void uart_sequence(struct hs_uart *u)
{
	uart_setup(0x07);
	wr32(IIR, 0x01);
	wr32(MCR, 0x10);            /* loopback */
	wr32(IER, 0x07);            /* ERBI, ETBEI, ELSI: THRE at once */
	note("iir thre", rd32(IIR));
	note("iir thre cleared", rd32(IIR));
	for (uint32_t b = 0x41; b < 0x45; b++) {
		wr32(RBR, b);           /* THR */
		note("lsr after thr", rd32(LSR));
		uart_take_byte();
	}
	/* 17 bytes into a 16-byte FIFO: overrun, OE cleared by an LSR read */
	for (uint32_t i = 0; i < 17; i++) {
		while (!(rd32(LSR) & 0x20U))
			hs_sim_run_for(5 * US);
		wr32(RBR, i);
	}
	hs_sim_run_for(3 * MS);
	note("iir line status", rd32(IIR));
	note("lsr overrun", rd32(LSR));
	note("lsr after overrun", rd32(LSR));
	note("iir after overrun", rd32(IIR));
	for (unsigned i = 0; i < 16; i++)
		note("rbr drain", rd32(RBR));
	note("rbr empty", rd32(RBR));
	note("lsr empty", rd32(LSR));
	/* a framing error from the line, reported once by LSR */
	wr32(MCR, 0);
	hs_uart_rx_byte(u, 0x40, 2400);
	hs_uart_rx_byte(u, 0x55, 115741);
	hs_sim_run_for(100 * US);
	note("iir error", rd32(IIR));
	note("lsr error", rd32(LSR));
	note("lsr error reported", rd32(LSR));
	note("rbr garbled", rd32(RBR));
	note("lsr next", rd32(LSR));
	note("rbr next", rd32(RBR));
	/* the character timeout with a trigger of 4 */
	wr32(IIR, 0x41);
	hs_uart_rx_byte(u, 0x12, 115741);
	hs_sim_run_for(1 * MS);
	note("iir timeout", rd32(IIR));
	note("rbr timeout", rd32(RBR));
	note("iir after timeout", rd32(IIR));
	/* DLAB: RBR reads DLL */
	wr32(LCR, 0x83);
	note("rbr dlab", rd32(RBR));
	wr32(LCR, 0x03);
	note("iir end", rd32(IIR));
}

static void gpio_sequence(void)
{
	uint32_t pair = gpio_pair(PIN_A), c_pair = gpio_pair(PIN_C);

	wr32(HS_GPIO_BASE + HS_GPIO_BINTEN, rd32(HS_GPIO_BASE + HS_GPIO_BINTEN) | (1U << 4));
	wr32(pair + HS_GPIO_SET_RIS_TRIG, gpio_bit(PIN_A) | gpio_bit(PIN_B));
	wr32(pair + HS_GPIO_SET_FAL_TRIG, gpio_bit(PIN_B));
	for (unsigned i = 0; i < 6; i++) {
		hs_gpio_drive(PIN_A, i & 1U ? HS_EXT_LOW : HS_EXT_HIGH);
		hs_gpio_drive(PIN_B, i & 2U ? HS_EXT_PULL_UP : HS_EXT_FLOAT);
		hs_gpio_drive(PIN_C, i & 1U ? HS_EXT_HIGH : HS_EXT_LOW);
		hs_sim_run_for(10 * US);
		note("in_data", rd32(pair + HS_GPIO_IN_DATA));
		note("in_data c", rd32(c_pair + HS_GPIO_IN_DATA));
		note("intstat", rd32(pair + HS_GPIO_INTSTAT));
		wr32(pair + HS_GPIO_INTSTAT, gpio_bit(PIN_A));
		note("intstat a cleared", rd32(pair + HS_GPIO_INTSTAT));
		wr32(pair + HS_GPIO_INTSTAT, 0xFFFFFFFFU);
		note("intstat cleared", rd32(pair + HS_GPIO_INTSTAT));
	}
	/* the SoC driving a pin: IN_DATA follows OUT_DATA */
	gpio_out(PIN_C, 1);
	note("in_data driven", rd32(c_pair + HS_GPIO_IN_DATA));
	gpio_float(PIN_C);
	note("in_data floated", rd32(c_pair + HS_GPIO_IN_DATA));
}

static void timer_sequence(void)
{
	note("tim34 at reset", rd32(TIM34));
	/* d_pwm's setup: dual unchained, TIM34 /4, continuous */
	wr32(TGCR, 0x3304);
	wr32(TGCR, rd32(TGCR) | 2U);
	wr32(PRD34, 0xFFFFFFFFU);
	wr32(TCR, 0x00800000U);
	for (unsigned i = 0; i < 4; i++) {
		hs_sim_run_for(333 * US);
		note("tim34", rd32(TIM34));
		note("tim12", rd32(TIM12));
	}
	/* TIM12 one-shot to a small period */
	wr32(PRD12, 1000);
	wr32(TGCR, rd32(TGCR) | 1U);
	wr32(TCR, rd32(TCR) | 0x40U);
	hs_sim_run_for(2 * US);
	note("tim12 one-shot", rd32(TIM12));
	hs_sim_run_for(1 * MS);
	note("tim12 stopped", rd32(TIM12));
	/* 64-bit mode */
	wr32(TGCR, 0);
	wr32(TGCR, 0x0003);
	wr32(PRD12, 0xFFFFFFFFU);
	wr32(PRD34, 0xFFFFFFFFU);
	wr32(TIM12, 0xFFFFFF00U);
	wr32(TCR, 0x80);
	hs_sim_run_for(50 * US);
	note("tim12 64-bit", rd32(TIM12));
	note("tim34 64-bit", rd32(TIM34));
}

/* The sequence, observed; with the polled regions' register log on or off. */
static void run_sequence(bool logged, struct run *r, const char *vcd_path)
{
	struct devtest_reglog log = { NULL, NULL, 0 };
	struct hs_uart *u;

	cur = r;
	r->notes.count = 0;
	devtest_boot(5, vcd_path);
	if (logged)
		devtest_reglog_begin(&log, "UART0,GPIO,TIMER64P3");
	u = ev3_input_uart(1);
	if (!u)
		tap_bail_out("no UART0");
	uart_sequence(u);
	gpio_sequence();
	timer_sequence();
	r->stats = *hs_uart_get_stats(u);
	if (logged)
		r->log_lines = devtest_reglog_end(&log);
	if (hs_sim_shutdown() != E_OK)
		tap_bail_out("shutdown failed");
	tf_read_text(vcd_path, r->vcd, sizeof(r->vcd));
}

int main(void)
{
	static struct run direct, hooked;
	char dir[] = "/tmp/test_direct_polls.XXXXXX", direct_vcd[64], hooked_vcd[64];
	const struct devtest_note *n;

	tap_plan(9);
	tf_make_scratch_dir(dir);
	snprintf(direct_vcd, sizeof(direct_vcd), "%s/direct.vcd", dir);
	snprintf(hooked_vcd, sizeof(hooked_vcd), "%s/hooked.vcd", dir);
	run_sequence(false, &direct, direct_vcd);
	run_sequence(true, &hooked, hooked_vcd);
	tf_remove_tree(dir);

	ok(direct.notes.count > 60 && direct.notes.count < DEVTEST_MAX_NOTES, "the sequence was observed (%u notes)",
	   direct.notes.count);
	n = devtest_find_note(&direct.notes, "lsr overrun");
	ok(n && (n->value & 0x03U) == 0x03U, "it has an overrun (LSR 0x%02x)", n ? n->value : 0U);
	n = devtest_find_note(&direct.notes, "lsr error");
	ok(n && (n->value & 0x88U) == 0x88U, "a framing error with RXFIFOE (LSR 0x%02x)", n ? n->value : 0U);
	n = devtest_find_note(&direct.notes, "intstat");
	ok(n && n->value != 0U && (n->lines & LINE_GPIO), "a GPIO edge interrupt (INTSTAT 0x%08x)", n ? n->value : 0U);
	n = devtest_find_note(&direct.notes, "tim34");
	ok(n && n->value != 0U, "the timer counts (TIM34 %u)", n ? n->value : 0U);
	is_int(hooked.notes.count, direct.notes.count, "the same number of observations with the register log on");
	is_int(devtest_same_notes(&direct.notes, &hooked.notes, "direct", "hooked"), direct.notes.count,
	       "every observation has the same value, time and interrupt lines (direct accesses and hooks)");
	ok(memcmp(&direct.stats, &hooked.stats, sizeof(direct.stats)) == 0 && strcmp(direct.vcd, hooked.vcd) == 0,
	   "the same UART statistics and VCD");
	ok(hooked.log_lines > direct.notes.count, "the register log was on (%u lines)", hooked.log_lines);
	return tap_done();
}
