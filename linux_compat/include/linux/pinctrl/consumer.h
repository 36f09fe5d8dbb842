/*
 * linux/pinctrl/consumer.h — pin control as a kernel built without
 * CONFIG_PINCTRL has it (Linux 6.1's include/linux/pinctrl/consumer.h, its
 * !CONFIG_PINCTRL branch): every lookup succeeds with a handle of NULL and
 * selecting a state does nothing (0).  The AM1808's pin multiplexing is what
 * the board code set at boot (SYSCFG's PINMUX registers), so a driver that
 * switches a pin between functions at run time (GPIO and UART on an EV3
 * input port) gets no switch: say so in its port.
 */
#ifndef _LINUX_PINCTRL_CONSUMER_H
#define _LINUX_PINCTRL_CONSUMER_H

#include <linux/device.h>
#include <linux/err.h>

struct pinctrl;
struct pinctrl_state;

#define PINCTRL_STATE_DEFAULT	"default"
#define PINCTRL_STATE_INIT	"init"
#define PINCTRL_STATE_IDLE	"idle"
#define PINCTRL_STATE_SLEEP	"sleep"

static inline struct pinctrl *pinctrl_get(struct device *dev) { return NULL; }
static inline void pinctrl_put(struct pinctrl *p) { }
static inline struct pinctrl *devm_pinctrl_get(struct device *dev) { return NULL; }
static inline void devm_pinctrl_put(struct pinctrl *p) { }
static inline struct pinctrl_state *pinctrl_lookup_state(struct pinctrl *p, const char *name)
{
	return NULL;
}
static inline int pinctrl_select_state(struct pinctrl *p, struct pinctrl_state *s) { return 0; }
static inline struct pinctrl *pinctrl_get_select(struct device *dev, const char *name) { return NULL; }
static inline struct pinctrl *pinctrl_get_select_default(struct device *dev) { return NULL; }
static inline struct pinctrl *devm_pinctrl_get_select(struct device *dev, const char *name) { return NULL; }
static inline struct pinctrl *devm_pinctrl_get_select_default(struct device *dev) { return NULL; }
static inline int pinctrl_pm_select_default_state(struct device *dev) { return 0; }
static inline int pinctrl_pm_select_sleep_state(struct device *dev) { return 0; }
static inline int pinctrl_pm_select_idle_state(struct device *dev) { return 0; }

#endif /* _LINUX_PINCTRL_CONSUMER_H */
