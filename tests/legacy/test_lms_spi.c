/*
 * test_lms_spi.c — lms_spi, SPI0 in LEGO's idiom (a `volatile unsigned long *`
 * array indexed by register number, as lms2012's d_analog declares it), at
 * the configuration's -O2 on the simulated EV3.  Where `unsigned long` is
 * the target's 4 bytes (host32, arm926-test) the module runs: its set-up
 * reaches SPIGCR1, SPIFMT0, SPIDELAY and SPIDEF at their offsets, its frames
 * get the converter's answers, its exit restores the registers.  On the
 * 64-bit hosts Spi0[n] is 8n bytes on: the build found the pointer and says
 * so (mk/legacy_long_regs.sh), and the test checks that report instead of
 * running a module whose every register address is wrong.
 */
#include <stdio.h>
#include <string.h>

#include "legacy_test.h"
#include "sil.h"
#include "host_sim/psc.h"
#include "host_sim/devices/spi_adc.h"

#include "lms_spi_hack.h"
#include "legacy_long_regs.h"

#define SPI0_PHYS   0x01C41000U
#define PLAN        10

/* SPI0's register at offset as the bus sees it (32 bits). */
static uint32_t spi_reg(unsigned offset)
{
	return sil_rew_mem(rtos_host_map_io(SPI0_PHYS + offset, 4));
}

static void body(void)
{
	is_int(lms_spi_load(), 0, "lms_spi's init succeeds");
	is_int((int)sizeof(unsigned long), 4, "unsigned long is the target's 4 bytes here");
	is_int((int)(lms_spi_setup(0) & 0x01000003U), 0x01000003, "Spi0[SPIGCR1] (offset 0x04): master and enabled");
	is_int((int)spi_reg(0x50), 0x00014A10, "Spi0[SPIFMT0] = 0x00010010 | CNVSPD << 8 reached offset 0x50");
	is_int((int)spi_reg(0x48), 0x0A0A0A0A, "Spi0[SPIDELAY] reached offset 0x48");
	is_int((int)lms_spi_setup(3), 0x00000001, "Spi0[SPIDEF] (offset 0x4C) reads back what was written");
	is_int((int)(lms_spi_adc_answer(2) >> 12), 5,
	       "three frames through Spi0[SPIDAT0]/Spi0[SPIBUF]: the third answers channel 5 (ADS7957 pipeline)");
	is_int((int)lms_spi_adc_answer(2), (int)ads7957_word(5, ev3_adc_channel_mv(5)), "with the converter's value");
	lms_spi_unload();
	is_int((int)(spi_reg(0x04) & 0x01000000U), 0, "exit: SpiRestoreReg put SPIGCR1 back (disabled)");
}

/* The boot loader's part on the brick: PSC0 powers SPI0. */
static void power_on(void)
{
	hs_psc_force(HS_PSC0_MODULE(HS_LPSC0_SPI0), HS_PSC_ENABLE);
}

int main(void)
{
	static const struct lt_test test = {
		.name = "lms_spi", .power_on = power_on, .body = body, .after_boot = PLAN - 1, .plain_pointers = true,
	};
	const char *lp64 = legacy_long_regs_of("lms_spi");

	tap_plan(PLAN);
	if (sizeof(unsigned long) == 8) {
		ok(lp64 != NULL && strstr(lp64, "lms_spi: Spi0 is a pointer to volatile unsigned long") &&
		   strstr(lp64, "Spi0[n] is 8n bytes on, not register n at 4n"),
		   "the build reports lms_spi's Spi0 as a wrong register address here: %s", lp64 ? lp64 : "(nothing)");
		tap_skip(PLAN - 1, "a 64-bit host: Spi0[n] is not register n (the module runs in host32 and arm926-test)");
		return tap_done();
	}
	ok(lp64 == NULL, "the build found no register pointer this configuration cannot run");
	lt_run(&test);
	return tap_done();
}
