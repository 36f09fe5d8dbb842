/*
 * test_lcd_draw.c — the LCD API's drawing core on a plain memory frame:
 * the ST7586 byte format (three pixels a byte, black = every bit of the
 * field, padding untouched), rectangles, lines (rounding, either direction,
 * clipping exact against an unclipped reference, int32_t extremes), both
 * fonts' cells, 1-bit images, and the BMP decoder (1/4/8/24/32 bits,
 * bottom-up and top-down, the palette's colours, every refusal).
 */
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "../../../api/src/lcd_draw.h"

#define W EV3_LCD_WIDTH
#define H EV3_LCD_HEIGHT

static uint8_t frame[LCD_FRAME_BYTES];

static void clear(void)
{
	memset(frame, 0, sizeof(frame));
}

static int count_black(void)
{
	int n = 0;

	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++)
			n += lcd_pixel(frame, x, y);
	return n;
}

/* The line's pixels by the rule, walking the whole major axis (moderate coordinates). */
static void reference_line(bool *px, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
	int64_t dx = x1 - x0, dy = y1 - y0;
	bool xm = llabs(dx) >= llabs(dy);
	int64_t steps = xm ? llabs(dx) : llabs(dy);

	memset(px, 0, sizeof(bool) * W * H);
	for (int64_t i = 0; i <= steps; i++) {
		int64_t m, n, x, y;
		/* walk from the end with the smaller major coordinate */
		int64_t a = xm ? (dx < 0 ? x1 : x0) : (dy < 0 ? y1 : y0);
		int64_t an = xm ? (dx < 0 ? y1 : y0) : (dy < 0 ? x1 : x0);
		int64_t d = xm ? (dx < 0 ? -dy : dy) : (dy < 0 ? -dx : dx);
		int64_t num;

		m = a + i;
		/* floor(i * d / steps + 1/2) = floor((2 i d + steps) / (2 steps)) */
		num = 2 * i * d + steps;
		n = an + (steps ? (num >= 0 ? num / (2 * steps) : -((-num + 2 * steps - 1) / (2 * steps))) : 0);
		x = xm ? m : n;
		y = xm ? n : m;
		if (x >= 0 && x < W && y >= 0 && y < H)
			px[y * W + x] = true;
	}
}

static bool frame_matches(const bool *px)
{
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++)
			if (lcd_pixel(frame, x, y) != px[y * W + x]) {
				tap_diag("pixel (%d, %d) is %d", x, y, lcd_pixel(frame, x, y));
				return false;
			}
	return true;
}

static void test_format_and_rects(void)
{
	clear();
	lcd_fill(frame, 1, 0, 1, 1, true);
	is_int(frame[0], 0x1C, "pixel 1 of a row is bits 4:2 of byte 0");
	lcd_fill(frame, 0, 0, 3, 1, true);
	is_int(frame[0], 0xFF, "pixels 0..2 black fill byte 0");
	lcd_fill(frame, 2, 0, 1, 1, false);
	is_int(frame[0], 0xFC, "pixel 2 white clears bits 1:0");
	lcd_fill(frame, 4, 1, 1, 1, true);
	is_int(frame[LCD_ROW_BYTES + 1], 0x1C, "row 1 starts 60 bytes on");

	clear();
	lcd_fill(frame, 0, 0, W, H, true);
	is_int(count_black(), W * H, "a full-screen fill blackens every pixel");
	is_int(frame[LCD_ROW_BYTES - 1], 0xE0, "the padding columns 178, 179 stay 0");
	lcd_fill(frame, 10, 20, 5, 3, false);
	is_int(count_black(), W * H - 15, "a white 5 x 3 rectangle");
	ok(!lcd_pixel(frame, 10, 20) && !lcd_pixel(frame, 14, 22) && lcd_pixel(frame, 15, 22) &&
	   lcd_pixel(frame, 14, 23) && lcd_pixel(frame, 9, 20), "exactly its pixels");

	clear();
	lcd_fill(frame, -5, -5, 10, 10, true);
	is_int(count_black(), 25, "clipped at the top-left edges");
	clear();
	lcd_fill(frame, W - 8, H - 8, 100, 100, true);
	is_int(count_black(), 64, "clipped at the bottom-right edges");
	clear();
	lcd_fill(frame, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX, true);
	lcd_fill(frame, INT32_MAX, 0, INT32_MAX, 10, true);
	lcd_fill(frame, 5, 5, -3, 4, true);
	lcd_fill(frame, 5, 5, 3, 0, true);
	is_int(count_black(), 0, "rectangles outside, negative or empty draw nothing");
	lcd_fill(frame, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX, true);
	lcd_fill(frame, -2, -2, INT32_MAX, INT32_MAX, true);
	is_int(count_black(), W * H, "a rectangle over the whole frame from far away");
}

static void test_lines(void)
{
	static bool ref[W * H];
	static const int32_t cases[][4] = {
		{ 0, 0, 10, 5 }, { 10, 5, 0, 0 }, { 3, 100, 170, 7 }, { 20, 2, 25, 120 },
		{ -1000, -500, 1000, 500 }, { -300, 200, 400, -50 }, { 90, -1000, 60, 1000 },
		{ 177, 127, 0, 0 }, { 50, 50, 50, 50 }, { 5, 60, 5, 10 }, { -20, 64, 300, 64 },
		{ 200, 10, 300, 20 }, { 0, 127, 177, 126 },
	};
	bool all = true;

	clear();
	lcd_line(frame, 0, 0, 10, 5, true);
	ok(lcd_pixel(frame, 0, 0) && lcd_pixel(frame, 1, 1) && lcd_pixel(frame, 2, 1) &&
	   lcd_pixel(frame, 3, 2) && lcd_pixel(frame, 10, 5) && !lcd_pixel(frame, 1, 0),
	   "(0,0)-(10,5): a tie at x = 1 rounds up to y = 1");
	is_int(count_black(), 11, "one pixel per step of the longer axis, both ends");
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		clear();
		lcd_line(frame, cases[i][0], cases[i][1], cases[i][2], cases[i][3], true);
		reference_line(ref, cases[i][0], cases[i][1], cases[i][2], cases[i][3]);
		if (!frame_matches(ref)) {
			tap_diag("line %d,%d - %d,%d", cases[i][0], cases[i][1], cases[i][2], cases[i][3]);
			all = false;
		}
	}
	ok(all, "clipped lines draw exactly the unclipped line's pixels inside the frame (%zu lines)",
	   sizeof(cases) / sizeof(cases[0]));

	clear();
	lcd_line(frame, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX, true);
	is_int(count_black(), H, "a diagonal across the whole int32_t range: 128 pixels");
	ok(lcd_pixel(frame, 0, 0) && lcd_pixel(frame, 127, 127) && lcd_pixel(frame, 64, 64),
	   "on the frame's diagonal");
	clear();
	lcd_line(frame, INT32_MAX, 3, INT32_MIN, 3, true);
	is_int(count_black(), W, "a horizontal line over the int32_t range fills its row");
	clear();
	/* its half-way point is x = -0.5: the whole frame is past it, on y = 1 */
	lcd_line(frame, INT32_MIN, 0, INT32_MAX, 1, true);
	ok(lcd_pixel(frame, 0, 1) && lcd_pixel(frame, W - 1, 1) && count_black() == W,
	   "a near-horizontal line over the int32_t range rounds exactly (no overflow)");
	lcd_line(frame, 0, 1, 177, 1, false);
	is_int(count_black(), 0, "a white line erases");
}

static void test_text(void)
{
	int32_t w, h;
	int black;

	lcd_font_cell(EV3_FONT_SMALL, &w, &h);
	ok(w == 6 && h == 8, "small cell 6 x 8");
	lcd_font_cell(EV3_FONT_MEDIUM, &w, &h);
	ok(w == 12 && h == 16, "medium cell 12 x 16");

	clear();
	lcd_fill(frame, 0, 0, 20, 20, true);
	lcd_char(frame, EV3_FONT_SMALL, 'A', 0, 0);
	ok(!lcd_pixel(frame, 0, 0) && lcd_pixel(frame, 1, 0) && lcd_pixel(frame, 3, 0) &&
	   !lcd_pixel(frame, 4, 0), "'A' row 0: .###.");
	ok(lcd_pixel(frame, 0, 3) && lcd_pixel(frame, 2, 3) && lcd_pixel(frame, 4, 3), "'A' row 3: #####");
	ok(!lcd_pixel(frame, 5, 0) && !lcd_pixel(frame, 0, 7) && lcd_pixel(frame, 6, 0) && lcd_pixel(frame, 0, 8),
	   "the cell's spacing column and row paint white, nothing outside the cell");
	black = 0;
	for (int y = 0; y < 8; y++)
		for (int x = 0; x < 6; x++)
			black += lcd_pixel(frame, x, y);
	is_int(black, 18, "'A' has 18 ink pixels");

	clear();
	lcd_char(frame, EV3_FONT_MEDIUM, 'H', 0, 0);
	ok(lcd_pixel(frame, 0, 1) && lcd_pixel(frame, 1, 14) && lcd_pixel(frame, 9, 1) &&
	   !lcd_pixel(frame, 0, 0) && !lcd_pixel(frame, 0, 15) && !lcd_pixel(frame, 10, 5),
	   "medium 'H': two-pixel strokes over rows 1..14");
	ok(lcd_pixel(frame, 4, 7) && lcd_pixel(frame, 5, 8) && !lcd_pixel(frame, 4, 9), "its bar on rows 7, 8");
	clear();
	lcd_char(frame, EV3_FONT_MEDIUM, '/', 0, 0);
	/* '/' rows 1 and 2: ....# and ...#. ; Scale2x fills the inner corners of the step */
	ok(lcd_pixel(frame, 9, 4) && lcd_pixel(frame, 7, 4) && lcd_pixel(frame, 8, 5) && !lcd_pixel(frame, 6, 3) &&
	   !lcd_pixel(frame, 9, 5),
	   "medium diagonals are smoothed, not stairs");

	clear();
	lcd_char(frame, EV3_FONT_SMALL, 0x7F, 0, 0);
	lcd_char(frame, EV3_FONT_SMALL, 0xC3, 6, 0);
	ok(lcd_pixel(frame, 0, 0) && lcd_pixel(frame, 4, 6) && !lcd_pixel(frame, 2, 3) &&
	   lcd_pixel(frame, 6, 0) && lcd_pixel(frame, 10, 6), "bytes outside printable ASCII show a box");

	clear();
	lcd_char(frame, EV3_FONT_SMALL, 'H', -2, -3);
	lcd_char(frame, EV3_FONT_SMALL, 'H', W - 3, H - 2);
	ok(lcd_pixel(frame, 2, 0) && lcd_pixel(frame, 0, 0) && lcd_pixel(frame, W - 3, H - 2) &&
	   lcd_pixel(frame, W - 3, H - 1), "glyphs clip at the edges, pixel for pixel");
	is_int(count_black(), 6 + 2, "only their inside pixels");
	lcd_char(frame, EV3_FONT_MEDIUM, 'W', INT32_MIN, INT32_MAX);
	is_int(count_black(), 8, "a glyph far outside draws nothing");
}

static void test_blit(void)
{
	/* 10 x 2: row 0 = #.#.#.#.#. , row 1 = ########## */
	static const uint8_t img[] = { 0xAA, 0x80, 0xFF, 0xC0 };

	clear();
	lcd_fill(frame, 0, 0, W, H, true);
	lcd_blit(frame, img, 10, 2, 0, 0);
	ok(lcd_pixel(frame, 0, 0) && !lcd_pixel(frame, 1, 0) && lcd_pixel(frame, 8, 0) && !lcd_pixel(frame, 9, 0),
	   "row 0 copied, white pixels painted white");
	is_int(count_black(), W * H - 5, "nothing else changed");
	clear();
	lcd_blit(frame, img, 10, 2, -1, -1);
	is_int(count_black(), 9, "clipped at the top-left: row 1's nine visible pixels");
	clear();
	lcd_blit(frame, img, 10, 2, W - 2, H - 1);
	ok(count_black() == 1 && lcd_pixel(frame, W - 2, H - 1), "clipped at the bottom-right");
	lcd_blit(frame, img, 10, 2, INT32_MAX, INT32_MIN);
	is_int(count_black(), 1, "far outside: nothing");
	is_int((int)lcd_image_bytes(10, 2), 4, "image bytes: 2 rows of 2");
	ok(lcd_image_bytes(0, 5) == 0 && lcd_image_bytes(5, -1) == 0, "no size for empty images");
}

/* ---- BMP ---- */

static void put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

/* A BMP header for w x h at bits with ncolours palette entries; returns the pixel offset. */
static uint32_t bmp_header(uint8_t *b, int32_t w, int32_t h, uint16_t bits, uint32_t ncolours, uint32_t total)
{
	uint32_t offset = 14 + 40 + 4 * ncolours;

	memset(b, 0, offset);
	b[0] = 'B';
	b[1] = 'M';
	put32(b + 2, total);
	put32(b + 10, offset);
	put32(b + 14, 40);
	put32(b + 18, (uint32_t)w);
	put32(b + 22, (uint32_t)h);
	b[26] = 1;
	b[28] = (uint8_t)bits;
	put32(b + 46, ncolours);
	return offset;
}

static bool image_bit(const image_t *img, int x, int y)
{
	return (((const uint8_t *)img->data)[y * ((img->width + 7) / 8) + x / 8] >> (7 - x % 8)) & 1;
}

static void test_bmp(void)
{
	static uint8_t b[512];
	image_t img = { 0, 0, NULL };
	uint32_t off;

	/* 1 bit, 9 x 2, bottom-up, palette 0 = white, 1 = black; stride 4 */
	off = bmp_header(b, 9, 2, 1, 2, 0);
	memset(b + 54, 0xFF, 3);                /* white */
	memset(b + 58, 0x00, 3);                /* black */
	b[off + 0] = 0x80;                      /* bottom row: pixel 0 */
	b[off + 1] = 0x80;                      /* bottom row: pixel 8 */
	b[off + 4] = 0x55;                      /* top row: .#.#.#.# */
	is_int(lcd_bmp_decode(b, off + 8, &img), E_OK, "1-bit BMP decodes");
	ok(img.width == 9 && img.height == 2, "its size");
	ok(!image_bit(&img, 0, 0) && image_bit(&img, 1, 0) && image_bit(&img, 7, 0) && !image_bit(&img, 8, 0) &&
	   image_bit(&img, 0, 1) && image_bit(&img, 8, 1) && !image_bit(&img, 1, 1),
	   "bottom-up rows, palette index 1 black");
	free(img.data);
	memset(b + 54, 0x00, 3);                /* index 0 black, 1 white: inverted palette */
	memset(b + 58, 0xFF, 3);
	lcd_bmp_decode(b, off + 8, &img);
	ok(image_bit(&img, 0, 0) && !image_bit(&img, 1, 0), "the palette decides, not the index");
	free(img.data);

	/* 24 bits, 2 x 2, top-down: dark red, light yellow / mid grey 127, 128 */
	off = bmp_header(b, 2, -2, 24, 0, 0);
	memcpy(b + off, (const uint8_t[]){ 0, 0, 200, 0, 255, 255, 0, 0 }, 8);
	memcpy(b + off + 8, (const uint8_t[]){ 127, 127, 127, 128, 128, 128, 0, 0 }, 8);
	is_int(lcd_bmp_decode(b, off + 16, &img), E_OK, "24-bit top-down BMP decodes");
	ok(image_bit(&img, 0, 0) && !image_bit(&img, 1, 0) && image_bit(&img, 0, 1) && !image_bit(&img, 1, 1),
	   "luminance threshold at half scale, rows top first");
	free(img.data);

	/* 32 bits, 1 x 1 */
	off = bmp_header(b, 1, 1, 32, 0, 0);
	memcpy(b + off, (const uint8_t[]){ 10, 10, 10, 0 }, 4);
	is_int(lcd_bmp_decode(b, off + 4, &img), E_OK, "32-bit BMP decodes");
	ok(image_bit(&img, 0, 0), "dark pixel black");
	free(img.data);

	/* 8 bits with 3 colours; 4 bits with 16 */
	off = bmp_header(b, 3, 1, 8, 3, 0);
	memset(b + 54, 0xFF, 4);
	memset(b + 58, 0x10, 4);
	memset(b + 62, 0xF0, 4);
	memcpy(b + off, (const uint8_t[]){ 0, 1, 2, 0 }, 4);
	is_int(lcd_bmp_decode(b, off + 4, &img), E_OK, "8-bit BMP decodes");
	ok(!image_bit(&img, 0, 0) && image_bit(&img, 1, 0) && !image_bit(&img, 2, 0), "by the palette");
	free(img.data);
	off = bmp_header(b, 3, 1, 4, 16, 0);
	put32(b + 46, 0);
	for (int i = 0; i < 16; i++)
		memset(b + 54 + 4 * i, i < 8 ? 0 : 0xFF, 3);
	memcpy(b + off, (const uint8_t[]){ 0x0F, 0x70, 0, 0 }, 4);
	is_int(lcd_bmp_decode(b, off + 4, &img), E_OK, "4-bit BMP decodes (palette of 2^4 when the count is 0)");
	ok(image_bit(&img, 0, 0) && !image_bit(&img, 1, 0) && image_bit(&img, 2, 0), "nibbles high first");
	free(img.data);

	off = bmp_header(b, 9, 2, 1, 2, 0);
	img.data = NULL;
	is_int(lcd_bmp_decode(b, off + 7, &img), E_PAR, "truncated pixel data: E_PAR");
	is_int(lcd_bmp_decode(b, 20, &img), E_PAR, "truncated header: E_PAR");
	b[0] = 'P';
	is_int(lcd_bmp_decode(b, off + 8, &img), E_PAR, "no BM signature: E_PAR");
	b[0] = 'B';
	put32(b + 30, 1);
	is_int(lcd_bmp_decode(b, off + 8, &img), E_NOSPT, "RLE compression: E_NOSPT");
	put32(b + 30, 0);
	b[28] = 16;
	is_int(lcd_bmp_decode(b, off + 8, &img), E_NOSPT, "16 bits per pixel: E_NOSPT");
	b[28] = 1;
	put32(b + 46, 3);
	is_int(lcd_bmp_decode(b, off + 8, &img), E_PAR, "more palette entries than 2^bits: E_PAR");
	put32(b + 46, 2);
	put32(b + 18, 0);
	is_int(lcd_bmp_decode(b, off + 8, &img), E_PAR, "zero width: E_PAR");
	put32(b + 18, 9);
	put32(b + 10, 5000);
	is_int(lcd_bmp_decode(b, off + 8, &img), E_PAR, "pixel offset past the end: E_PAR");
	put32(b + 10, off);
	put32(b + 14, 12);
	is_int(lcd_bmp_decode(b, off + 8, &img), E_NOSPT, "OS/2 core header: E_NOSPT");
	put32(b + 14, 40);
	put32(b + 22, 100000);
	is_int(lcd_bmp_decode(b, off + 8, &img), E_PAR, "implausible height: E_PAR");
	ok(img.data == NULL, "a refused file leaves the image alone");
}

int main(void)
{
	tap_plan(63);
	test_format_and_rects();
	test_lines();
	test_text();
	test_blit();
	test_bmp();
	return tap_done();
}
