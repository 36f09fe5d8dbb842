/*
 * gpiolib.c — GPIO descriptors and the board's lookup tables
 * (linux/gpio/consumer.h and linux/gpio/machine.h state the contract), after
 * Linux 6.1's drivers/gpio/gpiolib.c and gpiolib-devres.c, over the machine's
 * integer GPIOs: one descriptor per pin, claimed through gpio_request so
 * that gpiod and legacy users see each other's claims.
 */
#include <linux/gpio/consumer.h>
#include <linux/gpio/machine.h>
#include <linux/gpio.h>
#include <linux/device.h>
#include <linux/errno.h>
#include <linux/kernel.h>
#include <linux/mutex.h>
#include <linux/overflow.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>

#define DAVINCI_GPIO_CHIP	"davinci_gpio"

#define FLAG_REQUESTED		BIT(0)
#define FLAG_ACTIVE_LOW		BIT(1)
#define FLAG_OPEN_DRAIN		BIT(2)

struct gpio_desc {
	unsigned long flags;
	const char *label;      /* its consumer (kstrdup'd by gpiod_set_consumer_name) */
	bool label_owned;
};

static struct gpio_desc descs[ARCH_NR_GPIOS];
static DEFINE_MUTEX(lookup_lock);
static LIST_HEAD(lookup_tables);

/* The pin number of desc. */
static unsigned int desc_pin(const struct gpio_desc *desc)
{
	return (unsigned int)(desc - descs);
}

/* Whether calls should act on desc: NULL (an absent optional line) quietly
 * not, an error pointer not with a warning (gpiolib.c's validate_desc). */
static bool desc_valid(const struct gpio_desc *desc, const char *func)
{
	if (!desc)
		return false;
	if (IS_ERR(desc)) {
		pr_warn("%s: invalid GPIO (errorpointer)\n", func);
		return false;
	}
	return true;
}

void gpiod_add_lookup_table(struct gpiod_lookup_table *table)
{
	might_sleep();
	mutex_lock(&lookup_lock);
	list_add_tail(&table->list, &lookup_tables);
	mutex_unlock(&lookup_lock);
}

void gpiod_add_lookup_tables(struct gpiod_lookup_table **tables, size_t n)
{
	size_t i;

	for (i = 0; i < n; i++)
		gpiod_add_lookup_table(tables[i]);
}

void gpiod_remove_lookup_table(struct gpiod_lookup_table *table)
{
	might_sleep();
	if (!table)
		return;
	mutex_lock(&lookup_lock);
	list_del(&table->list);
	mutex_unlock(&lookup_lock);
}

/* The table for dev (by name; a table without dev_id serves calls without a
 * device), or NULL.  Lookup lock held. */
static struct gpiod_lookup_table *find_table(struct device *dev)
{
	const char *dev_id = dev ? dev_name(dev) : NULL;
	struct gpiod_lookup_table *table;

	list_for_each_entry(table, &lookup_tables, list) {
		if (table->dev_id && dev_id) {
			if (!strcmp(table->dev_id, dev_id))
				return table;
		} else if (dev_id == table->dev_id) {
			return table;
		}
	}
	return NULL;
}

/* The line the tables give dev for (con_id, idx), with its lookup flags:
 * ERR_PTR(-ENOENT), -EPROBE_DEFER (unknown chip) or -EINVAL (beyond it). */
static struct gpio_desc *find_desc(struct device *dev, const char *con_id, unsigned int idx,
				   unsigned long *lflags)
{
	struct gpiod_lookup_table *table;
	struct gpiod_lookup *p;
	struct gpio_desc *desc = ERR_PTR(-ENOENT);

	mutex_lock(&lookup_lock);
	table = find_table(dev);
	for (p = table ? table->table : NULL; p && p->key; p++) {
		if (p->idx != idx)
			continue;
		if (p->con_id && (!con_id || strcmp(p->con_id, con_id)))
			continue;
		if (strcmp(p->key, DAVINCI_GPIO_CHIP)) {
			dev_warn(dev, "cannot find GPIO chip %s, deferring\n", p->key);
			desc = ERR_PTR(-EPROBE_DEFER);
		} else if (p->chip_hwnum >= ARCH_NR_GPIOS) {
			dev_err(dev, "requested GPIO %u (%u) is out of range [0..%u] for chip %s\n", idx,
				p->chip_hwnum, ARCH_NR_GPIOS - 1, p->key);
			desc = ERR_PTR(-EINVAL);
		} else {
			desc = &descs[p->chip_hwnum];
			*lflags = p->flags;
		}
		break;
	}
	mutex_unlock(&lookup_lock);
	return desc;
}

int gpiod_count(struct device *dev, const char *con_id)
{
	struct gpiod_lookup_table *table;
	struct gpiod_lookup *p;
	int count = 0;

	might_sleep();
	mutex_lock(&lookup_lock);
	table = find_table(dev);
	for (p = table ? table->table : NULL; p && p->key; p++)
		if ((con_id && p->con_id && !strcmp(con_id, p->con_id)) || (!con_id && !p->con_id))
			count++;
	mutex_unlock(&lookup_lock);
	return count ? count : -ENOENT;
}

/* Drives the line's physical level, open drain by releasing it for high. */
static void set_raw(struct gpio_desc *desc, int value)
{
	unsigned int pin = desc_pin(desc);

	if (desc->flags & FLAG_OPEN_DRAIN) {
		if (value)
			gpio_direction_input(pin);
		else
			gpio_direction_output(pin, 0);
		return;
	}
	gpio_set_value(pin, value ? 1 : 0);
}

int gpiod_direction_input(struct gpio_desc *desc)
{
	if (!desc_valid(desc, __func__))
		return -EINVAL;
	return gpio_direction_input(desc_pin(desc));
}

int gpiod_direction_output_raw(struct gpio_desc *desc, int value)
{
	if (!desc_valid(desc, __func__))
		return -EINVAL;
	if ((desc->flags & FLAG_OPEN_DRAIN) && value)
		return gpio_direction_input(desc_pin(desc));
	return gpio_direction_output(desc_pin(desc), value ? 1 : 0);
}

int gpiod_direction_output(struct gpio_desc *desc, int value)
{
	if (!desc_valid(desc, __func__))
		return -EINVAL;
	if (desc->flags & FLAG_ACTIVE_LOW)
		value = !value;
	return gpiod_direction_output_raw(desc, value);
}

int gpiod_get_direction(struct gpio_desc *desc)
{
	if (!desc_valid(desc, __func__))
		return -EINVAL;
	return gpio_get_direction(desc_pin(desc)) ? GPIO_LINE_DIRECTION_IN : GPIO_LINE_DIRECTION_OUT;
}

int gpiod_get_raw_value(const struct gpio_desc *desc)
{
	if (!desc_valid(desc, __func__))
		return 0;
	return gpio_get_value(desc_pin(desc)) ? 1 : 0;
}

int gpiod_get_value(const struct gpio_desc *desc)
{
	int value;

	if (!desc_valid(desc, __func__))
		return 0;
	value = gpiod_get_raw_value(desc);
	return (desc->flags & FLAG_ACTIVE_LOW) ? !value : value;
}

void gpiod_set_raw_value(struct gpio_desc *desc, int value)
{
	if (desc_valid(desc, __func__))
		set_raw(desc, value);
}

void gpiod_set_value(struct gpio_desc *desc, int value)
{
	if (!desc_valid(desc, __func__))
		return;
	if (desc->flags & FLAG_ACTIVE_LOW)
		value = !value;
	set_raw(desc, value);
}

int gpiod_get_value_cansleep(const struct gpio_desc *desc)
{
	might_sleep();
	return gpiod_get_value(desc);
}

void gpiod_set_value_cansleep(struct gpio_desc *desc, int value)
{
	might_sleep();
	gpiod_set_value(desc, value);
}

int gpiod_get_raw_value_cansleep(const struct gpio_desc *desc)
{
	might_sleep();
	return gpiod_get_raw_value(desc);
}

void gpiod_set_raw_value_cansleep(struct gpio_desc *desc, int value)
{
	might_sleep();
	gpiod_set_raw_value(desc, value);
}

int gpiod_cansleep(const struct gpio_desc *desc)
{
	return 0;
}

int gpiod_is_active_low(const struct gpio_desc *desc)
{
	return desc_valid(desc, __func__) && (desc->flags & FLAG_ACTIVE_LOW);
}

void gpiod_toggle_active_low(struct gpio_desc *desc)
{
	if (desc_valid(desc, __func__))
		desc->flags ^= FLAG_ACTIVE_LOW;
}

int gpiod_set_consumer_name(struct gpio_desc *desc, const char *name)
{
	char *copy = NULL;

	if (!desc_valid(desc, __func__))
		return desc ? -EINVAL : 0;
	if (name) {
		copy = kstrdup(name, GFP_KERNEL);
		if (!copy)
			return -ENOMEM;
	}
	if (desc->label_owned)
		kfree(desc->label);
	desc->label = copy;
	desc->label_owned = true;
	return 0;
}

int gpiod_to_irq(const struct gpio_desc *desc)
{
	if (!desc_valid(desc, __func__))
		return -EINVAL;
	return gpio_to_irq(desc_pin(desc));
}

int desc_to_gpio(const struct gpio_desc *desc)
{
	return desc && !IS_ERR(desc) ? (int)desc_pin(desc) : -EINVAL;
}

struct gpio_desc *gpio_to_desc(unsigned int gpio)
{
	return gpio < ARCH_NR_GPIOS ? &descs[gpio] : NULL;
}

/* Claims desc for label: 0 or -EBUSY (claimed by gpiod or gpio_request). */
static int desc_request(struct gpio_desc *desc, const char *label)
{
	int ret;

	if (desc->flags & FLAG_REQUESTED)
		return -EBUSY;
	ret = gpio_request(desc_pin(desc), label);
	if (ret)
		return ret;
	desc->flags = FLAG_REQUESTED;
	desc->label = label;
	desc->label_owned = false;
	return 0;
}

struct gpio_desc *gpiod_get_index(struct device *dev, const char *con_id, unsigned int idx,
				  enum gpiod_flags flags)
{
	unsigned long lflags = GPIO_LOOKUP_FLAGS_DEFAULT;
	struct gpio_desc *desc;
	const char *label = con_id ? con_id : (dev ? dev_name(dev) : "?");
	int ret;

	might_sleep();
	desc = find_desc(dev, con_id, idx, &lflags);
	if (IS_ERR(desc))
		return desc;
	ret = desc_request(desc, label);
	if (ret == -EBUSY && (flags & GPIOD_FLAGS_BIT_NONEXCLUSIVE) && (desc->flags & FLAG_REQUESTED)) {
		dev_info(dev, "nonexclusive access to GPIO for %s\n", con_id ? con_id : "?");
		return desc;
	}
	if (ret)
		return ERR_PTR(ret);
	if (lflags & GPIO_ACTIVE_LOW)
		desc->flags |= FLAG_ACTIVE_LOW;
	if ((lflags & GPIO_OPEN_DRAIN) || (flags & GPIOD_FLAGS_BIT_OPEN_DRAIN))
		desc->flags |= FLAG_OPEN_DRAIN;
	if (flags & GPIOD_FLAGS_BIT_DIR_SET) {
		if (flags & GPIOD_FLAGS_BIT_DIR_OUT)
			ret = gpiod_direction_output(desc, !!(flags & GPIOD_FLAGS_BIT_DIR_VAL));
		else
			ret = gpiod_direction_input(desc);
		if (ret) {
			gpiod_put(desc);
			return ERR_PTR(ret);
		}
	}
	return desc;
}

struct gpio_desc *gpiod_get(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	return gpiod_get_index(dev, con_id, 0, flags);
}

struct gpio_desc *gpiod_get_index_optional(struct device *dev, const char *con_id, unsigned int idx,
					   enum gpiod_flags flags)
{
	struct gpio_desc *desc = gpiod_get_index(dev, con_id, idx, flags);

	return PTR_ERR_OR_ZERO(desc) == -ENOENT ? NULL : desc;
}

struct gpio_desc *gpiod_get_optional(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	return gpiod_get_index_optional(dev, con_id, 0, flags);
}

void gpiod_put(struct gpio_desc *desc)
{
	might_sleep();
	if (!desc_valid(desc, __func__))
		return;
	if (!(desc->flags & FLAG_REQUESTED)) {
		WARN(1, "gpiod_put: GPIO %u was not requested", desc_pin(desc));
		return;
	}
	if (desc->label_owned)
		kfree(desc->label);
	desc->flags = 0;
	desc->label = NULL;
	desc->label_owned = false;
	gpio_free(desc_pin(desc));
}

static void devm_gpiod_release(struct device *dev, void *res)
{
	gpiod_put(*(struct gpio_desc **)res);
}

static int devm_gpiod_match(struct device *dev, void *res, void *data)
{
	return *(struct gpio_desc **)res == data;
}

struct gpio_desc *devm_gpiod_get_index(struct device *dev, const char *con_id, unsigned int idx,
				       enum gpiod_flags flags)
{
	struct gpio_desc **dr, *desc;

	dr = devres_alloc(devm_gpiod_release, sizeof(*dr), GFP_KERNEL);
	if (!dr)
		return ERR_PTR(-ENOMEM);
	desc = gpiod_get_index(dev, con_id, idx, flags);
	if (IS_ERR(desc)) {
		devres_free(dr);
		return desc;
	}
	*dr = desc;
	devres_add(dev, dr);
	return desc;
}

struct gpio_desc *devm_gpiod_get(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	return devm_gpiod_get_index(dev, con_id, 0, flags);
}

struct gpio_desc *devm_gpiod_get_index_optional(struct device *dev, const char *con_id, unsigned int index,
						enum gpiod_flags flags)
{
	struct gpio_desc *desc = devm_gpiod_get_index(dev, con_id, index, flags);

	return PTR_ERR_OR_ZERO(desc) == -ENOENT ? NULL : desc;
}

struct gpio_desc *devm_gpiod_get_optional(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	return devm_gpiod_get_index_optional(dev, con_id, 0, flags);
}

void devm_gpiod_put(struct device *dev, struct gpio_desc *desc)
{
	if (devres_release(dev, devm_gpiod_release, devm_gpiod_match, desc))
		WARN(1, "devm_gpiod_put(%s): not a line %s manages", dev_name(dev), dev_name(dev));
}

void lx_gpiolib_boot(void)
{
	memset(descs, 0, sizeof(descs));
	mutex_init(&lookup_lock);
	INIT_LIST_HEAD(&lookup_tables);
}

/* ---- arrays of lines (Linux 6.1's gpiod_get_array, without its fast path) ---- */

struct gpio_descs *gpiod_get_array(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	struct gpio_descs *array;
	int count = gpiod_count(dev, con_id);
	int i;

	if (count < 0)
		return ERR_PTR(count);
	array = kzalloc(struct_size(array, desc, count), GFP_KERNEL);
	if (!array)
		return ERR_PTR(-ENOMEM);
	for (i = 0; i < count; i++) {
		struct gpio_desc *desc = gpiod_get_index(dev, con_id, (unsigned int)i, flags);

		if (IS_ERR(desc)) {
			gpiod_put_array(array);
			return ERR_CAST(desc);
		}
		array->desc[array->ndescs++] = desc;
	}
	return array;
}

struct gpio_descs *gpiod_get_array_optional(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	struct gpio_descs *array = gpiod_get_array(dev, con_id, flags);

	return PTR_ERR_OR_ZERO(array) == -ENOENT ? NULL : array;
}

void gpiod_put_array(struct gpio_descs *array)
{
	unsigned int i;

	if (!array)
		return;
	for (i = 0; i < array->ndescs; i++)
		gpiod_put(array->desc[i]);
	kfree(array);
}

/* devm's action: gives an array's lines back. */
static void devm_gpiod_put_array_action(void *array)
{
	gpiod_put_array(array);
}

struct gpio_descs *devm_gpiod_get_array(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	struct gpio_descs *array = gpiod_get_array(dev, con_id, flags);
	int ret;

	if (IS_ERR(array))
		return array;
	ret = devm_add_action_or_reset(dev, devm_gpiod_put_array_action, array);
	return ret ? ERR_PTR(ret) : array;
}

struct gpio_descs *devm_gpiod_get_array_optional(struct device *dev, const char *con_id, enum gpiod_flags flags)
{
	struct gpio_descs *array = devm_gpiod_get_array(dev, con_id, flags);

	return PTR_ERR_OR_ZERO(array) == -ENOENT ? NULL : array;
}
