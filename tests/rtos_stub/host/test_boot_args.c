/*
 * test_boot_args.c — the simulated boot loader's command line: empty until
 * set, seen by ATT_INI routines, kept across boots and shutdowns until it is
 * changed or cleared.
 */
#include <string.h>

#include "tap.h"
#include "kernel.h"
#include "rtos_host.h"

static char seen[64];

static void ini_fn(intptr_t x)
{
	(void)x;
	snprintf(seen, sizeof(seen), "%s", rtos_host_boot_args());
}

static const struct rtos_ini_cfg inis[] = { { ini_fn, 0 } };
static const struct rtos_cfg cfg = { .name = "boot_args", .inis = RTOS_TABLE(inis) };

int main(void)
{
	static const char line[] = "console=ttyS1 d_uart.port3_base=0x01f18000";

	tap_plan(5);
	is_str(rtos_host_boot_args(), "", "no command line before one is set");
	rtos_host_set_boot_args(line);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	is_str(seen, line, "an ATT_INI routine sees the command line");
	rtos_host_shutdown();
	is_str(rtos_host_boot_args(), line, "it outlives the boot, as a boot loader's does");
	rtos_host_set_boot_args(NULL);
	is_str(rtos_host_boot_args(), "", "cleared");
	return tap_done();
}
