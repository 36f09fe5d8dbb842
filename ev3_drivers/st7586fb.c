// SPDX-License-Identifier: GPL-2.0
/*
 * st7586fb.c - frame buffer driver for the LEGO MINDSTORMS EV3 display, a
 * Sitronix ST7586S on SPI (mode 3, up to 10 MHz, write only) with its A0
 * (command/data) and RESET lines on GPIOs (st7586fb.h: the user interface).
 *
 * The frame memory is in the controller's monochrome layout, so a frame is
 * pushed as it is: window columns 0..59 (units of three pixels) and rows
 * 0..127, write RAM, 7680 bytes.  Deferred I/O batches writes through the
 * mapping; write() schedules the same work.  The controller is initialised
 * only on FB_ST7586_INIT_DISPLAY, and frames are not pushed while the
 * buffer is all white until something is drawn or FB_ST7586_START_DISPLAY
 * is issued, so the boot loader's screen stays up until user space takes
 * over - the behaviour LEGO's user space expects.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/delay.h>
#include <linux/fb.h>
#include <linux/gpio.h>
#include <linux/jiffies.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/slab.h>
#include <linux/spi/spi.h>
#include <linux/string.h>
#include <linux/bug.h>
#include <linux/vmalloc.h>

#include "st7586fb.h"

#define ST7586_MAX_SPEED_HZ	10000000

/* ST7586S commands (data sheet, command table). */
#define ST7586_SLEEP_OUT	0x11
#define ST7586_INVERT_OFF	0x20
#define ST7586_DISPLAY_OFF	0x28
#define ST7586_DISPLAY_ON	0x29
#define ST7586_COLUMN_SET	0x2a
#define ST7586_ROW_SET		0x2b
#define ST7586_WRITE_RAM	0x2c
#define ST7586_PARTIAL_AREA	0x30
#define ST7586_SCAN_DIR		0x36
#define ST7586_MONO_ON		0x39
#define ST7586_DATA_FORMAT	0x3a
#define ST7586_DUTY		0xb0
#define ST7586_FIRST_COM	0xb1
#define ST7586_FOSC_DIVIDER	0xb3
#define ST7586_PARTIAL_DISPLAY	0xb4
#define ST7586_NLINE_INV	0xb5
#define ST7586_VOP		0xc0
#define ST7586_BIAS		0xc3
#define ST7586_BOOSTER		0xc4
#define ST7586_VOP_OFFSET	0xc7
#define ST7586_ANALOG_CONTROL	0xd0
#define ST7586_AUTO_READ	0xd7
#define ST7586_OTP_RW		0xe0
#define ST7586_OTP_OUT		0xe1
#define ST7586_OTP_READ		0xe3

/* The RAM is 128 column units of three pixels by 160 rows. */
#define ST7586_RAM_COLUMNS	128
#define ST7586_RAM_ROWS		160

struct st7586fb_par {
	struct spi_device *spi;
	struct fb_info *info;
	const struct st7586fb_platform_data *pdata;
	struct mutex bus_lock;		/* one command sequence on the bus at a time */
	u8 *vmem;
	bool started;
	bool initialised;
	u8 *txbuf;			/* commands and parameters: kmalloc'd, DMA-safe unlike the stack */
};

#define ST7586FB_TXBUF_SIZE	8

/*
 * Sends a command byte, then its parameters (at most ST7586FB_TXBUF_SIZE - 1)
 * as data.  bus_lock held.
 */
static int st7586fb_cmd(struct st7586fb_par *par, u8 cmd, const u8 *params, size_t n)
{
	int ret;

	if (WARN_ON(n > ST7586FB_TXBUF_SIZE - 1))
		return -EINVAL;
	par->txbuf[0] = cmd;
	if (n)
		memcpy(par->txbuf + 1, params, n);
	gpio_set_value(par->pdata->a0_gpio, 0);
	ret = spi_write(par->spi, par->txbuf, 1);
	if (ret || !n)
		return ret;
	gpio_set_value(par->pdata->a0_gpio, 1);
	return spi_write(par->spi, par->txbuf + 1, n);
}

#define st7586fb_cmdv(par, cmd, ...) \
	st7586fb_cmd((par), (cmd), (const u8[]){ __VA_ARGS__ }, sizeof((const u8[]){ __VA_ARGS__ }))

/* Sets the RAM window (columns in units of three pixels) and starts a RAM write.  bus_lock held. */
static int st7586fb_window(struct st7586fb_par *par, u8 col_end, u8 row_end)
{
	int ret;

	ret = st7586fb_cmdv(par, ST7586_COLUMN_SET, 0, 0, 0, col_end);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_ROW_SET, 0, 0, 0, row_end);
	if (!ret)
		ret = st7586fb_cmd(par, ST7586_WRITE_RAM, NULL, 0);
	return ret;
}

/* Pushes the whole frame memory to the panel.  bus_lock held. */
static int st7586fb_push(struct st7586fb_par *par)
{
	int ret;

	ret = st7586fb_window(par, FB_ST7586_LINE_LENGTH - 1, FB_ST7586_HEIGHT - 1);
	if (ret)
		return ret;
	gpio_set_value(par->pdata->a0_gpio, 1);
	return spi_write(par->spi, par->vmem, FB_ST7586_SIZE);
}

/* Resets the controller and runs its initialisation, clears its RAM and shows the frame. */
static int st7586fb_init_display(struct st7586fb_par *par)
{
	const size_t chunk = ST7586_RAM_COLUMNS * 16;
	unsigned int i;
	u8 *zeros;
	int ret;

	zeros = kzalloc(chunk, GFP_KERNEL);
	if (!zeros)
		return -ENOMEM;
	mutex_lock(&par->bus_lock);
	gpio_set_value(par->pdata->reset_gpio, 0);
	msleep(10);
	gpio_set_value(par->pdata->reset_gpio, 1);
	msleep(120);

	ret = st7586fb_cmdv(par, ST7586_AUTO_READ, 0x9f);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_OTP_RW, 0x00);
	if (ret)
		goto out;
	msleep(10);
	ret = st7586fb_cmd(par, ST7586_OTP_READ, NULL, 0);
	if (ret)
		goto out;
	msleep(20);
	ret = st7586fb_cmd(par, ST7586_OTP_OUT, NULL, 0);
	if (!ret)
		ret = st7586fb_cmd(par, ST7586_SLEEP_OUT, NULL, 0);
	if (!ret)
		ret = st7586fb_cmd(par, ST7586_DISPLAY_OFF, NULL, 0);
	if (ret)
		goto out;
	msleep(50);
	ret = st7586fb_cmdv(par, ST7586_VOP_OFFSET, 0x00);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_VOP, 0xe3, 0x00);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_BIAS, 0x02);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_BOOSTER, 0x04);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_ANALOG_CONTROL, 0x1d);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_NLINE_INV, 0x00);
	if (!ret)
		ret = st7586fb_cmd(par, ST7586_MONO_ON, NULL, 0);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_DATA_FORMAT, 0x02);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_SCAN_DIR, 0x00);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_DUTY, 0x7f);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_PARTIAL_DISPLAY, 0xa0);
	if (!ret)
		ret = st7586fb_cmdv(par, ST7586_PARTIAL_AREA, 0x00, 0x00, 0x00, 0x77);
	if (!ret)
		ret = st7586fb_cmd(par, ST7586_INVERT_OFF, NULL, 0);
	/* clear the whole RAM, including the rows and columns the panel does not show */
	if (!ret)
		ret = st7586fb_window(par, ST7586_RAM_COLUMNS - 1, ST7586_RAM_ROWS - 1);
	gpio_set_value(par->pdata->a0_gpio, 1);
	for (i = 0; !ret && i < ST7586_RAM_ROWS / 16; i++)
		ret = spi_write(par->spi, zeros, chunk);
	if (ret)
		goto out;
	msleep(100);
	ret = st7586fb_push(par);
	if (!ret)
		ret = st7586fb_cmd(par, ST7586_DISPLAY_ON, NULL, 0);
	if (!ret)
		par->initialised = true;
out:
	mutex_unlock(&par->bus_lock);
	kfree(zeros);
	if (ret)
		dev_err(&par->spi->dev, "display initialisation failed: %d\n", ret);
	return ret;
}

/* Deferred I/O: the frame goes out whole (7680 bytes), whichever pages were written. */
static void st7586fb_deferred_io(struct fb_info *info, struct list_head *pagelist)
{
	struct st7586fb_par *par = info->par;
	int ret;

	mutex_lock(&par->bus_lock);
	if (!par->started && memchr_inv(par->vmem, 0, FB_ST7586_SIZE))
		par->started = true;
	ret = par->started ? st7586fb_push(par) : 0;
	mutex_unlock(&par->bus_lock);
	if (ret)
		dev_err_ratelimited(info->device, "frame update failed: %d\n", ret);
}

static ssize_t st7586fb_write(struct fb_info *info, const char __user *buf, size_t count, loff_t *ppos)
{
	ssize_t ret = fb_sys_write(info, buf, count, ppos);

	if (ret > 0)
		schedule_delayed_work(&info->deferred_work, info->fbdefio->delay);
	return ret;
}

static int st7586fb_ioctl(struct fb_info *info, unsigned int cmd, unsigned long arg)
{
	struct st7586fb_par *par = info->par;

	switch (cmd) {
	case FB_ST7586_INIT_DISPLAY:
		return st7586fb_init_display(par);
	case FB_ST7586_START_DISPLAY:
		mutex_lock(&par->bus_lock);
		par->started = true;
		mutex_unlock(&par->bus_lock);
		schedule_delayed_work(&info->deferred_work, 0);
		return 0;
	default:
		return -ENOTTY;
	}
}

static const struct fb_ops st7586fb_ops = {
	.owner = THIS_MODULE,
	.fb_read = fb_sys_read,
	.fb_write = st7586fb_write,
	.fb_ioctl = st7586fb_ioctl,
};

static struct fb_deferred_io st7586fb_defio = {
	.delay = HZ * FB_ST7586_REFRESH_MS / 1000,
	.deferred_io = st7586fb_deferred_io,
};

static void st7586fb_fill_info(struct fb_info *info, u8 *vmem)
{
	info->screen_buffer = (char *)vmem;
	info->screen_size = FB_ST7586_SIZE;
	info->flags = FBINFO_VIRTFB;
	strscpy(info->fix.id, "ST7586", sizeof(info->fix.id));
	info->fix.type = FB_TYPE_PACKED_PIXELS;
	info->fix.visual = FB_VISUAL_MONO10;
	info->fix.line_length = FB_ST7586_LINE_LENGTH;
	info->fix.smem_len = FB_ST7586_SIZE;
	info->fix.accel = FB_ACCEL_NONE;
	info->var.xres = FB_ST7586_WIDTH;
	info->var.yres = FB_ST7586_HEIGHT;
	info->var.xres_virtual = FB_ST7586_WIDTH;
	info->var.yres_virtual = FB_ST7586_HEIGHT;
	/* three pixels a byte is no standard depth: nonstd says so, bpp is the nearest (LEGO's too) */
	info->var.bits_per_pixel = 2;
	info->var.nonstd = 1;
	info->var.grayscale = 1;
	info->var.activate = FB_ACTIVATE_NOW;
}

static int st7586fb_probe(struct spi_device *spi)
{
	const struct st7586fb_platform_data *pdata = dev_get_platdata(&spi->dev);
	struct st7586fb_par *par;
	struct fb_info *info;
	u8 *vmem;
	int ret;

	if (!pdata) {
		dev_err(&spi->dev, "no platform data (A0 and RESET GPIOs)\n");
		return -EINVAL;
	}
	spi->mode = SPI_MODE_3;
	spi->bits_per_word = 8;
	if (!spi->max_speed_hz || spi->max_speed_hz > ST7586_MAX_SPEED_HZ)
		spi->max_speed_hz = ST7586_MAX_SPEED_HZ;
	ret = spi_setup(spi);
	if (ret)
		return ret;
	ret = gpio_request_one(pdata->a0_gpio, GPIOF_OUT_INIT_LOW, "st7586 a0");
	if (ret)
		return ret;
	ret = gpio_request_one(pdata->reset_gpio, GPIOF_OUT_INIT_HIGH, "st7586 reset");
	if (ret)
		goto err_a0;

	ret = -ENOMEM;
	vmem = vzalloc(PAGE_ALIGN(FB_ST7586_SIZE));
	if (!vmem)
		goto err_reset;
	info = framebuffer_alloc(sizeof(*par), &spi->dev);
	if (!info)
		goto err_vmem;
	par = info->par;
	par->txbuf = kmalloc(ST7586FB_TXBUF_SIZE, GFP_KERNEL);
	if (!par->txbuf)
		goto err_info;
	par->spi = spi;
	par->info = info;
	par->pdata = pdata;
	par->vmem = vmem;
	mutex_init(&par->bus_lock);
	info->fbops = &st7586fb_ops;
	st7586fb_fill_info(info, vmem);
	info->fbdefio = &st7586fb_defio;
	ret = fb_deferred_io_init(info);
	if (ret)
		goto err_info;
	ret = register_framebuffer(info);
	if (ret)
		goto err_defio;
	spi_set_drvdata(spi, info);
	dev_info(&spi->dev, "fb%d: %dx%d display on SPI at %u Hz\n", info->node, FB_ST7586_WIDTH,
		 FB_ST7586_HEIGHT, spi->max_speed_hz);
	return 0;

err_defio:
	fb_deferred_io_cleanup(info);
err_info:
	kfree(par->txbuf);
	framebuffer_release(info);
err_vmem:
	vfree(vmem);
err_reset:
	gpio_free(pdata->reset_gpio);
err_a0:
	gpio_free(pdata->a0_gpio);
	return ret;
}

static void st7586fb_remove(struct spi_device *spi)
{
	struct fb_info *info = spi_get_drvdata(spi);
	struct st7586fb_par *par = info->par;
	const struct st7586fb_platform_data *pdata = par->pdata;
	u8 *vmem = par->vmem;

	unregister_framebuffer(info);
	fb_deferred_io_cleanup(info);
	kfree(par->txbuf);
	framebuffer_release(info);
	vfree(vmem);
	gpio_free(pdata->reset_gpio);
	gpio_free(pdata->a0_gpio);
}

static const struct spi_device_id st7586fb_ids[] = {
	{ ST7586FB_MODALIAS, 0 },
	{ }
};
MODULE_DEVICE_TABLE(spi, st7586fb_ids);

static struct spi_driver st7586fb_driver = {
	.driver = {
		.name = "st7586fb",
	},
	.id_table = st7586fb_ids,
	.probe = st7586fb_probe,
	.remove = st7586fb_remove,
};
module_spi_driver(st7586fb_driver);

MODULE_DESCRIPTION("Frame buffer driver for the LEGO MINDSTORMS EV3 display (Sitronix ST7586S)");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
