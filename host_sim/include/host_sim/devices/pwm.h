/*
 * pwm.h — eHRPWM0/1 and eCAP0/eCAP1 (APWM mode) of the AM1808 as the motor
 * PWM outputs the EV3 drives its motors with.  Host only.
 *
 * eHRPWM0 (0x01F00000, the speaker) and eHRPWM1 (0x01F02000), 16-bit registers: time base (TBCTL, TBPRD with its
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
 *
 * The models know nothing of what their outputs drive: the board connects
 * a peer to each output (hs_pwm_connect), which is told whenever the
 * output's low fraction or frequency changes and reads it back with hs_pwm_low_fraction.
 */
#ifndef HOST_SIM_DEVICES_PWM_H
#define HOST_SIM_DEVICES_PWM_H

#include "host_sim/board.h"

/* The PWM outputs of the modelled modules. */
enum hs_pwm_output {
	HS_PWM_EHRPWM1_A,
	HS_PWM_EHRPWM1_B,
	HS_PWM_ECAP0,
	HS_PWM_ECAP1,
	HS_PWM_EHRPWM0_A,
	HS_PWM_EHRPWM0_B,       /* the EV3's speaker (through its amplifier) */
};
#define HS_PWM_OUTPUTS	6U

/* What an output drives: changed(ctx, out) runs after out's low fraction changed. */
struct hs_pwm_peer {
	void (*changed)(void *ctx, enum hs_pwm_output out);
	void *ctx;
};

/* Connects peer to out (copied; NULL disconnects).  Connections outlive the models. */
void hs_pwm_connect(enum hs_pwm_output out, const struct hs_pwm_peer *peer);

/* The peripheral models (for hs_board_cfg.devices). */
extern const struct hs_device hs_ehrpwm0_device;
extern const struct hs_device hs_ehrpwm1_device;
extern const struct hs_device hs_ecap0_device;
extern const struct hs_device hs_ecap1_device;

/* Fraction of each period the PWM output is low (0..1), as the H-bridge
 * sees it now; 1.0 (held low, as after reset) if the module is absent,
 * unpowered or stopped at a low level. */
double hs_pwm_low_fraction(enum hs_pwm_output src);

/* PWM frequency in Hz of a source now (0 if stopped). */
double hs_pwm_frequency(enum hs_pwm_output src);

#endif /* HOST_SIM_DEVICES_PWM_H */
