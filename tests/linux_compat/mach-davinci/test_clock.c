/*
 * test_clock.c — the DA850 clocks by name (linux/clk.h, mach-davinci/clock.c):
 * the PRU soft UART's pru_ck and mcasp_pru at PLL0_SYSCLK2 (150 MHz), an
 * unknown name -ENOENT, enables counted and an unbalanced disable reported.
 */
#define KBUILD_MODNAME "clktest"
#include "lx_log_test.h"
#include <linux/clk.h>
#include "host_sim/board.h"

static void body(void)
{
	struct clk *pru = clk_get(NULL, "pru_ck"), *mcasp = clk_get(NULL, "mcasp_pru");

	ok(!IS_ERR(pru) && !IS_ERR(mcasp), "pru_ck and mcasp_pru exist");
	is_int((int)clk_get_rate(pru), 150000000, "pru_ck: 150 MHz");
	is_int((int)clk_get_rate(mcasp), 150000000, "mcasp_pru: 150 MHz");
	ok(PTR_ERR(clk_get(NULL, "no_such_clock")) == -ENOENT, "an unknown name: -ENOENT");
	is_int((int)clk_get_rate(NULL), 0, "clk_get_rate(NULL): 0");
	is_int(clk_enable(pru), 0, "clk_enable");
	is_int(clk_prepare_enable(pru), 0, "clk_prepare_enable");
	is_int(clk_enable(ERR_PTR(-ENOENT)), -EINVAL, "clk_enable of an error pointer: -EINVAL");
	clk_disable(pru);
	clk_disable_unprepare(pru);
	is_int((int)DC_EXPECT_BUG(clk_disable(pru)), 1, "a disable without an enable is reported");
	ok(strstr(dc_bug, "clk_disable(pru_ck): not enabled") != NULL, "naming the clock");
	clk_put(pru);
	clk_put(mcasp);
}

int main(void)
{
	tap_plan(12);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
