/*
 * config.c — ev3api_cfg: what an application using the API INCLUDEs.
 */
#include "ev3api.h"
#include "ev3_drivers_cfg.h"
#include "api_internal.h"

/* ATT_INI: the API's state starts empty at every boot. */
static void api_boot(intptr_t exinf)
{
	(void)exinf;
	api_motor_boot();
	api_sensor_boot();
}

static const struct rtos_ini_cfg api_inis[] = { { api_boot, 0 } };

static const struct rtos_cfg *const api_includes[] = { &ev3_drivers_cfg, NULL };

const struct rtos_cfg ev3api_cfg = {
	.name = "ev3api_cfg",
	.inis = RTOS_TABLE(api_inis),
	.includes = api_includes,
};
