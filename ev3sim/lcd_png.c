/*
 * lcd_png.c — ev3sim --lcd: the display's last frame as a PNG through
 * libpng (the program only: the test configurations, ARM ones included,
 * link the library without it).
 */
#include <png.h>
#include <stdio.h>
#include "ev3sim/run.h"
#include "host_sim/devices/ev3_lcd.h"

/* 178 x 128, 8-bit grey, no interlace: a dark pixel is 0, a light one 255. */
static ER lcd_write_png(const char *path)
{
	static uint8_t px[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];
	static png_byte rows[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];
	png_bytep row_ptrs[EV3_LCD_PANEL_HEIGHT];
	png_structp png;
	png_infop info;
	FILE *f;
	bool ok;

	ev3_lcd_pixels(px);
	for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++) {
		for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x++)
			rows[y][x] = px[y][x] ? 0 : 255;
		row_ptrs[y] = rows[y];
	}
	f = fopen(path, "wb");
	if (!f)
		return E_SYS;
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	info = png ? png_create_info_struct(png) : NULL;
	if (!info || setjmp(png_jmpbuf(png))) {
		png_destroy_write_struct(&png, &info);
		fclose(f);
		return E_SYS;
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, EV3_LCD_PANEL_WIDTH, EV3_LCD_PANEL_HEIGHT, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
		     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_set_filter(png, 0, PNG_FILTER_NONE);
	png_set_rows(png, info, row_ptrs);
	png_write_png(png, info, PNG_TRANSFORM_IDENTITY, NULL);
	png_destroy_write_struct(&png, &info);
	ok = !ferror(f);
	return fclose(f) == 0 && ok ? E_OK : E_SYS;
}

/* Installs the writer before the command line runs (a constructor: main.c stays the CLI's). */
__attribute__((constructor)) static void lcd_png_install(void)
{
	ev3sim_lcd_png_writer = lcd_write_png;
}
