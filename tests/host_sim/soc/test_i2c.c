/*
 * test_i2c.c — the I2C0 controller model at register level, polled as a
 * bare-metal driver would: reset values, the SCL period from ICPSC/ICCLKL/
 * ICCLKH, a master write and a master read against a register-file slave
 * (a received byte held while ICDRR is full, nothing overrun), ARDY and a
 * repeated START, a NACKed address waiting for STP, ICIVR's priority and
 * clearing, ICSTR's write-1-to-clear, lost arbitration, IRS = 0, and the
 * interrupt line following ICIMR.
 */
#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/i2c.h"

#define B	HS_I2C0_BASE
#define ICOAR	(B + 0x00)
#define ICIMR	(B + 0x04)
#define ICSTR	(B + 0x08)
#define ICCLKL	(B + 0x0C)
#define ICCLKH	(B + 0x10)
#define ICCNT	(B + 0x14)
#define ICDRR	(B + 0x18)
#define ICSAR	(B + 0x1C)
#define ICDXR	(B + 0x20)
#define ICMDR	(B + 0x24)
#define ICIVR	(B + 0x28)
#define ICPSC	(B + 0x30)

#define AL	0x01U
#define NACK	0x02U
#define ARDY	0x04U
#define RRDY	0x08U
#define XRDY	0x10U
#define SCD	0x20U
#define BB	0x1000U
#define IRS	0x20U
#define TRX	0x200U
#define MST	0x400U
#define STP	0x800U
#define STT	0x2000U

static uint32_t rd(uint32_t phys)
{
	return sil_rew_mem(rtos_host_map_io(phys, 4));
}

static void wr(uint32_t phys, uint32_t v)
{
	sil_wrw_mem(rtos_host_map_io(phys, 4), v);
}

/* Runs the simulation until ICSTR has one of bits, at most 10 ms: true if it came. */
static bool wait_str(uint32_t bits)
{
	for (int i = 0; i < 10000; i++) {
		if (rd(ICSTR) & bits)
			return true;
		hs_sim_run_for(1000);
	}
	return false;
}

static const struct rtos_cfg cfg = { .name = "i2c" };

int main(void)
{
	static const struct hs_device *const devices[] = { &hs_i2c0_device, NULL };
	static const struct hs_board_cfg board = { .devices = devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board };
	static struct hs_i2c_regfile f;
	struct hs_i2c_stats st;
	uint64_t t0;

	tap_plan(32);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	for (int i = 0; i < 256; i++)
		f.regs[i] = (uint8_t)(0xA0 + i);
	is_int(hs_i2c_attach(0, 0x50, &hs_i2c_regfile_ops, &f), E_OK, "slave at 0x50");
	is_int(hs_i2c_attach(0, 0x50, &hs_i2c_regfile_ops, &f), E_OBJ, "the same address twice: E_OBJ");
	is_int(hs_i2c_attach(0, 0x80, &hs_i2c_regfile_ops, &f), E_PAR, "an 8-bit address: E_PAR");
	is_int(rd(ICSTR), 0x410, "ICSTR at reset: XSMT | ICXRDY");

	/* 24 MHz / (ICPSC 1 + 1) = 12 MHz; (54 + 6) + (54 + 6) cycles = 10 us */
	wr(ICMDR, 0);
	wr(ICPSC, 1);
	wr(ICCLKL, 54);
	wr(ICCLKH, 54);
	wr(ICOAR, 0x08);
	wr(ICMDR, IRS);

	/* write pointer 0x10 and 0x5A: START+address, 2 bytes, STOP */
	wr(ICSAR, 0x50);
	wr(ICCNT, 2);
	wr(ICDXR, 0x10);
	ok(!(rd(ICSTR) & XRDY), "ICDXR written: ICXRDY clear");
	t0 = hs_now();
	wr(ICMDR, IRS | MST | TRX | STT | STP);
	ok(rd(ICSTR) & BB, "STT: bus busy");
	ok(wait_str(XRDY), "the first byte moved out of ICDXR: ICXRDY");
	wr(ICDXR, 0x5A);
	ok(wait_str(SCD), "STOP condition detected after the count");
	is_int((int)hs_i2c_get_stats(0).scl_period_ns, 10000, "SCL period 10 us");
	ok(hs_now() - t0 >= 29 * 10000ULL && hs_now() - t0 < 29 * 10000ULL + 2000U,
	   "START, address, 2 bytes and STOP: 29 periods, polled in 1 us steps (%llu ns)",
	   (unsigned long long)(hs_now() - t0));
	is_int(f.regs[0x10], 0x5A, "the slave stored 0x5A at 0x10");
	ok(!(rd(ICSTR) & BB) && !(rd(ICMDR) & (MST | STP)), "bus free, MST and STP cleared");
	wr(ICSTR, SCD);
	ok(!(rd(ICSTR) & SCD), "ICSTR.SCD write-1-to-clear");

	/* pointer write without STP: ARDY, then a repeated START to read 3 bytes */
	wr(ICCNT, 1);
	wr(ICDXR, 0x20);
	wr(ICMDR, IRS | MST | TRX | STT);
	ok(wait_str(ARDY), "count done without STP: ARDY, bus held");
	ok(rd(ICSTR) & BB, "  still busy");
	wr(ICCNT, 3);
	wr(ICMDR, IRS | MST | STT | STP);
	ok(wait_str(RRDY), "repeated START, read: the first byte in ICDRR");
	hs_sim_run_for(500000);
	ok(!(rd(ICSTR) & SCD), "ICDRR unread: the next byte is held, no STOP yet");
	is_int(rd(ICDRR), 0xC0, "byte 0 (register 0x20)");
	ok(wait_str(RRDY), "then the next");
	is_int(rd(ICDRR), 0xC1, "byte 1");
	ok(wait_str(RRDY), "and the last");
	is_int(rd(ICDRR), 0xC2, "byte 2");
	ok(wait_str(SCD), "STOP");
	st = hs_i2c_get_stats(0);
	ok(st.repeated_starts == 1 && st.bytes_read == 3, "one repeated START, 3 bytes read");
	wr(ICSTR, 0x3F);

	/* nobody at 0x51: NACK, the module waits for STP; ICIVR with interrupts enabled */
	wr(ICIMR, AL | NACK | ARDY | SCD);
	wr(ICSAR, 0x51);
	wr(ICCNT, 1);
	wr(ICMDR, IRS | MST | STT);
	ok(wait_str(NACK), "address NACKed");
	ok(hs_intc_pending(HS_I2C0_INTNO), "the interrupt line raised (NACK enabled)");
	is_int(rd(ICIVR), 2, "ICIVR: 2, NACK");
	ok(!(rd(ICSTR) & NACK) && !hs_intc_pending(HS_I2C0_INTNO), "cleared by the read, line low");
	wr(ICMDR, rd(ICMDR) | STP);
	ok(wait_str(SCD), "STP: STOP");
	is_int(rd(ICIVR), 6, "ICIVR: 6, SCD");

	/* arbitration lost at the next address */
	hs_i2c_lose_arbitration(0, 1);
	wr(ICSAR, 0x50);
	wr(ICCNT, 1);
	wr(ICMDR, IRS | MST | STT | STP);
	ok(wait_str(AL) && !(rd(ICMDR) & MST) && !(rd(ICSTR) & BB), "AL: master mode left, bus not ours");

	wr(ICMDR, 0);
	is_int(rd(ICSTR), 0x410, "IRS = 0: ICSTR back to its reset value");
	hs_sim_shutdown();
	return tap_done();
}
