/*
 * lms_pins26 — a conformance module as a Linux 2.6.33 DaVinci (AM1808)
 * module was written: the GPIO calls from <asm/gpio.h>, which ARM's 2.6
 * kernels had (arch/arm/include/asm/gpio.h, bringing the machine's
 * <mach/gpio.h>) and today's x86 kernel headers do not, so kbuild against
 * them cannot build it; only the brick's kernel, and ev3lx, can.  It claims
 * an output pin and an input pin (numbers as bank * 16 + bit, module
 * parameters), drives the output, and mirrors the input to the output on
 * request.
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>
#include <asm/gpio.h>

#define   MODULE_NAME   "lms_pins26"

static int OutPin = 3 * 16 + 13;        /* GP3[13] */
static int InPin  = 0 * 16 + 3;         /* GP0[3] */
module_param(OutPin, int, 0);
module_param(InPin, int, 0);

int       Mirrored;

void      PinsMirror(void)
{
  gpio_set_value(OutPin,gpio_get_value(InPin));
  Mirrored++;
}

void      PinsDrive(int Level)
{
  gpio_set_value(OutPin,Level);
}

static int __init ModuleInit(void)
{
  int     Result;

  if (!gpio_is_valid(OutPin) || !gpio_is_valid(InPin))
  {
    return (-EINVAL);
  }
  Result  =  gpio_request(OutPin,MODULE_NAME);
  if (Result == 0)
  {
    Result  =  gpio_request(InPin,MODULE_NAME);
    if (Result == 0)
    {
      gpio_direction_input(InPin);
      gpio_direction_output(OutPin,1);
      printk(KERN_INFO "%s: GP%d[%d] out, GP%d[%d] in\n",MODULE_NAME,OutPin / 16,OutPin % 16,InPin / 16,InPin % 16);
      return (0);
    }
    gpio_free(OutPin);
  }
  return (Result);
}

static void __exit ModuleExit(void)
{
  gpio_direction_input(OutPin);
  gpio_free(InPin);
  gpio_free(OutPin);
}

module_init(ModuleInit);
module_exit(ModuleExit);

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("conformance module: GPIO through <asm/gpio.h>, as 2.6.33's DaVinci kernel had it");
