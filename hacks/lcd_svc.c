/*
 * lcd_svc.c — st7586fb's interface on the RTOS: the module's extended
 * service calls (lcd_hack.h) and its configuration fragment.  The calls go
 * through /dev/fb0's file operations.
 * The driver is in lcd_hack.c.
 */
#include "hack_svc.h"
#include "lcd_hack.h"
#include "lcd_module.h"
#include <linux/fb.h>

/* The open frame buffer, or NULL before LCD_FN_INIT. */
static struct file *lcd_hack_file(void)
{
	return READ_ONCE(lcd_file);
}

/* LCD_FN_INIT: open /dev/fb0 (once), then INIT and START as LEGO's user space does. */
ER_UINT svc_lcd_init(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
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
ER_UINT svc_lcd_update(intptr_t frame, intptr_t len, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
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
ER_UINT svc_lcd_flush(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
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
