/*
 * pwm_outputs.c — the PWM outputs of eHRPWM1 and eCAP0/1 as one table: what
 * each output drives (the peer the board connects) and its state now.
 */
#include "host_sim/devices/pwm.h"
#include "pwm_outputs.h"

static struct hs_pwm_peer peers[HS_PWM_OUTPUTS];

void hs_pwm_connect(enum hs_pwm_output out, const struct hs_pwm_peer *peer)
{
	if ((unsigned)out >= HS_PWM_OUTPUTS)
		return;
	peers[out] = peer != NULL ? *peer : (struct hs_pwm_peer){ 0 };
}

void hs_pwm_output_changed(enum hs_pwm_output out)
{
	if ((unsigned)out < HS_PWM_OUTPUTS && peers[out].changed != NULL)
		peers[out].changed(peers[out].ctx, out);
}

/* Low fraction of an output now. */
double hs_pwm_low_fraction(enum hs_pwm_output out)
{
	switch (out) {
	case HS_PWM_EHRPWM1_A: return hs_ehrpwm1_low_fraction(0);
	case HS_PWM_EHRPWM1_B: return hs_ehrpwm1_low_fraction(1);
	case HS_PWM_ECAP0: return hs_ecap_low_fraction(0);
	case HS_PWM_ECAP1: return hs_ecap_low_fraction(1);
	default: return 1.0;
	}
}

/* PWM frequency of an output now (0 if stopped). */
double hs_pwm_frequency(enum hs_pwm_output out)
{
	switch (out) {
	case HS_PWM_EHRPWM1_A:
	case HS_PWM_EHRPWM1_B: return hs_ehrpwm1_frequency();
	case HS_PWM_ECAP0: return hs_ecap_frequency(0);
	case HS_PWM_ECAP1: return hs_ecap_frequency(1);
	default: return 0;
	}
}
