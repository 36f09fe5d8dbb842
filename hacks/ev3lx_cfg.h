/*
 * ev3lx_cfg.h — what the library's static-API fragment (cfg/ev3lx.cfg) names
 * from linux_compat and the hacks: the settings (priorities, stacks, the
 * pool's and IRQ threads' counts, the tick's line, every module's function
 * codes) and the routines (tasks, ISRs, initialisation and termination
 * routines, extended service routines).  No Linux header: a firmware's
 * kernel_cfg.c also includes the headers of the kernel's other drivers, which
 * may bring a Linux layer of their own (EV3RT's).  The fragment #includes it, so a
 * configurator's pass over the fragment and the kernel_cfg.c it writes see
 * the same declarations, on the host (ev3cfg) as in an HRP2 firmware.
 */
#ifndef EV3LX_EV3LX_CFG_H
#define EV3LX_EV3LX_CFG_H

#include <kernel.h>
#include <rtos_cfg.h>
/* by relative path: linux_compat's include directories, which hold its Linux
 * headers, are not on a firmware's path */
#include "../linux_compat/include/linux_compat/config.h"
#include "../linux_compat/mach-davinci/include/linux_compat/irq_lines.h"
#include "hack_routines.h"
/* the modules' function codes only: their ABI headers are Linux's */
#define EV3LX_CFG_NAMES_ONLY 1
#include "pwm_hack.h"
#include "analog_hack.h"
#include "uart_hack.h"
#include "ui_hack.h"
#include "power_hack.h"
#include "sound_hack.h"
#include "iic_hack.h"
#include "lcd_hack.h"

#endif /* EV3LX_EV3LX_CFG_H */
