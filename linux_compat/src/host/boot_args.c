/*
 * boot_args.c (host) — the boot command line is the one the simulated board
 * hands the host kernel, as a boot loader would.
 */
#include <linux_compat/config.h>
#include <linux_compat/platform.h>
#include <rtos_host.h>

/* The simulated boot loader keeps it for the next boots. */
void lx_compat_set_boot_args(const char *args)
{
	rtos_host_set_boot_args(args);
}

/* rtos_host_boot_args. */
const char *lx_platform_boot_args(void)
{
	return rtos_host_boot_args();
}
