/*
 * boot_args.c (host) — the boot command line is the one the simulated board
 * hands the host kernel, as a boot loader would.
 */
#include <linux_compat/platform.h>
#include <rtos_host.h>

/* rtos_host_boot_args. */
const char *lx_platform_boot_args(void)
{
	return rtos_host_boot_args();
}
