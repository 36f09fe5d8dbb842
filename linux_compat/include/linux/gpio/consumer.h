/*
 * linux/gpio/consumer.h — GPIO descriptors (Linux 6.1's gpiolib consumer
 * interface), implemented by linux_compat/src/gpiolib.c over the machine's
 * integer GPIOs (mach/gpio.h: DaVinci's 144 pins as one chip, "davinci_gpio").
 *
 * gpiod_get(dev, con_id, flags) finds the line in the board's lookup tables
 * (linux/gpio/machine.h) for dev_name(dev) and con_id, claims it
 * (-EBUSY if claimed, through gpiod or gpio_request), applies flags
 * (direction and initial logical value) and returns its descriptor:
 * ERR_PTR(-ENOENT) if no table names it (the _optional forms return NULL
 * then), -EPROBE_DEFER if the table names an unknown chip.  Values are
 * logical: GPIO_ACTIVE_LOW inverts them (the _raw forms do not); an open-drain
 * line is driven low or released as an input.  A NULL descriptor (an absent
 * optional line) is ignored by every call; an error pointer is warned about.
 * Nothing here sleeps (the DaVinci banks are memory-mapped): gpiod_cansleep
 * is 0 and the _cansleep forms only check that the caller may sleep.
 */
#ifndef __LINUX_GPIO_CONSUMER_H
#define __LINUX_GPIO_CONSUMER_H

#include <linux/bits.h>
#include <linux/err.h>
#include <linux/types.h>

struct device;
struct gpio_desc;

#define GPIOD_FLAGS_BIT_DIR_SET		BIT(0)
#define GPIOD_FLAGS_BIT_DIR_OUT		BIT(1)
#define GPIOD_FLAGS_BIT_DIR_VAL		BIT(2)
#define GPIOD_FLAGS_BIT_OPEN_DRAIN	BIT(3)
#define GPIOD_FLAGS_BIT_NONEXCLUSIVE	BIT(4)

enum gpiod_flags {
	GPIOD_ASIS	= 0,
	GPIOD_IN	= GPIOD_FLAGS_BIT_DIR_SET,
	GPIOD_OUT_LOW	= GPIOD_FLAGS_BIT_DIR_SET | GPIOD_FLAGS_BIT_DIR_OUT,
	GPIOD_OUT_HIGH	= GPIOD_FLAGS_BIT_DIR_SET | GPIOD_FLAGS_BIT_DIR_OUT | GPIOD_FLAGS_BIT_DIR_VAL,
	GPIOD_OUT_LOW_OPEN_DRAIN	= GPIOD_OUT_LOW | GPIOD_FLAGS_BIT_OPEN_DRAIN,
	GPIOD_OUT_HIGH_OPEN_DRAIN	= GPIOD_OUT_HIGH | GPIOD_FLAGS_BIT_OPEN_DRAIN,
};

#define GPIO_LINE_DIRECTION_IN	1
#define GPIO_LINE_DIRECTION_OUT	0

/* Process context (they may sleep in Linux). */
struct gpio_desc *__must_check gpiod_get(struct device *dev, const char *con_id, enum gpiod_flags flags);
struct gpio_desc *__must_check gpiod_get_index(struct device *dev, const char *con_id, unsigned int idx,
					       enum gpiod_flags flags);
struct gpio_desc *__must_check gpiod_get_optional(struct device *dev, const char *con_id,
						  enum gpiod_flags flags);
struct gpio_desc *__must_check gpiod_get_index_optional(struct device *dev, const char *con_id,
							unsigned int idx, enum gpiod_flags flags);
/* The number of lines the tables give dev for con_id, or -ENOENT. */
int gpiod_count(struct device *dev, const char *con_id);
/* Releases a line from gpiod_get. */
void gpiod_put(struct gpio_desc *desc);

/* As gpiod_get*, released when dev's driver unbinds (devres). */
struct gpio_desc *__must_check devm_gpiod_get(struct device *dev, const char *con_id, enum gpiod_flags flags);
struct gpio_desc *__must_check devm_gpiod_get_index(struct device *dev, const char *con_id, unsigned int idx,
						    enum gpiod_flags flags);
struct gpio_desc *__must_check devm_gpiod_get_optional(struct device *dev, const char *con_id,
						       enum gpiod_flags flags);
struct gpio_desc *__must_check devm_gpiod_get_index_optional(struct device *dev, const char *con_id,
							     unsigned int index, enum gpiod_flags flags);
/* Releases a devm_gpiod_get line now. */
void devm_gpiod_put(struct device *dev, struct gpio_desc *desc);

/* All of con_id's lines in index order (Linux's struct gpio_descs; the
 * fast-path info of Linux's array is not kept: values go line by line). */
struct gpio_descs {
	struct gpio_array *info;        /* always NULL here */
	unsigned int ndescs;
	struct gpio_desc *desc[];
};

/* Every line the tables give dev for con_id: the array, or ERR_PTR(-ENOENT)
 * when there is none (or a line's error; those taken are put back). */
struct gpio_descs *__must_check gpiod_get_array(struct device *dev, const char *con_id, enum gpiod_flags flags);
/* As gpiod_get_array, NULL instead of -ENOENT. */
struct gpio_descs *__must_check gpiod_get_array_optional(struct device *dev, const char *con_id,
							 enum gpiod_flags flags);
/* Puts every line back and frees the array. */
void gpiod_put_array(struct gpio_descs *descs);
/* As gpiod_get_array, put back when dev's driver unbinds (devres). */
struct gpio_descs *__must_check devm_gpiod_get_array(struct device *dev, const char *con_id,
						     enum gpiod_flags flags);
struct gpio_descs *__must_check devm_gpiod_get_array_optional(struct device *dev, const char *con_id,
							      enum gpiod_flags flags);

/* GPIO_LINE_DIRECTION_IN / _OUT, or -EINVAL. */
int gpiod_get_direction(struct gpio_desc *desc);
/* 0 or -EINVAL; value is logical (raw: physical).  Any context. */
int gpiod_direction_input(struct gpio_desc *desc);
int gpiod_direction_output(struct gpio_desc *desc, int value);
int gpiod_direction_output_raw(struct gpio_desc *desc, int value);

/* Line values; any context. */
int gpiod_get_value(const struct gpio_desc *desc);
void gpiod_set_value(struct gpio_desc *desc, int value);
int gpiod_get_raw_value(const struct gpio_desc *desc);
void gpiod_set_raw_value(struct gpio_desc *desc, int value);
/* The same from process context only (Linux lets the chip sleep there). */
int gpiod_get_value_cansleep(const struct gpio_desc *desc);
void gpiod_set_value_cansleep(struct gpio_desc *desc, int value);
int gpiod_get_raw_value_cansleep(const struct gpio_desc *desc);
void gpiod_set_raw_value_cansleep(struct gpio_desc *desc, int value);

/* 0: DaVinci's banks never sleep. */
int gpiod_cansleep(const struct gpio_desc *desc);
/* Whether values are inverted (GPIO_ACTIVE_LOW). */
int gpiod_is_active_low(const struct gpio_desc *desc);
/* Inverts the line's active-low setting. */
void gpiod_toggle_active_low(struct gpio_desc *desc);
/* Renames the line's consumer: 0 or -ENOMEM. */
int gpiod_set_consumer_name(struct gpio_desc *desc, const char *name);
/* The line's IRQ (mach/gpio.h's gpio_to_irq), or -EINVAL. */
int gpiod_to_irq(const struct gpio_desc *desc);

/* The legacy number of desc (-EINVAL for none), and the descriptor of a number (NULL if invalid). */
int desc_to_gpio(const struct gpio_desc *desc);
struct gpio_desc *gpio_to_desc(unsigned int gpio);

#endif /* __LINUX_GPIO_CONSUMER_H */
