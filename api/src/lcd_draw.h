/*
 * lcd_draw.h — the LCD API's drawing core (not for applications): lines,
 * rectangles, text and 1-bit images drawn into any frame in the display's
 * format, clipped at its edges, and the BMP decoder.  No service calls and no
 * state, so the tests draw into plain memory.
 *
 * The frame is the ST7586 framebuffer as /dev/fb0 maps it: EV3_LCD_HEIGHT
 * rows of LCD_ROW_BYTES bytes, byte 0 top-left; each byte holds three pixels
 * left to right in bits 7:5, 4:2 and 1:0; black sets every bit of a pixel's
 * field (as LEGO's lms2012 writes it), white clears them.  Columns 178 and
 * 179 are padding and never drawn.
 *
 * Coordinates are int32_t, anywhere: what falls outside the frame is
 * clipped, and a clipped line or glyph draws exactly the pixels the whole
 * one would draw inside the frame.
 */
#ifndef EV3API_LCD_DRAW_H
#define EV3API_LCD_DRAW_H

#include <stdbool.h>
#include <stdint.h>
#include "ev3api_lcd.h"

#define LCD_ROW_BYTES   60      /* (178 + 2) / 3 */
#define LCD_FRAME_BYTES (LCD_ROW_BYTES * EV3_LCD_HEIGHT)

/* Whether the pixel at (x, y), inside the frame, is dark (any bit of its field set). */
bool lcd_pixel(const uint8_t *frame, int32_t x, int32_t y);

/* Fills w x h pixels from (x, y) with black or white; w or h <= 0 draws nothing. */
void lcd_fill(uint8_t *frame, int32_t x, int32_t y, int32_t w, int32_t h, bool black);

/* The line from (x0, y0) to (x1, y1), both ends included: along its longer
 * axis one pixel per step, the other coordinate rounded to the nearest (a
 * tie rounds up), so it is the same line drawn either way round. */
void lcd_line(uint8_t *frame, int32_t x0, int32_t y0, int32_t x1, int32_t y1, bool black);

/* A w x h 1-bit image (rows of (w + 7) / 8 bytes, bit 7 of a byte leftmost,
 * set = black) copied with its top-left at (x, y): white pixels paint white. */
void lcd_blit(uint8_t *frame, const uint8_t *bits, int32_t w, int32_t h, int32_t x, int32_t y);

/* ---- fonts (lcd_font.c) ---- */

/* A font's cell: characters advance by width, lines by height. */
void lcd_font_cell(lcdfont_t font, int32_t *width, int32_t *height);

/* Whether pixel (col, row) of character c's cell is ink.  Printable ASCII
 * (0x20..0x7E) has its glyph; any other byte shows a hollow box. */
bool lcd_font_ink(lcdfont_t font, unsigned char c, int32_t col, int32_t row);

/* Character c's cell with its top-left at (x, y): ink black, the rest white. */
void lcd_char(uint8_t *frame, lcdfont_t font, unsigned char c, int32_t x, int32_t y);

/* ---- images (lcd_bmp.c) ---- */

/* The bytes of a w x h 1-bit image; 0 when w or h is not positive or the
 * size does not fit in a size_t. */
size_t lcd_image_bytes(int32_t w, int32_t h);

/*
 * Decodes a Windows BMP of size bytes into image (data malloc'd, the format
 * of lcd_blit): uncompressed 1, 4, 8, 24 or 32 bits per pixel, bottom-up or
 * top-down; a pixel is black when its colour's luminance is below half.
 * E_PAR: not a BMP, truncated or inconsistent; E_NOSPT: compressed, another
 * depth or header; E_NOMEM.
 */
ER lcd_bmp_decode(const uint8_t *bmp, uint32_t size, image_t *image);

#endif /* EV3API_LCD_DRAW_H */
