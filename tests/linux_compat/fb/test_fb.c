/*
 * test_fb.c — the frame buffer core and deferred I/O: register_framebuffer
 * makes /dev/fb0, the FBIO* ioctls answer from var/fix (FBIOPUT through
 * fb_check_var/fb_set_par), other ioctls reach fb_ioctl, read/write copy
 * the frame memory, mmap hands out the frame memory, and writes reported
 * through the mapping run deferred_io once, fbdefio->delay later, with the
 * written pages in order; a second register takes fb1, unregister removes
 * the node, cleanup cancels pending work.
 */
#include "lx_test.h"
#include <linux/fb.h>
#include <linux/jiffies.h>
#include <linux/delay.h>
#include <linux/vmalloc.h>
#include <linux_compat/devfs.h>
#include <linux_compat/fbdev.h>

#define W 178
#define H 128
#define LINE 60
#define SIZE (LINE * H)

static int io_calls, io_pages;
static unsigned long io_offsets[4];
static uint64_t io_time;
static int opens, checks;

static void test_deferred_io(struct fb_info *info, struct list_head *pagelist)
{
	struct fb_deferred_io_pageref *ref;

	io_calls++;
	io_pages = 0;
	io_time = rtos_host_now();
	list_for_each_entry(ref, pagelist, list) {
		if (io_pages < 4)
			io_offsets[io_pages] = ref->offset;
		io_pages++;
	}
}

static struct fb_deferred_io test_defio = {
	.delay = HZ / 20,
	.sort_pagereflist = true,
	.deferred_io = test_deferred_io,
};

static int test_open(struct fb_info *info, int user)
{
	opens++;
	return 0;
}

static int test_ioctl(struct fb_info *info, unsigned int cmd, unsigned long arg)
{
	return cmd == 0x40045300 ? 42 : -ENOTTY;
}

static int test_check_var(struct fb_var_screeninfo *var, struct fb_info *info)
{
	checks++;
	return var->xres == W && var->yres == H ? 0 : -EINVAL;
}

static const struct fb_ops test_ops = {
	.owner = THIS_MODULE,
	.fb_open = test_open,
	.fb_ioctl = test_ioctl,
	.fb_check_var = test_check_var,
};

static struct fb_info *make_fb(bool defio)
{
	struct fb_info *info = framebuffer_alloc(16, NULL);

	info->fbops = &test_ops;
	info->screen_buffer = vzalloc(PAGE_ALIGN(SIZE));
	info->screen_size = SIZE;
	info->fix.smem_len = SIZE;
	info->fix.line_length = LINE;
	info->var.xres = info->var.xres_virtual = W;
	info->var.yres = info->var.yres_virtual = H;
	if (defio) {
		info->fbdefio = &test_defio;
		fb_deferred_io_init(info);
	}
	return info;
}

static void body(void)
{
	struct fb_info *info = make_fb(true), *second;
	struct fb_var_screeninfo var;
	struct fb_fix_screeninfo fix;
	struct file *file;
	char buf[8];
	loff_t pos = 0;
	void *map;
	uint64_t t0;

	ok(info->par != NULL && info->node == -1, "framebuffer_alloc: par behind the info, not registered");
	is_int(register_framebuffer(info), 0, "register_framebuffer");
	is_int(info->node, 0, "as fb0");
	ok(lx_dev_exists("/dev/fb0"), "/dev/fb0 exists");
	is_int(register_framebuffer(info), -EBUSY, "twice: -EBUSY");
	is_int(lx_dev_open("/dev/fb0", O_RDWR, &file), 0, "open");
	is_int(opens, 1, "fb_open called");

	is_int(lx_dev_ioctl_kernel(file, FBIOGET_VSCREENINFO, &var), 0, "FBIOGET_VSCREENINFO");
	ok(var.xres == W && var.yres == H, "178 x 128");
	is_int(lx_dev_ioctl_kernel(file, FBIOGET_FSCREENINFO, &fix), 0, "FBIOGET_FSCREENINFO");
	ok(fix.line_length == LINE && fix.smem_len == SIZE, "line_length 60, smem_len 7680");
	var.xres = 100;
	is_int(lx_dev_ioctl_kernel(file, FBIOPUT_VSCREENINFO, &var), -EINVAL, "FBIOPUT with another size: fb_check_var says no");
	var.xres = W;
	is_int(lx_dev_ioctl_kernel(file, FBIOPUT_VSCREENINFO, &var), 0, "FBIOPUT with the same size");
	is_int(checks, 2, "both went through fb_check_var");
	is_int(lx_dev_ioctl(file, 0x40045300, 0), 42, "a driver ioctl reaches fb_ioctl");
	is_int(lx_dev_ioctl(file, 0x1234, 0), -ENOTTY, "an unknown one: -ENOTTY");
	is_int(lx_dev_ioctl(file, FBIOBLANK, 0), -EINVAL, "FBIOBLANK without fb_blank: -EINVAL");

	is_int(lx_dev_write(file, "abc", 3, &pos), 3, "write");
	ok(!memcmp(info->screen_buffer, "abc", 3), "lands in the frame memory");
	pos = SIZE - 2;
	is_int(lx_dev_write(file, "xyz", 3, &pos), 2, "a write past the end is cut");
	pos = SIZE;
	is_int(lx_dev_write(file, "x", 1, &pos), -ENOSPC, "at the end: -ENOSPC");
	pos = 0;
	is_int(lx_dev_read(file, buf, 3, &pos), 3, "read");
	ok(!memcmp(buf, "abc", 3), "reads the frame memory");
	pos = SIZE;
	is_int(lx_dev_read(file, buf, 3, &pos), 0, "read at the end: 0");

	is_int(lx_dev_mmap(file, SIZE, &map), 0, "mmap 7680 bytes");
	ok(map == info->screen_buffer, "maps the frame memory itself");
	is_int(lx_dev_mmap(file, 3 * PAGE_SIZE, &map), -EINVAL, "more than the frame memory: -EINVAL");
	lx_dev_mmap(file, SIZE, &map);

	((u8 *)map)[5000] = 1;
	t0 = rtos_host_now();
	is_int(lx_fb_mmap_written(file, 5000, 1), 0, "a write to page 1 reported");
	((u8 *)map)[10] = 1;
	is_int(lx_fb_mmap_written(file, 10, 1), 0, "then page 0");
	is_int(lx_fb_mmap_written(file, 20, 100), 0, "page 0 again");
	msleep(20);
	is_int(io_calls, 0, "no deferred_io before the delay");
	msleep(60);
	is_int(io_calls, 1, "one deferred_io after the delay");
	in_range((double)(io_time - t0) / 1e6, 50, 62, "%.1f ms after the first write (delay HZ/20 = 50 ms)",
		 (double)(io_time - t0) / 1e6);
	ok(io_pages == 2 && io_offsets[0] == 0 && io_offsets[1] == PAGE_SIZE, "pages 0 and 1, each once, sorted");
	is_int(lx_fb_mmap_written(file, 0, PAGE_SIZE + 1), 0, "a new write after the update");
	msleep(60);
	ok(io_calls == 2 && io_pages == 2, "lists its pages again");
	is_int(lx_fb_mmap_written(file, SIZE, PAGE_SIZE * 2), -EINVAL, "beyond the mapping: -EINVAL");
	is_int(lx_fb_mmap_written(NULL, 0, 1), -EBADF, "not a frame buffer: -EBADF");

	second = make_fb(false);
	is_int(register_framebuffer(second), 0, "a second frame buffer");
	is_int(second->node, 1, "as fb1");
	unregister_framebuffer(second);
	ok(!lx_dev_exists("/dev/fb1"), "unregister removes /dev/fb1");
	vfree(second->screen_buffer);
	framebuffer_release(second);

	lx_fb_mmap_written(file, 0, 1);
	is_int(lx_dev_close(file), 0, "close");
	unregister_framebuffer(info);
	fb_deferred_io_cleanup(info);
	msleep(100);
	is_int(io_calls, 2, "cleanup cancelled the pending deferred_io");
	ok(!lx_dev_exists("/dev/fb0"), "/dev/fb0 gone");
	vfree(info->screen_buffer);
	framebuffer_release(info);
}

int main(void)
{
	tap_plan(45);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
