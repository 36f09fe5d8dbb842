/*
 * lcd_bmp.c — Windows BMP files to the LCD's 1-bit images (lcd_draw.h).
 *
 * The format as Microsoft documents it (BITMAPFILEHEADER, BITMAPINFOHEADER
 * and its later versions): a 14-byte file header ("BM", file size, the
 * pixel data's offset), an info header of at least 40 bytes (width, height
 * — negative for top-down rows —, planes 1, bits per pixel, compression),
 * for 1/4/8 bits a palette of 4-byte blue, green, red, 0 entries (the
 * header's count, or 2^bits when 0), then rows padded to 4 bytes, bottom
 * row first unless top-down.  All fields are little-endian.
 */
#include <stdlib.h>
#include <string.h>
#include "lcd_draw.h"

#define FILE_HEADER   14
#define INFO_HEADER   40        /* BITMAPINFOHEADER; V4/V5 headers extend it */
#define BI_RGB        0
#define MAX_SIDE      32767     /* larger sides are refused as implausible */

static uint32_t le32(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint16_t le16(const uint8_t *p)
{
	return (uint16_t)(p[0] | p[1] << 8);
}

size_t lcd_image_bytes(int32_t w, int32_t h)
{
	size_t stride;

	if (w <= 0 || h <= 0)
		return 0;
	stride = ((size_t)w + 7) / 8;
	return (size_t)h > SIZE_MAX / stride ? 0 : stride * (size_t)h;
}

/* Dark: ITU-R BT.601 luminance of blue, green, red below half scale. */
static bool dark(const uint8_t *bgr)
{
	return 299U * bgr[2] + 587U * bgr[1] + 114U * bgr[0] < 128000U;
}

ER lcd_bmp_decode(const uint8_t *bmp, uint32_t size, image_t *image)
{
	uint32_t offset, info, bits, compression, colours = 0, stride;
	int32_t width, height;
	bool top_down;
	const uint8_t *palette;
	uint8_t *out;
	size_t out_stride;

	if (size < FILE_HEADER + 4 || bmp[0] != 'B' || bmp[1] != 'M')
		return E_PAR;
	offset = le32(bmp + 10);
	info = le32(bmp + FILE_HEADER);
	if (info == 12 || (info > 12 && info < INFO_HEADER))
		return E_NOSPT;         /* OS/2 headers */
	if (info < INFO_HEADER || info > size - FILE_HEADER)
		return E_PAR;
	width = (int32_t)le32(bmp + 18);
	height = (int32_t)le32(bmp + 22);
	bits = le16(bmp + 28);
	compression = le32(bmp + 30);
	if (le16(bmp + 26) != 1 || width <= 0 || height == 0 || height == INT32_MIN)
		return E_PAR;
	if (compression != BI_RGB || (bits != 1 && bits != 4 && bits != 8 && bits != 24 && bits != 32))
		return E_NOSPT;
	top_down = height < 0;
	if (top_down)
		height = -height;
	if (width > MAX_SIDE || height > MAX_SIDE)
		return E_PAR;
	if (bits <= 8) {
		colours = le32(bmp + 46);
		if (colours == 0)
			colours = 1U << bits;
		else if (colours > (1U << bits))
			return E_PAR;
	}
	palette = bmp + FILE_HEADER + info;
	if ((uint64_t)FILE_HEADER + info + 4U * colours > size)
		return E_PAR;
	stride = ((uint32_t)width * bits + 31U) / 32U * 4U;
	if (offset > size || (uint64_t)stride * (uint32_t)height > size - offset)
		return E_PAR;

	out_stride = ((size_t)width + 7) / 8;
	out = calloc(lcd_image_bytes(width, height), 1);
	if (out == NULL)
		return E_NOMEM;
	for (int32_t r = 0; r < height; r++) {
		const uint8_t *row = bmp + offset + (size_t)stride * (size_t)(top_down ? r : height - 1 - r);

		for (int32_t c = 0; c < width; c++) {
			bool black;

			if (bits <= 8) {
				uint32_t bit = (uint32_t)c * bits;
				uint32_t index = (row[bit / 8] >> (8 - bits - bit % 8)) & ((1U << bits) - 1U);

				/* an index past the palette is a broken file: show it black */
				black = index >= colours || dark(palette + 4U * index);
			} else {
				black = dark(row + (size_t)c * (bits / 8));
			}
			if (black)
				out[(size_t)r * out_stride + (size_t)c / 8] |= (uint8_t)(0x80U >> (c % 8));
		}
	}
	image->width = width;
	image->height = height;
	image->data = out;
	return E_OK;
}
