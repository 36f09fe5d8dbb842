/*
 * test_script.c — scenario scripts: scheduled drives and interrupt
 * requests, runs, expectations on pins, signals and bug counts; a failed
 * expectation and a malformed line are reported with their line number.
 */
#include <string.h>

#include "tap.h"
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/scenario.h"

static unsigned isr_runs;
static uint64_t isr_time;

static void isr(intptr_t x)
{
	(void)x;
	isr_runs++;
	isr_time = hs_now();
}

static const struct rtos_int_cfg ints[] = { { 60, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, 60, isr, 1 } };
static const struct rtos_cfg cfg = { .name = "script", .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs) };

static const char script[] =
	"# a small scenario\n"
	"at 2ms drive GP5_11 high\n"
	"at 3ms irq 60\n"
	"at 5ms drive GP5_11 pulldown   # weak\n"
	"run 2500us\n"
	"expect GP5_11 1\n"
	"until 4ms\n"
	"expect irq.int60 0\n"
	"run 2ms\n"
	"expect GP5_11 0\n"
	"expect-bugs 0\n";

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg };
	char err[200];
	ER er;

	tap_plan(8);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	er = hs_sim_script(script, err, sizeof(err));
	is_int(er, E_OK, "the script runs and its expectations hold");
	if (er != E_OK)
		tap_diag("%s", err);
	is_u64(hs_now(), 6000000, "it ran to 6 ms");
	ok(isr_runs == 1 && isr_time == 3000000, "the scheduled interrupt request ran the ISR at 3 ms");
	ok(hs_gpio_level(HS_GPIO(5, 11)) == 0, "the last drive took effect");

	er = hs_sim_script("expect GP5_11 1\nrun 1ms\n", err, sizeof(err));
	ok(er == E_OBJ && strstr(err, "line 1: GP5_11 is 0 at 6000000 ns, expected 1"), "a failed expectation: %s", err);
	is_u64(hs_now(), 7000000, "the rest of the script still ran");
	er = hs_sim_script("run 1ms\nat 1ms jump GP5_11\nrun 1ms\n", err, sizeof(err));
	ok(er == E_PAR && strstr(err, "line 2:"), "a malformed line: %s", err);
	is_u64(hs_now(), 8000000, "nothing after it ran");
	hs_sim_shutdown();
	return tap_done();
}
