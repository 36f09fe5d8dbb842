/*
 * pwm.h — eHRPWM1 and eCAP0/eCAP1 (APWM mode) of the AM1808 as the motor
 * PWM sources of the EV3 (facts §2, §3).  Host only.
 *
 * eHRPWM1 (0x01F02000, 16-bit registers): time base (TBCTL, TBPRD with its
 * shadow, TBCNT computed from the virtual clock), counter-compare CMPA/CMPB
 * with shadow registers loaded at counter zero and/or period as CMPCTL
 * says, action qualifier AQCTLA/B and the software forces.  Dead band, PWM
 * chopper, trip zones and event triggers are declared; enabling them is
 * reported as unmodelled.  The time base runs only while SYSCFG0
 * CFGCHIP1.TBCLKSYNC is set.
 * eCAP0/1 (0x01F06000, 0x01F07000) in APWM mode: CAP1 period and CAP2
 * compare (active), CAP3/CAP4 their shadows loaded at the period, polarity
 * from ECCTL2.APWMPOL, counter running while ECCTL2.TSCTRSTOP is set.
 * Module clock of both: the ASYNC3 domain, HS_PLL1_SYSCLK2_HZ.
 */
#ifndef HOST_SIM_DEVICES_PWM_H
#define HOST_SIM_DEVICES_PWM_H

#include "host_sim/board.h"
#include "host_sim/devices/ev3_ports.h"

/* The board devices (for hs_board_cfg.devices). */
extern const struct hs_device ev3_ehrpwm1_device;
extern const struct hs_device ev3_ecap0_device;
extern const struct hs_device ev3_ecap1_device;

/* Fraction of each period the PWM output is low (0..1), as the H-bridge
 * sees it now; 1.0 (held low, as after reset) if the module is absent,
 * unpowered or stopped at a low level. */
double ev3_pwm_low_fraction(enum ev3_pwm_source src);

/* PWM frequency in Hz of a source now (0 if stopped). */
double ev3_pwm_frequency(enum ev3_pwm_source src);

#endif /* HOST_SIM_DEVICES_PWM_H */
