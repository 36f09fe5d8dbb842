/*
 * boot_args.c (AM1808) — the boot command line is the one the firmware's
 * start-up passes before the kernel starts (lx_compat_set_boot_args).
 */
#include <linux_compat/config.h>
#include <linux_compat/platform.h>

static const char *boot_args;

/* Keeps the firmware's command line (the string must stay valid). */
void lx_compat_set_boot_args(const char *args)
{
	boot_args = args;
}

/* The command line, "" if the start-up passed none. */
const char *lx_platform_boot_args(void)
{
	return boot_args != NULL ? boot_args : "";
}
