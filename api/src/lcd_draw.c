/*
 * lcd_draw.c — pixels, rectangles, lines and 1-bit images in the display's
 * frame format (lcd_draw.h), clipped at the frame's edges.
 */
#include "lcd_draw.h"

/* The bits of pixel x's field in its byte: bits 7:5, 4:2, 1:0. */
static const uint8_t field_mask[3] = { 0xE0, 0x1C, 0x03 };

static void put(uint8_t *frame, int32_t x, int32_t y, bool black)
{
	uint8_t *byte = &frame[y * LCD_ROW_BYTES + x / 3];

	if (black)
		*byte |= field_mask[x % 3];
	else
		*byte &= (uint8_t)~field_mask[x % 3];
}

static bool inside(int64_t x, int64_t y)
{
	return x >= 0 && x < EV3_LCD_WIDTH && y >= 0 && y < EV3_LCD_HEIGHT;
}

bool lcd_pixel(const uint8_t *frame, int32_t x, int32_t y)
{
	return (frame[y * LCD_ROW_BYTES + x / 3] & field_mask[x % 3]) != 0;
}

void lcd_fill(uint8_t *frame, int32_t x, int32_t y, int32_t w, int32_t h, bool black)
{
	int64_t left = x < 0 ? 0 : x, top = y < 0 ? 0 : y;
	int64_t right = (int64_t)x + w, bottom = (int64_t)y + h;

	if (right > EV3_LCD_WIDTH)
		right = EV3_LCD_WIDTH;
	if (bottom > EV3_LCD_HEIGHT)
		bottom = EV3_LCD_HEIGHT;
	for (int64_t row = top; row < bottom; row++)
		for (int64_t col = left; col < right; col++)
			put(frame, (int32_t)col, (int32_t)row, black);
}

/*
 * floor(t * minor / major + 1/2) for 0 <= t <= major, |minor| <= major,
 * major > 0: the minor axis's offset t steps along the major one, exact for
 * any int32_t end points (the product needs all 64 bits, unsigned).
 */
static int64_t minor_offset(uint32_t t, int64_t minor, uint32_t major)
{
	uint64_t u = (uint64_t)t * (uint64_t)(minor < 0 ? -minor : minor);
	uint64_t q = u / major, r2 = 2 * (u % major);

	return minor >= 0 ? (int64_t)(q + (r2 >= major)) : -(int64_t)(q + (r2 > major));
}

void lcd_line(uint8_t *frame, int32_t x0, int32_t y0, int32_t x1, int32_t y1, bool black)
{
	int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
	bool x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
	/* the major axis as (a, b) with a <= b, the minor coordinate at a, and its change */
	int64_t a = x_major ? (dx < 0 ? x1 : x0) : (dy < 0 ? y1 : y0);
	int64_t b = x_major ? (dx < 0 ? x0 : x1) : (dy < 0 ? y0 : y1);
	int64_t minor_a = x_major ? (dx < 0 ? y1 : y0) : (dy < 0 ? x1 : x0);
	int64_t minor_d = x_major ? (dx < 0 ? -dy : dy) : (dy < 0 ? -dx : dx);
	int64_t limit = x_major ? EV3_LCD_WIDTH - 1 : EV3_LCD_HEIGHT - 1;
	int64_t from = a < 0 ? 0 : a, to = b > limit ? limit : b;

	if (a == b) {
		if (inside(x0, y0))
			put(frame, x0, y0, black);
		return;
	}
	for (int64_t m = from; m <= to; m++) {
		int64_t n = minor_a + minor_offset((uint32_t)(m - a), minor_d, (uint32_t)(b - a));
		int64_t x = x_major ? m : n, y = x_major ? n : m;

		if (inside(x, y))
			put(frame, (int32_t)x, (int32_t)y, black);
	}
}

void lcd_blit(uint8_t *frame, const uint8_t *bits, int32_t w, int32_t h, int32_t x, int32_t y)
{
	size_t stride = ((size_t)w + 7) / 8;
	int64_t col0 = x < 0 ? -(int64_t)x : 0, row0 = y < 0 ? -(int64_t)y : 0;
	int64_t cols = (int64_t)EV3_LCD_WIDTH - x, rows = (int64_t)EV3_LCD_HEIGHT - y;

	if (cols > w)
		cols = w;
	if (rows > h)
		rows = h;
	for (int64_t r = row0; r < rows; r++)
		for (int64_t c = col0; c < cols; c++)
			put(frame, (int32_t)(x + c), (int32_t)(y + r),
			    (bits[(size_t)r * stride + (size_t)c / 8] >> (7 - c % 8)) & 1);
}
