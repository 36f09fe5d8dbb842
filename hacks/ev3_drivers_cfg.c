/*
 * ev3_drivers_cfg.c — ev3_drivers_cfg (see ev3_drivers_cfg.h).
 *
 * The shared areas are read without service calls (MOTORDATA, ANALOG, UART),
 * so user domains need read access to the pool they are allocated from; the
 * pool holds nothing else a user task could not also learn through the
 * drivers' read() and mmap in Linux.  Writes stay with the drivers.
 */
#include <linux_compat/config.h>
#include <linux_compat/heap.h>
#include "ev3_drivers_cfg.h"
#include "pwm_hack.h"
#include "analog_hack.h"
#include "uart_hack.h"
#include "ui_hack.h"
#include "power_hack.h"
#include "sound_hack.h"
#include "iic_hack.h"
#include "lcd_hack.h"

#define SHARED_AREA_ROW(dom) \
	{ (dom), lx_heap_area, sizeof(lx_heap_area), TPM_READ, "ev3 driver shared memory" }

static const struct rtos_mem_cfg shared_area_rows[] = {
	SHARED_AREA_ROW(1),
#if TNUM_DOMID >= 2
	SHARED_AREA_ROW(2),
#endif
#if TNUM_DOMID >= 3
	SHARED_AREA_ROW(3),
#endif
#if TNUM_DOMID >= 4
	SHARED_AREA_ROW(4),
#endif
};
_Static_assert(TNUM_DOMID >= 1 && TNUM_DOMID <= 4, "one shared-area row per user domain (1..4)");

static const struct rtos_cfg *const driver_cfgs[] = {
	&linux_compat_cfg, &pwm_hack_cfg, &analog_hack_cfg, &uart_hack_cfg, &ui_hack_cfg,
	&power_hack_cfg, &sound_hack_cfg, &iic_hack_cfg, &lcd_hack_cfg, NULL,
};

const struct rtos_cfg ev3_drivers_cfg = {
	.name = "ev3_drivers_cfg",
	.mems = RTOS_TABLE(shared_area_rows),
	.includes = driver_cfgs,
};
