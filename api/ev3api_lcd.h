/*
 * ev3api_lcd.h — the LCD (included by ev3api.h), EV3RT's interface, over
 * the st7586fb frame buffer driver: small font 6 x 8, medium 12 x 16, BMP
 * images of 1, 4, 8, 24 or 32 bits (dark below half luminance).
 */
#ifndef EV3API_LCD_H
#define EV3API_LCD_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdint.h>
#include "kernel.h"
#include "ev3api_fs.h"

#define EV3_LCD_WIDTH   178
#define EV3_LCD_HEIGHT  128

typedef enum {
	EV3_FONT_SMALL = 0, EV3_FONT_MEDIUM = 1
} lcdfont_t;

typedef enum {
	EV3_LCD_WHITE = 0, EV3_LCD_BLACK = 1
} lcdcolor_t;

typedef struct {
	int32_t width, height;
	void *data;
} image_t;


/* Every call returns E_OK or: E_ID (a font other than SMALL/MEDIUM), E_PAR
 * (a colour other than WHITE/BLACK, a NULL string/image/file, an image
 * without data or size, a file that is not a supported BMP), E_NOSPT (a
 * compressed BMP or another depth), E_MACV (memory the task may not access),
 * E_NOMEM, E_CTX (a drawing call outside a task that may wait), E_OBJ (no
 * display; ev3_image_free: nothing loaded).  Drawing is clipped at the
 * panel's edges; what a call drew is on the panel within 40 ms. */
ER ev3_lcd_set_font(lcdfont_t font);
ER ev3_font_get_size(lcdfont_t font, int32_t *p_width, int32_t *p_height);
ER ev3_lcd_draw_string(const char *str, int32_t x, int32_t y);
ER ev3_lcd_draw_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1);
ER ev3_lcd_fill_rect(int32_t x, int32_t y, int32_t w, int32_t h, lcdcolor_t color);
ER ev3_lcd_draw_image(const image_t *image, int32_t x, int32_t y);
ER ev3_image_load(const memfile_t *file, image_t *image);
ER ev3_image_free(image_t *image);

#ifdef __cplusplus
}
#endif

#endif /* EV3API_LCD_H */
