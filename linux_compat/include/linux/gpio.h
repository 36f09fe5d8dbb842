/*
 * linux/gpio.h — the legacy integer GPIO API (asm/gpio.h, mach/gpio.h) and
 * the request-with-flags helpers.
 */
#ifndef __LINUX_GPIO_H
#define __LINUX_GPIO_H

#include <linux/types.h>
#include <linux/errno.h>
#include <asm/gpio.h>

#define GPIOF_DIR_OUT		(0 << 0)
#define GPIOF_DIR_IN		(1 << 0)
#define GPIOF_INIT_LOW		(0 << 1)
#define GPIOF_INIT_HIGH		(1 << 1)
#define GPIOF_IN		(GPIOF_DIR_IN)
#define GPIOF_OUT_INIT_LOW	(GPIOF_DIR_OUT | GPIOF_INIT_LOW)
#define GPIOF_OUT_INIT_HIGH	(GPIOF_DIR_OUT | GPIOF_INIT_HIGH)
#define GPIOF_ACTIVE_LOW	(1 << 2)
#define GPIOF_OPEN_DRAIN	(1 << 3)
#define GPIOF_OPEN_SOURCE	(1 << 4)
#define GPIOF_EXPORT		(1 << 5)

struct gpio {
	unsigned int gpio;
	unsigned long flags;
	const char *label;
};

/* gpio_request, then the direction and initial level flags say; undone on failure. */
int gpio_request_one(unsigned int gpio, unsigned long flags, const char *label);
/* gpio_request_one for each of num pins; all or none are claimed. */
int gpio_request_array(const struct gpio *array, size_t num);
/* gpio_free for each of num pins. */
void gpio_free_array(const struct gpio *array, size_t num);

/* sysfs export: there is no sysfs, so there is nothing to do. */
static inline int gpio_export(unsigned int gpio, bool direction_may_change)
{
	(void)gpio;
	(void)direction_may_change;
	return 0;
}

static inline void gpio_unexport(unsigned int gpio)
{
	(void)gpio;
}

#endif /* __LINUX_GPIO_H */
