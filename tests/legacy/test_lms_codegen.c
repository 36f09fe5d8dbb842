/*
 * test_lms_codegen.c — the lms_codegen conformance module (tests/legacy/
 * drivers/lms_codegen.c) at the configuration's -O2 on the simulated EV3:
 * its adjacent register stores, which gcc merges (a 4-byte store over
 * eHRPWM1's 16-bit AQCTLA/AQCTLB, an 8-byte one over eCAP0's CAP1/CAP2), reach
 * each register; eCAP0's TSCTR/CTRPHS take 16-bit halves; SPIDAT1 written
 * before SPIGCR1.ENABLE latches its fields without a transfer or a report;
 * a tone command's `char` bytes above 127 give 440 Hz (kbuild's
 * -funsigned-char); and no bug report is made (one would fail the run).
 */
#include <stdio.h>

#include "legacy_test.h"
#include "sil.h"
#include "host_sim/psc.h"

#include "lms_codegen_hack.h"

static uint32_t reg(uint32_t phys, unsigned width)
{
	volatile void *p = rtos_host_map_io(phys, width);

	return width == 2U ? sil_reh_mem((uint16_t *)p) : sil_rew_mem((uint32_t *)p);
}

static void body(void)
{
	static const char tone_440[] = { 1, 50, (char)0xB8, 0x01 };

	is_int(lms_codegen_load(), 0, "lms_codegen's init succeeds");
	is_int((int)reg(HS_EHRPWM1_BASE + 0x16, 2), 0x0021, "eHRPWM1.AQCTLA = 0x0021 (merged with AQCTLB by gcc)");
	is_int((int)reg(HS_EHRPWM1_BASE + 0x18, 2), 0x0201, "eHRPWM1.AQCTLB = 0x0201");
	is_int((int)reg(HS_ECAP0_BASE + 0x08, 4), 0x1000, "eCAP0.CAP1 = 0x1000 (merged with CAP2)");
	is_int((int)reg(HS_ECAP0_BASE + 0x0C, 4), 0x0400, "eCAP0.CAP2 = 0x0400");
	is_int((int)reg(HS_ECAP0_BASE + 0x2A, 2), 0x0690, "eCAP0.ECCTL2 = 0x0690 after TSCTR/CTRPHS's 16-bit halves");
	is_int((int)reg(HS_SPI0_BASE + 0x04, 4), 0x01000003, "SPI0 enabled after SPIDAT1 was written while disabled");
	is_int((int)reg(HS_SPI0_BASE + 0x3C, 4), 0, "SPIDAT1 kept the format select written before the enable");
	is_int(lms_codegen_command(tone_440, (int)sizeof(tone_440)), 4, "TONE command accepted");
	is_int((int)lms_codegen_frequency(), 440, "its `char` bytes 0xB8 0x01 are 440 Hz (-funsigned-char), not 184");
	is_int((int)reg(HS_EHRPWM0_BASE + 0x0A, 2), 132000000 / 32 / 440 - 1, "eHRPWM0.TBPRD is 440 Hz's period");
	lms_codegen_unload();
}

/* The boot loader's part on the brick: PSC power for the modules. */
static void power_on(void)
{
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_EHRPWM), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_ECAP), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC0_MODULE(HS_LPSC0_SPI0), HS_PSC_ENABLE);
}

int main(void)
{
	static const struct lt_test test = {
		.name = "lms_codegen", .power_on = power_on, .body = body, .after_boot = 12, .plain_pointers = true,
	};

	tap_plan(12);
	if (lt_run(&test))
		ok(lt_done, "the test body ran to its end");
	return tap_done();
}
