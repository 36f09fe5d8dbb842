/* asm/gpio.h — the legacy GPIO API of the machine (mach/gpio.h). */
#ifndef __ARM_GPIO_H
#define __ARM_GPIO_H

#include <mach/gpio.h>

#endif /* __ARM_GPIO_H */
