/*
 * ev3api_lcd.h — the LCD (included by ev3api.h), EV3RT's interface.  ev3lx
 * has no display driver yet: every call is EV3API_NOT_YET (an app using one
 * compiles and fails to link, naming the call).
 */
#ifndef EV3API_LCD_H
#define EV3API_LCD_H

#include <stdint.h>
#include "kernel.h"
#include "ev3api_fs.h"
#include "ev3api_not_yet.h"

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


ER ev3_lcd_set_font(lcdfont_t font) EV3API_NOT_YET(lcd, ev3_lcd_set_font);
ER ev3_font_get_size(lcdfont_t font, int32_t *p_width, int32_t *p_height)
	EV3API_NOT_YET(lcd, ev3_font_get_size);
ER ev3_lcd_draw_string(const char *str, int32_t x, int32_t y)
	EV3API_NOT_YET(lcd, ev3_lcd_draw_string);
ER ev3_lcd_draw_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1)
	EV3API_NOT_YET(lcd, ev3_lcd_draw_line);
ER ev3_lcd_fill_rect(int32_t x, int32_t y, int32_t w, int32_t h, lcdcolor_t color)
	EV3API_NOT_YET(lcd, ev3_lcd_fill_rect);
ER ev3_lcd_draw_image(const image_t *image, int32_t x, int32_t y)
	EV3API_NOT_YET(lcd, ev3_lcd_draw_image);
ER ev3_image_load(const memfile_t *file, image_t *image)
	EV3API_NOT_YET(lcd, ev3_image_load);
ER ev3_image_free(image_t *image) EV3API_NOT_YET(lcd, ev3_image_free);

#endif /* EV3API_LCD_H */
