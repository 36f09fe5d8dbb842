/*
 * lcd_hack.c — st7586fb on the RTOS: the board's part (SPI1 as bus 1 with
 * the display's chip select on GP2_12, the display declared on it with its
 * A0 and RESET GPIOs, as LEGO's board file does), the Linux driver source
 * included byte-for-byte, then its interface as extended service calls
 * (lcd_hack.h) through /dev/fb0's file operations.
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
#include "lcd_hack.h"

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

static struct file *lcd_file;		/* /dev/fb0, opened by LCD_FN_INIT */
static DEFINE_MUTEX(lcd_hack_mutex);

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

/* The open frame buffer, or NULL before LCD_FN_INIT. */
static struct file *lcd_hack_file(void)
{
	return READ_ONCE(lcd_file);
}

/* LCD_FN_INIT: open /dev/fb0 (once), then INIT and START as LEGO's user space does. */
static ER_UINT svc_lcd_init(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	struct file *file;
	long ret;

	if (sns_ctx())
		return E_CTX;
	mutex_lock(&lcd_hack_mutex);
	file = lcd_file;
	if (!file && lx_dev_open("/dev/fb0", O_RDWR, &file))
		file = NULL;
	ret = file ? lx_dev_ioctl(file, FB_ST7586_INIT_DISPLAY, 0) : -ENODEV;
	if (!ret)
		ret = lx_dev_ioctl(file, FB_ST7586_START_DISPLAY, 0);
	if (!ret)
		lcd_file = file;
	else if (file && !lcd_file)
		lx_dev_close(file);
	mutex_unlock(&lcd_hack_mutex);
	return lx_errno_to_er(ret);
}

/* LCD_FN_UPDATE: the caller's frame written to the frame buffer (the driver copies it from user memory). */
static ER_UINT svc_lcd_update(intptr_t frame, intptr_t len, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	struct file *file = lcd_hack_file();
	loff_t pos = 0;
	ssize_t ret;

	if (sns_ctx())
		return E_CTX;
	if (!file)
		return E_OBJ;
	if (len != FB_ST7586_SIZE)
		return E_PAR;
	ret = lx_dev_write(file, (const char __user *)frame, (size_t)len, &pos);
	if (ret < 0)
		return lx_errno_to_er(ret);
	return ret == len ? E_OK : E_MACV;
}

/* LCD_FN_FLUSH: runs a pending deferred update now. */
static ER_UINT svc_lcd_flush(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	struct file *file = lcd_hack_file();
	struct fb_info *info;

	if (sns_ctx())
		return E_CTX;
	if (!file)
		return E_OBJ;
	info = file->private_data;
	flush_delayed_work(&info->deferred_work);
	return E_OK;
}

static const struct rtos_svc_cfg lcd_svcs[] = {
	{ LCD_FN_INIT,   svc_lcd_init,   2048 },
	{ LCD_FN_UPDATE, svc_lcd_update, 1024 },
	{ LCD_FN_FLUSH,  svc_lcd_flush,  1024 },
};

const struct rtos_cfg lcd_hack_cfg = {
	.name = "lcd_hack",
	.svcs = RTOS_TABLE(lcd_svcs),
	.svc_first = LCD_FN_FIRST, .svc_count = LCD_FN_COUNT,
};
