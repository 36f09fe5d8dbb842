/*
 * linux/pwm.h — the PWM framework (Linux 6.1's include/linux/pwm.h),
 * implemented by linux_compat/src/pwm.c: chips (pwmchip_add,
 * devm_pwmchip_add, pwmchip_remove), consumers found through the board's
 * lookup tables (pwm_add_table; pwm_get, devm_pwm_get, pwm_put) and the
 * atomic state (pwm_apply_state, and pwm_apply_might_sleep, its name since
 * Linux 6.8; pwm_get_state, pwm_init_state, the legacy pwm_config,
 * pwm_enable, pwm_disable).
 *
 * As in Linux: a state needs a period and a duty cycle within it (-EINVAL),
 * applying the state the device has already calls nothing, pwm_get asks the
 * chip's get_state for the hardware's state, a chip that is not there yet
 * defers the consumer's probe (-EPROBE_DEFER), a requested device gives
 * -EBUSY.  pwm_apply_state may sleep (might_sleep reports a call from
 * atomic context); there are no atomic chips.  No sysfs export.
 */
#ifndef __LINUX_PWM_H
#define __LINUX_PWM_H

#include <linux/err.h>
#include <linux/list.h>
#include <linux/mutex.h>
#include <linux/of.h>
#include <linux/types.h>

struct device;
struct pwm_chip;
struct of_phandle_args;

enum pwm_polarity {
	PWM_POLARITY_NORMAL,
	PWM_POLARITY_INVERSED,
};

struct pwm_args {
	u64 period;
	enum pwm_polarity polarity;
};

enum {
	PWMF_REQUESTED = 0,
	PWMF_EXPORTED = 1,
};

struct pwm_state {
	u64 period;
	u64 duty_cycle;
	enum pwm_polarity polarity;
	bool enabled;
	bool usage_power;
};

struct pwm_device {
	const char *label;
	unsigned long flags;
	unsigned int hwpwm;
	unsigned int pwm;
	struct pwm_chip *chip;
	void *chip_data;
	struct pwm_args args;
	struct pwm_state state;
	struct pwm_state last;
};

struct pwm_capture {
	unsigned int period;
	unsigned int duty_cycle;
};

struct pwm_ops {
	int (*request)(struct pwm_chip *chip, struct pwm_device *pwm);
	void (*free)(struct pwm_chip *chip, struct pwm_device *pwm);
	int (*capture)(struct pwm_chip *chip, struct pwm_device *pwm, struct pwm_capture *result,
		       unsigned long timeout);
	int (*apply)(struct pwm_chip *chip, struct pwm_device *pwm, const struct pwm_state *state);
	int (*get_state)(struct pwm_chip *chip, struct pwm_device *pwm, struct pwm_state *state);
	struct module *owner;
};

struct pwm_chip {
	struct device *dev;
	const struct pwm_ops *ops;
	int base;
	unsigned int npwm;
	struct pwm_device *(*of_xlate)(struct pwm_chip *pc, const struct of_phandle_args *args);
	unsigned int of_pwm_n_cells;
	struct list_head list;
	struct pwm_device *pwms;
};

/* A board's lookup entry: PWM index of the chip whose device is named
 * provider serves consumer device dev_id (NULL: any) as con_id (NULL: any),
 * with the default period (ns) and polarity pwm_init_state gives. */
struct pwm_lookup {
	struct list_head list;
	const char *provider;
	unsigned int index;
	const char *dev_id;
	const char *con_id;
	unsigned int period;
	enum pwm_polarity polarity;
	const char *module;
};

#define PWM_LOOKUP_WITH_MODULE(_provider, _index, _dev_id, _con_id, _period, _polarity, _module) \
	{ .provider = _provider, .index = _index, .dev_id = _dev_id, .con_id = _con_id,	\
	  .period = _period, .polarity = _polarity, .module = _module }
#define PWM_LOOKUP(_provider, _index, _dev_id, _con_id, _period, _polarity) \
	PWM_LOOKUP_WITH_MODULE(_provider, _index, _dev_id, _con_id, _period, _polarity, NULL)

/* Adds / removes num entries of a board's lookup table.  Process context. */
void pwm_add_table(struct pwm_lookup *table, size_t num);
void pwm_remove_table(struct pwm_lookup *table, size_t num);

/* Registers chip (dev, ops with apply, npwm > 0): 0, -EINVAL or -ENOMEM.
 * base -1 (or any negative) takes the next free global numbers. */
int pwmchip_add(struct pwm_chip *chip);
/* Unregisters chip; PWM devices still requested from it are reported. */
void pwmchip_remove(struct pwm_chip *chip);
/* pwmchip_add whose pwmchip_remove runs when dev's driver unbinds. */
int devm_pwmchip_add(struct device *dev, struct pwm_chip *chip);

/* The PWM device the lookup tables give dev for con_id, requested: it, or
 * ERR_PTR(-ENODEV) (no entry), -EPROBE_DEFER (its chip is not registered
 * yet), -EBUSY (requested already), or the chip's request error. */
struct pwm_device *pwm_get(struct device *dev, const char *con_id);
/* pwm_get whose pwm_put runs when dev's driver unbinds. */
struct pwm_device *devm_pwm_get(struct device *dev, const char *con_id);
/* Releases a PWM device from pwm_get. */
void pwm_put(struct pwm_device *pwm);

/* Applies state: 0, -EINVAL (NULL, no period, duty above the period), or
 * the chip's error (the device keeps its old state then). */
int pwm_apply_state(struct pwm_device *pwm, const struct pwm_state *state);
static inline int pwm_apply_might_sleep(struct pwm_device *pwm, const struct pwm_state *state)
{
	return pwm_apply_state(pwm, state);
}
/* Sets the state's period and polarity from the lookup's defaults. */
int pwm_adjust_config(struct pwm_device *pwm);

static inline void pwm_get_state(const struct pwm_device *pwm, struct pwm_state *state)
{
	*state = pwm->state;
}
static inline bool pwm_is_enabled(const struct pwm_device *pwm)
{
	return pwm->state.enabled;
}
static inline u64 pwm_get_period(const struct pwm_device *pwm)
{
	return pwm->state.period;
}
static inline u64 pwm_get_duty_cycle(const struct pwm_device *pwm)
{
	return pwm->state.duty_cycle;
}
static inline enum pwm_polarity pwm_get_polarity(const struct pwm_device *pwm)
{
	return pwm->state.polarity;
}
static inline void pwm_get_args(const struct pwm_device *pwm, struct pwm_args *args)
{
	*args = pwm->args;
}
/* The current state with the lookup's period and polarity and duty 0: a
 * starting point for pwm_apply_state. */
static inline void pwm_init_state(const struct pwm_device *pwm, struct pwm_state *state)
{
	struct pwm_args args;

	pwm_get_state(pwm, state);
	pwm_get_args(pwm, &args);
	state->period = args.period;
	state->polarity = args.polarity;
	state->duty_cycle = 0;
	state->usage_power = false;
}
/* duty_cycle = scale-th part of the period (duty_cycle / scale); -EINVAL if above. */
static inline int pwm_set_relative_duty_cycle(struct pwm_state *state, unsigned int duty_cycle,
					      unsigned int scale)
{
	if (!scale || duty_cycle > scale)
		return -EINVAL;
	state->duty_cycle = (state->period * duty_cycle + scale / 2) / scale;
	return 0;
}
static inline int pwm_config(struct pwm_device *pwm, int duty_ns, int period_ns)
{
	struct pwm_state state;

	if (!pwm || duty_ns < 0 || period_ns < 0)
		return -EINVAL;
	pwm_get_state(pwm, &state);
	if (state.duty_cycle == (u64)duty_ns && state.period == (u64)period_ns)
		return 0;
	state.duty_cycle = (u64)duty_ns;
	state.period = (u64)period_ns;
	return pwm_apply_state(pwm, &state);
}
static inline int pwm_enable(struct pwm_device *pwm)
{
	struct pwm_state state;

	if (!pwm)
		return -EINVAL;
	pwm_get_state(pwm, &state);
	if (state.enabled)
		return 0;
	state.enabled = true;
	return pwm_apply_state(pwm, &state);
}
static inline void pwm_disable(struct pwm_device *pwm)
{
	struct pwm_state state;

	if (!pwm)
		return;
	pwm_get_state(pwm, &state);
	if (!state.enabled)
		return;
	state.enabled = false;
	pwm_apply_state(pwm, &state);
}
static inline int pwm_set_chip_data(struct pwm_device *pwm, void *data)
{
	pwm->chip_data = data;
	return 0;
}
static inline void *pwm_get_chip_data(struct pwm_device *pwm)
{
	return pwm->chip_data;
}

#endif /* __LINUX_PWM_H */
