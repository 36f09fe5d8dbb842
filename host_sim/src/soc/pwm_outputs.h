/*
 * pwm_outputs.h — how the PWM models (ehrpwm.c, ecap.c) enter their outputs
 * into the output table (pwm_outputs.c).  Private to host_sim/src/soc.
 */
#ifndef HOST_SIM_SOC_PWM_OUTPUTS_H
#define HOST_SIM_SOC_PWM_OUTPUTS_H

#include "host_sim/devices/pwm.h"

/* A model's answers for one of its outputs (channel: the model's own index). */
struct hs_pwm_source_ops {
	double (*low_fraction)(const void *ctx, unsigned channel);
	double (*frequency)(const void *ctx, unsigned channel);
};

/* Enters the model behind out (ops NULL: the output is gone, held low). */
void hs_pwm_output_attach(enum hs_pwm_output out, const struct hs_pwm_source_ops *ops,
			  const void *ctx, unsigned channel);
/* Tells out's peer that its low fraction changed. */
void hs_pwm_output_changed(enum hs_pwm_output out);

#endif /* HOST_SIM_SOC_PWM_OUTPUTS_H */
