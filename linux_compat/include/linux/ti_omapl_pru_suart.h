/*
 * linux/ti_omapl_pru_suart.h — the board's platform data for TI's PRU soft
 * UART ("ti_omapl_pru_suart"), as TI's DaVinci 2.6.33 tree declares it
 * (LEGO's EV3 kernel, e.g. ev3dev/ev3-kernel include/linux/ti_omapl_pru_suart.h):
 * a version word, set by the board (devices-da8xx.c's da8xx_register_pru_suart).
 * The board's device has five memory resources — PRU subsystem, McASP, PSC0,
 * PSC1, shared RAM — and one IRQ per soft UART (PRU EVTOUT0..7).
 */
#ifndef _LINUX_SUART_OMAPL_PRU_H
#define _LINUX_SUART_OMAPL_PRU_H

#include <linux/serial_core.h>
#include <linux/platform_device.h>

struct ti_pru_suart_platform_data {
	u32 version;
};

#endif
