/*
 * pwm.c — the PWM framework (linux/pwm.h states the contract), after Linux
 * 6.1's drivers/pwm/core.c: chips and their global numbers, the board's
 * lookup tables, requesting a device through them, and applying states.
 * Lists change in process context under one mutex.
 */
#include <linux/pwm.h>
#include <linux/bitops.h>
#include <linux/device.h>
#include <linux/err.h>
#include <linux/errno.h>
#include <linux/kernel.h>
#include <linux/mutex.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux_compat/irq.h>
#include <linux_compat/report.h>

static DEFINE_MUTEX(pwm_lock);
static LIST_HEAD(pwm_chips);
static LIST_HEAD(pwm_lookups);

/* The first global number after every registered chip's.  pwm_lock held. */
static int next_base(void)
{
	struct pwm_chip *chip;
	int base = 0;

	list_for_each_entry(chip, &pwm_chips, list)
		if (chip->base + (int)chip->npwm > base)
			base = chip->base + (int)chip->npwm;
	return base;
}

int pwmchip_add(struct pwm_chip *chip)
{
	unsigned int i;

	might_sleep();
	if (!chip || !chip->dev || !chip->ops || !chip->ops->apply || !chip->npwm)
		return -EINVAL;
	chip->pwms = kcalloc(chip->npwm, sizeof(*chip->pwms), GFP_KERNEL);
	if (!chip->pwms)
		return -ENOMEM;
	mutex_lock(&pwm_lock);
	if (chip->base < 0)
		chip->base = next_base();
	for (i = 0; i < chip->npwm; i++) {
		chip->pwms[i].chip = chip;
		chip->pwms[i].hwpwm = i;
		chip->pwms[i].pwm = (unsigned int)chip->base + i;
	}
	list_add_tail(&chip->list, &pwm_chips);
	mutex_unlock(&pwm_lock);
	return 0;
}

void pwmchip_remove(struct pwm_chip *chip)
{
	unsigned int i;

	might_sleep();
	mutex_lock(&pwm_lock);
	for (i = 0; i < chip->npwm; i++)
		if (test_bit(PWMF_REQUESTED, &chip->pwms[i].flags))
			lx_report("pwmchip_remove with a PWM device requested", __FILE__, __LINE__,
				  "%s: pwm %u (%s) is still in use", dev_name(chip->dev), i,
				  chip->pwms[i].label ? chip->pwms[i].label : "?");
	list_del_init(&chip->list);
	mutex_unlock(&pwm_lock);
	kfree(chip->pwms);
	chip->pwms = NULL;
}

/* devres action of devm_pwmchip_add. */
static void devm_pwmchip_remove(void *chip)
{
	pwmchip_remove(chip);
}

int devm_pwmchip_add(struct device *dev, struct pwm_chip *chip)
{
	int ret = pwmchip_add(chip);

	if (ret)
		return ret;
	return devm_add_action_or_reset(dev, devm_pwmchip_remove, chip);
}

void pwm_add_table(struct pwm_lookup *table, size_t num)
{
	might_sleep();
	mutex_lock(&pwm_lock);
	while (num--)
		list_add_tail(&(table++)->list, &pwm_lookups);
	mutex_unlock(&pwm_lock);
}

void pwm_remove_table(struct pwm_lookup *table, size_t num)
{
	might_sleep();
	mutex_lock(&pwm_lock);
	while (num--)
		list_del(&(table++)->list);
	mutex_unlock(&pwm_lock);
}

/* The registered chip whose device is called name, or NULL.  pwm_lock held. */
static struct pwm_chip *chip_by_name(const char *name)
{
	struct pwm_chip *chip;

	list_for_each_entry(chip, &pwm_chips, list)
		if (!strcmp(dev_name(chip->dev), name))
			return chip;
	return NULL;
}

/* The lookup entry that fits dev_id and con_id best (Linux's scoring: the
 * device name counts more than the connection name; an entry with both
 * matching wins at once), or NULL.  pwm_lock held. */
static struct pwm_lookup *best_lookup(const char *dev_id, const char *con_id)
{
	struct pwm_lookup *p, *best = NULL;
	unsigned int match, best_match = 0;

	list_for_each_entry(p, &pwm_lookups, list) {
		match = 0;
		if (p->dev_id) {
			if (!dev_id || strcmp(p->dev_id, dev_id))
				continue;
			match += 2;
		}
		if (p->con_id) {
			if (!con_id || strcmp(p->con_id, con_id))
				continue;
			match += 1;
		}
		if (match > best_match || !best) {
			best = p;
			best_match = match;
			if (match == 3)
				break;
		}
	}
	return best;
}

struct pwm_device *pwm_get(struct device *dev, const char *con_id)
{
	const char *dev_id = dev ? dev_name(dev) : NULL;
	struct pwm_lookup *lookup;
	struct pwm_device *pwm;
	struct pwm_chip *chip;
	int ret;

	might_sleep();
	mutex_lock(&pwm_lock);
	lookup = best_lookup(dev_id, con_id);
	if (!lookup) {
		mutex_unlock(&pwm_lock);
		return ERR_PTR(-ENODEV);
	}
	chip = chip_by_name(lookup->provider);
	if (!chip) {
		mutex_unlock(&pwm_lock);
		return ERR_PTR(-EPROBE_DEFER);
	}
	if (lookup->index >= chip->npwm) {
		mutex_unlock(&pwm_lock);
		pr_err("pwm: %s has no PWM %u\n", lookup->provider, lookup->index);
		return ERR_PTR(-EINVAL);
	}
	pwm = &chip->pwms[lookup->index];
	if (test_bit(PWMF_REQUESTED, &pwm->flags)) {
		mutex_unlock(&pwm_lock);
		return ERR_PTR(-EBUSY);
	}
	if (chip->ops->request) {
		ret = chip->ops->request(chip, pwm);
		if (ret) {
			mutex_unlock(&pwm_lock);
			return ERR_PTR(ret);
		}
	}
	set_bit(PWMF_REQUESTED, &pwm->flags);
	pwm->label = con_id ? con_id : dev_id;
	if (chip->ops->get_state && chip->ops->get_state(chip, pwm, &pwm->state) == 0)
		pwm->last = pwm->state;
	pwm->args.period = lookup->period;
	pwm->args.polarity = lookup->polarity;
	mutex_unlock(&pwm_lock);
	return pwm;
}

void pwm_put(struct pwm_device *pwm)
{
	might_sleep();
	if (!pwm)
		return;
	mutex_lock(&pwm_lock);
	if (!test_and_clear_bit(PWMF_REQUESTED, &pwm->flags)) {
		mutex_unlock(&pwm_lock);
		lx_report("pwm_put of a PWM device not requested", __FILE__, __LINE__, "pwm %u", pwm->pwm);
		return;
	}
	if (pwm->chip->ops->free)
		pwm->chip->ops->free(pwm->chip, pwm);
	pwm->label = NULL;
	mutex_unlock(&pwm_lock);
}

/* devres release of devm_pwm_get. */
static void devm_pwm_release(void *pwm)
{
	pwm_put(pwm);
}

struct pwm_device *devm_pwm_get(struct device *dev, const char *con_id)
{
	struct pwm_device *pwm = pwm_get(dev, con_id);
	int ret;

	if (IS_ERR(pwm))
		return pwm;
	ret = devm_add_action_or_reset(dev, devm_pwm_release, pwm);
	return ret ? ERR_PTR(ret) : pwm;
}

int pwm_apply_state(struct pwm_device *pwm, const struct pwm_state *state)
{
	struct pwm_chip *chip;
	int ret;

	might_sleep();
	if (!pwm || !state || !state->period || state->duty_cycle > state->period)
		return -EINVAL;
	if (state->period == pwm->state.period && state->duty_cycle == pwm->state.duty_cycle &&
	    state->polarity == pwm->state.polarity && state->enabled == pwm->state.enabled &&
	    state->usage_power == pwm->state.usage_power)
		return 0;
	chip = pwm->chip;
	ret = chip->ops->apply(chip, pwm, state);
	if (ret)
		return ret;
	pwm->state = *state;
	return 0;
}

int pwm_adjust_config(struct pwm_device *pwm)
{
	struct pwm_state state;

	if (!pwm)
		return -EINVAL;
	pwm_get_state(pwm, &state);
	state.period = pwm->args.period;
	state.polarity = pwm->args.polarity;
	if (state.duty_cycle > state.period)
		state.duty_cycle = 0;
	return pwm_apply_state(pwm, &state);
}

void lx_pwm_boot(void)
{
	mutex_init(&pwm_lock);
	INIT_LIST_HEAD(&pwm_chips);
	INIT_LIST_HEAD(&pwm_lookups);
}
