/*
 * api_internal.h — helpers shared by the API's source files (not for applications).
 */
#ifndef EV3API_INTERNAL_H
#define EV3API_INTERNAL_H

#include <stdbool.h>
#include "kernel.h"

/* Whether the caller may write size bytes at p: not NULL and, from a task,
 * inside its protection domain (prb_mem).  Handlers run in the kernel domain. */
static inline bool api_can_write(const void *p, SIZE size)
{
	if (p == NULL)
		return false;
	return sns_ctx() || prb_mem(p, size, TSK_SELF, TPM_WRITE) == E_OK;
}

/* Forget everything of a previous boot (ATT_INI of ev3api_cfg, in config.c). */
void api_motor_boot(void);
void api_sensor_boot(void);
void api_brick_boot(void);
void api_battery_boot(void);

/* The button task's body (CRE_TSK EV3_BUTTON_TSKID in config.c): runs click handlers. */
void api_button_task(intptr_t exinf);

#endif /* EV3API_INTERNAL_H */
