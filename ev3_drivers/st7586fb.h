/* SPDX-License-Identifier: GPL-2.0 WITH Linux-syscall-note */
/*
 * st7586fb.h - the EV3 display's frame buffer (/dev/fb0, driver st7586fb)
 * as user space sees it, and the board data the driver needs.
 *
 *   178 x 128 pixels in 128 rows of 60 bytes (FB_ST7586_LINE_LENGTH), three
 *   pixels a byte from the left: bits 7:5, 4:2, 1:0 (the ST7586S's
 *   monochrome layout); a pixel is black when its field's top bit is set
 *   (write all bits of the field, as LEGO's user space does).  Columns 178
 *   and 179 of each row are padding.
 *   ioctl FB_ST7586_INIT_DISPLAY  resets and initialises the controller,
 *                                 then shows the frame buffer (~310 ms)
 *   ioctl FB_ST7586_START_DISPLAY marks the display as started: frames are
 *                                 pushed from now on even if all white (until
 *                                 then an all-white buffer keeps the boot screen)
 *   mmap  the frame memory; changes reach the panel within
 *         FB_ST7586_REFRESH_MS (deferred I/O), as do write()s.
 */
#ifndef ST7586FB_H
#define ST7586FB_H

#define FB_ST7586_WIDTH		178
#define FB_ST7586_HEIGHT	128
#define FB_ST7586_LINE_LENGTH	60
#define FB_ST7586_SIZE		(FB_ST7586_LINE_LENGTH * FB_ST7586_HEIGHT)
#define FB_ST7586_REFRESH_MS	40

#define FB_ST7586_INIT_DISPLAY	0x40045300	/* _IOW('S', 0, int) */
#define FB_ST7586_START_DISPLAY	0x40045301	/* _IOW('S', 1, int) */

/* The SPI modalias the board declares the display under. */
#define ST7586FB_MODALIAS	"lms2012_lcd"

/* Board data (spi_board_info.platform_data): the GPIOs of the controller's
 * A0 (command low, data high) and RESET (active low) lines. */
struct st7586fb_platform_data {
	int a0_gpio;
	int reset_gpio;
};

#endif /* ST7586FB_H */
