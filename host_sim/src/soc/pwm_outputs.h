/*
 * pwm_outputs.h — what the PWM models (ehrpwm.c, ecap.c) give the output
 * table (pwm_outputs.c).  Private to host_sim/src/soc.
 */
#ifndef HOST_SIM_SOC_PWM_OUTPUTS_H
#define HOST_SIM_SOC_PWM_OUTPUTS_H

#include "host_sim/devices/pwm.h"

/* Tells out's peer that its low fraction changed. */
void hs_pwm_output_changed(enum hs_pwm_output out);

double hs_ehrpwm1_low_fraction(unsigned output);
double hs_ehrpwm1_frequency(void);
double hs_ecap_low_fraction(unsigned n);
double hs_ecap_frequency(unsigned n);

#endif /* HOST_SIM_SOC_PWM_OUTPUTS_H */
