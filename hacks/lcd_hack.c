/*
 * lcd_hack.c — st7586fb on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: the board's
 * part (SPI1 as bus 1 with the display's chip select on GP2_12, the display
 * declared on it with its A0 and RESET GPIOs, as LEGO's board file does) and
 * the module's init and exit
 * (lcd_module.h).  Only Linux headers: the service calls and the
 * configuration fragment are lcd_svc.c.
 */
#define KBUILD_MODNAME "st7586fb"
/* The driver's module_init/exit become plain pointers, called by ours below. */
#define LX_HACK_DRIVER_INIT lcd_driver_init
#define LX_HACK_DRIVER_EXIT lcd_driver_exit

#include "st7586fb.c"

#include "driver_common.h"

#include <linux/fb.h>
#include <linux/platform_data/spi-davinci.h>
#include <mach/spi.h>
#include "lcd_module.h"

#define LCD_SPI_BUS	1
#define LCD_CS_GPIO	GPIO_TO_PIN(2, 12)
#define LCD_A0_GPIO	GPIO_TO_PIN(2, 11)
#define LCD_RESET_GPIO	GPIO_TO_PIN(5, 0)

/* The EV3's wiring (LEGO's board file): mode 3, 10 MHz, chip-select delays of 10 clocks. */
static const int lcd_cs_gpios[] = { LCD_CS_GPIO };
static struct davinci_spi_config lcd_spi_cfg = { .c2tdelay = 10, .t2cdelay = 10 };
static const struct st7586fb_platform_data lcd_pdata = {
	.a0_gpio = LCD_A0_GPIO,
	.reset_gpio = LCD_RESET_GPIO,
};
static const struct spi_board_info lcd_board_info = {
	.modalias = ST7586FB_MODALIAS,
	.platform_data = &lcd_pdata,
	.controller_data = &lcd_spi_cfg,
	.max_speed_hz = 10000000,
	.bus_num = LCD_SPI_BUS,
	.chip_select = 0,
	.mode = SPI_MODE_3,
};

struct file *lcd_file;		/* /dev/fb0, opened by LCD_FN_INIT */
DEFINE_MUTEX(lcd_hack_mutex);

/* Registers the bus and the display, then loads st7586fb (which probes it). */
static int __init lcd_hack_init(void)
{
	int ret;

	lcd_file = NULL;
	ret = da8xx_register_spi_bus(LCD_SPI_BUS, ARRAY_SIZE(lcd_cs_gpios), lcd_cs_gpios);
	if (!ret)
		ret = spi_register_board_info(&lcd_board_info, 1);
	if (!ret)
		ret = lcd_driver_init();
	if (ret) {
		pr_err("lcd_hack: no display (%d)\n", ret);
		da8xx_unregister_spi_bus(LCD_SPI_BUS);
	}
	return ret;
}
module_init(lcd_hack_init);

/* Closes /dev/fb0 (the calls then answer E_OBJ), unloads st7586fb, removes the bus. */
static void __exit lcd_hack_exit(void)
{
	struct file *file;

	mutex_lock(&lcd_hack_mutex);
	file = lcd_file;
	lcd_file = NULL;
	mutex_unlock(&lcd_hack_mutex);
	lx_dev_close(file);
	lcd_driver_exit();
	da8xx_unregister_spi_bus(LCD_SPI_BUS);
}
module_exit(lcd_hack_exit);
