/*
 * pwm_outputs.c — the PWM outputs of eHRPWM1 and eCAP0/1 as one table: the
 * model behind each output (entered by the model) and what it drives (the
 * peer the board connects).
 */
#include "host_sim/devices/pwm.h"
#include "pwm_outputs.h"

static struct {
	const struct hs_pwm_source_ops *ops;
	const void *ctx;
	unsigned channel;
} sources[HS_PWM_OUTPUTS];

static struct hs_pwm_peer peers[HS_PWM_OUTPUTS];

void hs_pwm_output_attach(enum hs_pwm_output out, const struct hs_pwm_source_ops *ops,
			  const void *ctx, unsigned channel)
{
	if ((unsigned)out >= HS_PWM_OUTPUTS)
		return;
	sources[out].ops = ops;
	sources[out].ctx = ctx;
	sources[out].channel = channel;
}

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

/* Low fraction of an output now; 1.0 (held low, as after reset) without its model. */
double hs_pwm_low_fraction(enum hs_pwm_output out)
{
	if ((unsigned)out >= HS_PWM_OUTPUTS || sources[out].ops == NULL)
		return 1.0;
	return sources[out].ops->low_fraction(sources[out].ctx, sources[out].channel);
}

/* PWM frequency of an output now (0 if stopped or without its model). */
double hs_pwm_frequency(enum hs_pwm_output out)
{
	if ((unsigned)out >= HS_PWM_OUTPUTS || sources[out].ops == NULL)
		return 0;
	return sources[out].ops->frequency(sources[out].ctx, sources[out].channel);
}
