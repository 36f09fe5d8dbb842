/*
 * linux_compat/ev3rt_gpio.h — EV3RT's GPIO driver interface (gpio_dri), served
 * by linux_compat's DaVinci GPIO, so that the EV3RT drivers a firmware keeps
 * beside ev3lx's (Bluetooth, brick) share one Linux layer with them.  The
 * names, argument types and pin numbers are EV3RT's (ev3rt-git/ev3rt-hrp2,
 * target/ev3_gcc/drivers/gpio/include/gpio_dri.h): a GPIO is bank * 16 + pin,
 * Linux's GPIO_TO_PIN numbering, and the functions after the last GPIO name
 * pin functions.  gpio_direction_output and gpio_direction_input are Linux's
 * own (linux/gpio.h), which EV3RT's callers reach with the same arguments.
 */
#ifndef _LINUX_COMPAT_EV3RT_GPIO_H
#define _LINUX_COMPAT_EV3RT_GPIO_H

#include <linux/types.h>

/* EV3RT's numbers of the pin functions setup_pinmux knows besides GPIOs. */
#define EV3RT_PIN_UART2_TXD	164
#define EV3RT_PIN_UART2_RXD	165
#define EV3RT_PIN_UART2_CTS	166
#define EV3RT_PIN_UART2_RTS	167
#define EV3RT_PIN_ECAP2_APWM2	168

/* Muxes pin (a GPIO, or one of the functions above) to its pad; an unknown
 * pin is reported and left alone, as EV3RT's does. */
void setup_pinmux(uint32_t pin);
/* The level of GPIO pin (0 or 1): gpio_get_value as a function, which EV3RT's
 * drivers link against (Linux's is inline). */
int gpio_get_value(unsigned int gpio);

#endif /* _LINUX_COMPAT_EV3RT_GPIO_H */
