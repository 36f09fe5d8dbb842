/*
 * test_trm_enable_widths.c — register behaviour the AM1808 TRM gives and
 * LEGO's drivers rely on: eCAP's 32-bit TSCTR and CTRPHS take 16-bit halves
 * (a half written to the running TSCTR replaces that half of the count, the
 * other half keeps counting from where it was); a SPIDAT1 write with SPI
 * out of reset but SPIGCR1.ENABLE still 0 latches its fields and starts no
 * transfer, and the first one after ENABLE does; one while SPI is in reset
 * is still reported.
 */
#include "devtest.h"
#include "host_sim/psc.h"

#define TSCTR   0x00U
#define CTRPHS  0x04U
#define ECCTL2  0x2AU

#define SPIGCR0  0x00U
#define SPIGCR1  0x04U
#define SPIDAT1  0x3CU
#define SPIBUF   0x40U
#define SPIFMT0  0x50U
#define RXEMPTY  (1U << 31)

static void test_ecap_halves(void)
{
	const uint32_t e = HS_ECAP0_BASE;
	uint32_t v;

	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_ECAP), HS_PSC_ENABLE);
	wr32(e + TSCTR, 0x12340000U);
	wr16(e + ECCTL2, 0x0010);               /* capture mode, TSCTRSTOP: free running */
	hs_sim_run_for(1000);
	wr16(e + TSCTR, 0x0005);                /* the low half, as LEGO's d_pwm through a UWORD pointer */
	v = rd32(e + TSCTR);
	ok((v >> 16) == 0x1234U && (v & 0xFFFFU) >= 5U && (v & 0xFFFFU) < 0x40U,
	   "TSCTR low half written: the high half kept, the count runs on from 5 (0x%08x)", v);
	wr16(e + TSCTR + 2U, 0x00AB);
	v = rd32(e + TSCTR);
	ok((v >> 16) == 0x00ABU && (v & 0xFFFFU) >= 5U && (v & 0xFFFFU) < 0x80U,
	   "TSCTR high half written: the low half keeps counting (0x%08x)", v);
	hs_sim_run_for(1000);
	ok(rd32(e + TSCTR) - v >= 131U && rd32(e + TSCTR) - v < 160U, "and it still counts at 132 MHz");
	wr16(e + CTRPHS, 0xBEEF);
	wr16(e + CTRPHS + 2U, 0x1234);
	is_int((int)rd32(e + CTRPHS), 0x1234BEEF, "CTRPHS written as two 16-bit halves reads back whole");
	is_int((int)rd16(e + CTRPHS + 2U), 0x1234, "and its upper half reads alone");
	wr16(e + ECCTL2, 0x0006);
}

static void test_spidat1_before_enable(void)
{
	const uint32_t s = HS_SPI0_BASE;
	unsigned bugs = rtos_host_bug_count();

	hs_psc_force(HS_PSC0_MODULE(HS_LPSC0_SPI0), HS_PSC_ENABLE);
	wr32(s + SPIGCR0, 0);
	wr32(s + SPIGCR0, 1);                   /* out of reset */
	wr32(s + SPIGCR1, 0x00000003);          /* master, not enabled */
	wr32(s + SPIFMT0, 0x00010010);          /* 16-bit words */
	wr32(s + SPIDAT1, 0x00000000);          /* format 0 selected before the enable (LEGO's SPIInit) */
	hs_sim_run_for(100000);
	is_int((int)rtos_host_bug_count(), (int)bugs, "SPIDAT1 with ENABLE=0: no bug report");
	ok(rd32(s + SPIBUF) & RXEMPTY, "and no transfer: SPIBUF stays empty");
	is_int((int)rd32(s + SPIDAT1), 0, "its fields are latched");
	wr32(s + SPIGCR1, 0x01000003);          /* enable */
	wr32(s + SPIDAT1, 0x00001234);
	hs_sim_run_for(100000);
	ok(!(rd32(s + SPIBUF) & RXEMPTY), "after ENABLE a SPIDAT1 write transfers a word");
	wr32(s + SPIGCR0, 0);                   /* in reset */
	rtos_host_expect_bugs(true);
	wr32(s + SPIDAT1, 0x00005678);
	rtos_host_expect_bugs(false);
	is_int((int)rtos_host_bug_count(), (int)bugs + 1, "a SPIDAT1 write while SPI is in reset is still reported");
	wr32(s + SPIGCR0, 1);
}

int main(void)
{
	tap_plan(10);
	devtest_boot(7, NULL);
	test_ecap_halves();
	test_spidat1_before_enable();
	hs_sim_shutdown();
	return tap_done();
}
