/*
 * fw_main.c — the link-check firmware's C entry.
 *
 * On the brick, HRP2's own start code initialises the kernel, which then runs
 * the ATT_INI routines and tasks of the configuration; this image stands in
 * for that only to prove that libev3lx.a links completely against the HRP2
 * service calls (the provider beside it) and to produce a loadable uImage.
 */
#include "kernel.h"
#include "ev3api.h"

void fw_main(void);

/*
 * The image's root: on the brick HRP2's configurator turns the application's
 * configuration (which INCLUDEs ev3api_cfg: linux_compat, the three drivers'
 * service calls, their ISRs and tasks) into kernel tables.  Referencing it
 * here keeps exactly what a real firmware would keep after --gc-sections.
 */
const struct rtos_cfg *volatile fw_configuration = &ev3api_cfg;

/* Never returns: the real kernel would dispatch the configured tasks here. */
void fw_main(void)
{
	syslog(LOG_NOTICE, "ev3lx link-check firmware");
	for (;;)
		;
}
