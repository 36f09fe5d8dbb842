/*
 * mach/mux.h — DaVinci pin multiplexing.
 *
 * LEGO's d_pwm includes it but uses nothing from it: the drivers program the
 * PINMUX registers themselves through da8xx_syscfg0_base (mach/da8xx.h:
 * DA8XX_PINMUX_REG, DA8XX_KICK0_REG...), so DaVinci's pin tables and
 * davinci_cfg_reg are not provided.
 */
#ifndef __INC_MACH_MUX_H
#define __INC_MACH_MUX_H

#include <mach/da8xx.h>

#endif /* __INC_MACH_MUX_H */
