/*
 * test_lcd.c — st7586fb through lcd_hack on host_sim's SPI1 and ST7586S:
 * the board's bus and display probed at boot, nothing sent before INIT,
 * INIT's reset and script (~310 ms) leaving the display on and white, a
 * drawn frame reaching the panel pixel for pixel within the refresh delay
 * (and not before), FLUSH, LEGO's user-space flow on /dev/fb0 (INIT ioctl,
 * screen info, mmap, writes through the mapping), the boot screen kept
 * while the buffer is all white and START not issued, bad calls refused.
 */
#include <string.h>
#include <linux/fcntl.h>
#include <linux/errno.h>
#include <linux/fb.h>
#include <linux_compat/devfs.h>
#include <linux_compat/fbdev.h>
#include <linux_compat/config.h>
#include "tap.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/clock.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_lcd.h"
#include "lcd_hack.h"

#define MS 1000000ULL

static bool done;
static uint8_t frame[FB_ST7586_SIZE];

/* The test pattern: a diagonal band, a border and a checkerboard, in LEGO's black (whole fields). */
static bool pattern(unsigned x, unsigned y)
{
	return x == 0 || y == 0 || x == FB_ST7586_WIDTH - 1 || y == FB_ST7586_HEIGHT - 1 ||
	       (x > y && x < y + 9) || (y > 90 && ((x / 4 + y / 4) & 1));
}

static void draw(uint8_t *f, bool (*pix)(unsigned, unsigned))
{
	static const uint8_t black[3] = { 0xE0, 0x1C, 0x03 };

	memset(f, 0, FB_ST7586_SIZE);
	for (unsigned y = 0; y < FB_ST7586_HEIGHT; y++)
		for (unsigned x = 0; x < FB_ST7586_WIDTH; x++)
			if (pix(x, y))
				f[y * FB_ST7586_LINE_LENGTH + x / 3] |= black[x % 3];
}

/* Pixels of the panel that differ from pix. */
static unsigned panel_diff(bool (*pix)(unsigned, unsigned))
{
	static uint8_t px[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];
	unsigned bad = 0;

	ev3_lcd_pixels(px);
	for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++)
		for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x++)
			bad += px[y][x] != pix(x, y);
	return bad;
}

static bool white(unsigned x, unsigned y)
{
	(void)x; (void)y;
	return false;
}

static bool cross(unsigned x, unsigned y)
{
	return x == 89 || y == 64;
}

static void lego_flow(void)
{
	struct fb_var_screeninfo var;
	struct fb_fix_screeninfo fix;
	struct file *file;
	uint8_t *map;
	void *m;
	uint32_t frames;

	is_int(lx_dev_open("/dev/fb0", O_RDWR, &file), 0, "LEGO's flow: open /dev/fb0");
	is_int(lx_dev_ioctl(file, FB_ST7586_INIT_DISPLAY, 0), 0, "ioctl 0x40045300 (INIT)");
	is_int(lx_dev_ioctl_kernel(file, FBIOGET_VSCREENINFO, &var), 0, "FBIOGET_VSCREENINFO");
	ok(var.xres == 178 && var.yres == 128 && var.nonstd == 1, "178 x 128, nonstd");
	is_int(lx_dev_ioctl_kernel(file, FBIOGET_FSCREENINFO, &fix), 0, "FBIOGET_FSCREENINFO");
	ok(fix.line_length == 60 && fix.smem_len == 7680 && !strcmp(fix.id, "ST7586"), "line_length 60, 7680 bytes, id ST7586");
	is_int(lx_dev_mmap(file, var.yres * fix.line_length, &m), 0, "mmap(yres * line_length)");
	map = m;
	draw(frame, cross);
	memcpy(map, frame, sizeof(frame));
	frames = ev3_lcd_get_stats()->frames;
	is_int(lx_fb_mmap_written(file, 0, sizeof(frame)), 0, "the stores through the mapping reported");
	dly_tsk(FB_ST7586_REFRESH_MS + 15);
	is_int(ev3_lcd_get_stats()->frames, frames + 1, "one frame pushed for all of them");
	is_int(panel_diff(cross), 0, "the panel shows the cross drawn through the mapping");
	is_int(lx_dev_ioctl(file, 0x4600 + 0x99, 0), -ENOTTY, "an unknown ioctl: -ENOTTY");
	is_int(lx_dev_close(file), 0, "close");
}

static void body(void)
{
	uint64_t t0, t;
	uint32_t frames;

	is_int(lcd_svc_update(frame, sizeof(frame)), E_OBJ, "UPDATE before INIT: E_OBJ");
	ok(!ev3_lcd_display_on(), "the panel is off after boot: the driver does not initialise it at probe");
	is_int(ev3_lcd_get_stats()->commands, 0, "and sent nothing");

	t0 = hs_now();
	is_int(lcd_svc_init(), E_OK, "INIT");
	t = (hs_now() - t0) / MS;
	in_range((double)t, 335, 360, "INIT takes %llu ms (reset 130 ms, script waits 180 ms, 20 ms RAM clear, 8 ms frame)",
		 (unsigned long long)t);
	ok(ev3_lcd_display_on(), "display on after INIT");
	is_int(ev3_lcd_get_stats()->resets, 1, "one hardware reset");
	is_int(panel_diff(white), 0, "a white panel");

	draw(frame, pattern);
	frames = ev3_lcd_get_stats()->frames;
	t0 = hs_now();
	is_int(lcd_svc_update(frame, sizeof(frame)), E_OK, "UPDATE with the pattern");
	dly_tsk(FB_ST7586_REFRESH_MS - 5);
	is_int(ev3_lcd_get_stats()->frames, frames, "not on the panel before the refresh delay");
	dly_tsk(15);
	is_int(ev3_lcd_get_stats()->frames, frames + 1, "pushed after it");
	t = (ev3_lcd_get_stats()->last_frame_ns - t0) / 100000;
	in_range((double)t / 10, FB_ST7586_REFRESH_MS, FB_ST7586_REFRESH_MS + 10,
		 "on the panel %.1f ms after the write (delay plus 7.8 ms of transfer)", (double)t / 10);
	is_int(panel_diff(pattern), 0, "all 178 x 128 pixels show the pattern");

	draw(frame, cross);
	is_int(lcd_svc_update(frame, sizeof(frame)), E_OK, "UPDATE with a cross");
	is_int(lcd_svc_flush(), E_OK, "FLUSH");
	is_int(panel_diff(cross), 0, "on the panel when FLUSH returns");
	is_int(lcd_svc_flush(), E_OK, "FLUSH with nothing pending");

	is_int(lcd_svc_update(frame, 100), E_PAR, "a short frame: E_PAR");
	is_int(lcd_svc_update(NULL, sizeof(frame)), E_MACV, "a NULL frame: E_MACV");
	is_int(ev3_lcd_get_stats()->dropped, 0, "no byte was dropped by the panel");

	lego_flow();
	done = true;
}

/* The boot screen: while the buffer is all white and START was not issued, nothing is pushed. */
static void splash_body(void)
{
	struct file *file;
	loff_t pos = 0;
	uint32_t ram_bytes;

	is_int(lx_dev_open("/dev/fb0", O_RDWR, &file), 0, "open /dev/fb0 without INIT");
	memset(frame, 0, sizeof(frame));
	is_int(lx_dev_write(file, (const char *)frame, sizeof(frame), &pos), (int)sizeof(frame),
	       "write() an all-white frame");
	dly_tsk(100);
	is_int(ev3_lcd_get_stats()->ram_bytes, 0, "not pushed: the boot screen stays");
	frame[0] = 0xE0;
	pos = 0;
	lx_dev_write(file, (const char *)frame, sizeof(frame), &pos);
	dly_tsk(100);
	ram_bytes = ev3_lcd_get_stats()->ram_bytes;
	is_int(ram_bytes, FB_ST7586_SIZE, "a black pixel: the frame is pushed");
	memset(frame, 0, sizeof(frame));
	pos = 0;
	lx_dev_write(file, (const char *)frame, sizeof(frame), &pos);
	dly_tsk(100);
	is_int(ev3_lcd_get_stats()->ram_bytes, 2 * FB_ST7586_SIZE, "from then on white frames too");
	lx_dev_close(file);
	done = true;
}

static void task(intptr_t exinf)
{
	((void (*)(void))exinf)();
}

static bool run(void (*fn)(void))
{
	const struct rtos_task_cfg t = { 1, TA_ACT, (intptr_t)fn, task, 8, 64 * 1024, TDOM_KERNEL, "lcd_test" };
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, &lcd_hack_cfg, NULL };
	const struct rtos_cfg cfg = { .name = "lcd_test", .tasks = &t, .ntasks = 1, .includes = includes };
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };

	done = false;
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		return false;
	}
	for (int i = 0; !done && i < 100; i++)
		hs_sim_run_for(100 * MS);
	hs_sim_shutdown();
	return done;
}

int main(void)
{
	tap_plan(39);
	ok(run(body), "the test task ran to completion");
	ok(run(splash_body), "the boot-screen test ran to completion");
	return tap_done();
}
