/*
 * test_lcd_api.c — EV3RT's LCD calls from an application task (user domain
 * 1) on the simulated brick: the panel shows what was drawn (a string in
 * both fonts, lines, rectangles, a BMP loaded with ev3_image_load) pixel
 * for pixel against the drawing core run on a frame of the test's own,
 * within 40 ms; EV3RT's enum values; the argument checks' TOPPERS codes.
 */
#include <stdlib.h>
#include <string.h>
#include "api_test.h"
#include "host_sim/devices/ev3_lcd.h"
#include "../../../api/src/lcd_draw.h"

static uint8_t expect[LCD_FRAME_BYTES];

static unsigned panel_diff(void)
{
	static uint8_t px[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];
	unsigned bad = 0;

	ev3_lcd_pixels(px);
	for (int y = 0; y < EV3_LCD_HEIGHT; y++)
		for (int x = 0; x < EV3_LCD_WIDTH; x++)
			bad += px[y][x] != lcd_pixel(expect, x, y);
	return bad;
}

/* A 16 x 8 1-bit BMP: the left half black, the right white, one white pixel at (2, 1). */
static uint32_t make_bmp(uint8_t *b)
{
	static const uint8_t head[62] = {
		'B', 'M', 62 + 32, 0, 0, 0, 0, 0, 0, 0, 62, 0, 0, 0,
		40, 0, 0, 0, 16, 0, 0, 0, 8, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 32, 0, 0, 0,
		0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0,
		0, 0, 0, 0, 255, 255, 255, 0,
	};

	memcpy(b, head, sizeof(head));
	for (int row = 0; row < 8; row++) {            /* bottom-up rows of 4 bytes */
		uint8_t *r = b + 62 + 4 * row;

		r[0] = 0x00;
		r[1] = 0xFF;
		r[2] = r[3] = 0;
		if (7 - row == 1)
			r[0] = 0x20;
	}
	return 62 + 32;
}

static void body(void)
{
	int32_t w = 0, h = 0;
	uint8_t bmp[128];
	memfile_t mf;
	image_t img;
	uint64_t t0;
	char hello[] = "Hello EV3", medium[] = "ev3lx!";	/* on the task's stack: its domain */

	ok(EV3_FONT_SMALL == 0 && EV3_FONT_MEDIUM == 1 && EV3_LCD_WHITE == 0 && EV3_LCD_BLACK == 1,
	   "EV3RT's enum values");
	is_int(ev3_font_get_size(EV3_FONT_SMALL, &w, &h), E_OK, "small font size");
	ok(w == 6 && h == 8, "6 x 8");
	is_int(ev3_font_get_size(EV3_FONT_MEDIUM, &w, &h), E_OK, "medium font size");
	ok(w == 12 && h == 16, "12 x 16");
	is_int(ev3_font_get_size((lcdfont_t)2, &w, &h), E_ID, "font 2: E_ID");
	is_int(ev3_lcd_set_font((lcdfont_t)-1), E_ID, "set_font(-1): E_ID");

	t0 = at_now_ms();
	is_int(ev3_lcd_draw_string(hello, 0, 0), E_OK, "draw_string while the panel starts up");
	ok(at_now_ms() - t0 < 5, "does not wait for the panel's start-up, which the platform runs at boot (%llu ms)",
	   (unsigned long long)(at_now_ms() - t0));
	for (int i = 0; i < 9; i++)
		lcd_char(expect, EV3_FONT_SMALL, (unsigned char)"Hello EV3"[i], 6 * i, 0);
	is_int(ev3_lcd_set_font(EV3_FONT_MEDIUM), E_OK, "set_font(MEDIUM)");
	is_int(ev3_lcd_draw_string(medium, 10, 20), E_OK, "a medium string");
	for (int i = 0; i < 6; i++)
		lcd_char(expect, EV3_FONT_MEDIUM, (unsigned char)"ev3lx!"[i], 10 + 12 * i, 20);
	is_int(ev3_lcd_draw_line(0, 127, 177, 40), E_OK, "draw_line");
	lcd_line(expect, 0, 127, 177, 40, true);
	is_int(ev3_lcd_fill_rect(120, 60, 40, 30, EV3_LCD_BLACK), E_OK, "fill_rect black");
	lcd_fill(expect, 120, 60, 40, 30, true);
	is_int(ev3_lcd_fill_rect(130, 70, 10, 10, EV3_LCD_WHITE), E_OK, "fill_rect white inside it");
	lcd_fill(expect, 130, 70, 10, 10, false);
	is_int(ev3_lcd_fill_rect(170, 120, 100, 100, EV3_LCD_BLACK), E_OK, "a rectangle over the edge is clipped");
	lcd_fill(expect, 170, 120, 100, 100, true);

	mf.buffer = bmp;
	mf.filesz = make_bmp(bmp);
	mf.buffersz = sizeof(bmp);
	is_int(ev3_image_load(&mf, &img), E_OK, "ev3_image_load of a 1-bit BMP");
	ok(img.width == 16 && img.height == 8 && img.data != NULL, "16 x 8");
	is_int(ev3_lcd_draw_image(&img, 60, 100), E_OK, "draw_image");
	lcd_blit(expect, img.data, img.width, img.height, 60, 100);
	tslp_tsk(400);
	is_int(panel_diff(), 0, "once up (~310 ms after boot), the panel shows exactly what was drawn before");
	is_int(ev3_lcd_fill_rect(0, 120, 8, 8, EV3_LCD_BLACK), E_OK, "a drawing after the start-up");
	lcd_fill(expect, 0, 120, 8, 8, true);
	tslp_tsk(45);
	is_int(panel_diff(), 0, "the panel shows it 40 ms later");
	ok(ev3_lcd_pixel(60, 100) && !ev3_lcd_pixel(70, 100) && !ev3_lcd_pixel(62, 101),
	   "the image's black half, white half and white pixel");
	is_int(ev3_image_free(&img), E_OK, "image_free");
	ok(img.data == NULL, "data cleared");
	is_int(ev3_image_free(&img), E_OBJ, "freeing again: E_OBJ");

	is_int(ev3_lcd_fill_rect(0, 0, 10, 10, (lcdcolor_t)2), E_PAR, "colour 2: E_PAR");
	is_int(ev3_lcd_draw_string(NULL, 0, 0), E_PAR, "NULL string: E_PAR");
	is_int(ev3_lcd_draw_image(NULL, 0, 0), E_PAR, "NULL image: E_PAR");
	img.width = 0;
	img.data = bmp;
	is_int(ev3_lcd_draw_image(&img, 0, 0), E_PAR, "an empty image: E_PAR");
	{
		/* as EV3RT apps do: the load's result unchecked, the image drawn anyway */
		memfile_t unloaded = { .buffer = NULL };
		image_t stale = { .width = 8, .height = 8, .data = (void *)0x1000 };

		is_int(ev3_image_load(&unloaded, &stale), E_PAR, "a memfile that did not load: E_PAR");
		ok(stale.data == NULL && stale.width == 0 && stale.height == 0,
		   "and the image is left empty, as EV3RT's ev3_image_load leaves it");
		is_int(ev3_lcd_draw_image(&stale, 0, 0), E_PAR, "drawing it: E_PAR, no stale pointer read");
	}
	is_int(ev3_image_load(NULL, &img), E_PAR, "NULL file: E_PAR");
	mf.filesz = 10;
	is_int(ev3_image_load(&mf, &img), E_PAR, "a truncated BMP: E_PAR");
	is_int(ev3_image_load(&mf, NULL), E_MACV, "NULL image out-parameter: E_MACV");
	is_int(ev3_font_get_size(EV3_FONT_SMALL, (int32_t *)&expect[0], NULL), E_MACV,
	       "an out-parameter outside the task's domain: E_MACV");
	is_int(panel_diff(), 0, "refused calls drew nothing");
}

int main(void)
{
	tap_plan(38);
	ok(at_run(NULL, body, 1, 10), "the application task ran to completion");
	return tap_done();
}
