/*
 * lcd.c — EV3RT's LCD calls (ev3api_lcd.h) over st7586fb: the API draws into
 * its frame in the driver's format (lcd_draw.c), and each call that changed
 * it hands the frame to the driver through lcd_hack (a write() of /dev/fb0,
 * on the panel within FB_ST7586_REFRESH_MS).  The display is started at
 * boot, as EV3RT's platform starts it before the app runs (api_lcd_task): a drawing call never waits for the panel's
 * start-up, and what an app draws before the panel is up is shown when it is.
 */
#include <stdlib.h>
#include <string.h>
#include "ev3api_fs.h"
#include "ev3api_lcd.h"
#include "ev3api_speaker.h"
#include "rtos_cfg.h"
#include "api_internal.h"
#include "lcd_draw.h"
#include "lcd_hack.h"

_Static_assert(LCD_FRAME_BYTES == FB_ST7586_SIZE, "the API's frame is the driver's");
_Static_assert(EV3_LCD_WIDTH == FB_ST7586_WIDTH && EV3_LCD_HEIGHT == FB_ST7586_HEIGHT,
	       "EV3RT's LCD size is the panel's");

/* The frame every task draws into; the user domains may read and write it
 * (ev3api_cfg's memory rows), as the write() handing it to the driver checks. */
uint8_t api_lcd_frame[LCD_FRAME_BYTES] __attribute__((aligned(32))) EV3LX_SHARED_RW;
#define lcd_frame api_lcd_frame
static lcdfont_t lcd_font;
static bool lcd_ready;

void api_lcd_boot(void)
{
	memset(lcd_frame, 0, sizeof(lcd_frame));
	lcd_font = EV3_FONT_SMALL;
	lcd_ready = false;
}

static bool font_valid(lcdfont_t font)
{
	return font == EV3_FONT_SMALL || font == EV3_FONT_MEDIUM;
}

/* A drawing call may start: task context. */
static ER lcd_begin(void)
{
	return api_may_wait();
}

/* The frame to the driver after a change; until the panel is up, the frame
 * is kept and api_lcd_task shows it. */
static ER lcd_show(void)
{
	return lcd_ready ? lcd_svc_update(lcd_frame, sizeof(lcd_frame)) : E_OK;
}

/* The LCD task (CRE_TSK EV3_LCD_TSKID in config.c), at boot: starts the
 * panel (LEGO's INIT, then START: ~310 ms of the st7586's start-up), then
 * shows what was drawn meanwhile, and ends. */
void api_lcd_task(intptr_t exinf)
{
	ER ercd;

	(void)exinf;
	if (lcd_ready)
		return;
	ercd = lcd_svc_init();
	if (ercd == E_RSFN)
		return;         /* a configuration without the LCD's driver */
	if (ercd != E_OK) {
		syslog(LOG_WARNING, "ev3api: the LCD did not start (%d)", (int)ercd);
		return;
	}
	lcd_ready = true;
	lcd_show();
}

ER ev3_lcd_set_font(lcdfont_t font)
{
	if (!font_valid(font))
		return E_ID;
	lcd_font = font;
	return E_OK;
}

ER ev3_font_get_size(lcdfont_t font, int32_t *p_width, int32_t *p_height)
{
	int32_t w, h;
	ER ercd;

	if (!font_valid(font))
		return E_ID;
	if ((p_width && (ercd = API_CHECK_OUT(p_width)) != E_OK) ||
	    (p_height && (ercd = API_CHECK_OUT(p_height)) != E_OK))
		return ercd;
	lcd_font_cell(font, &w, &h);
	if (p_width)
		*p_width = w;
	if (p_height)
		*p_height = h;
	return E_OK;
}

ER ev3_lcd_draw_string(const char *str, int32_t x, int32_t y)
{
	int32_t w, h;
	ER ercd;

	if (str == NULL)
		return E_PAR;
	if (!sns_ctx() && prb_mem(str, 1, TSK_SELF, TPM_READ) != E_OK)
		return E_MACV;
	if ((ercd = lcd_begin()) != E_OK)
		return ercd;
	lcd_font_cell(lcd_font, &w, &h);
	for (const unsigned char *c = (const unsigned char *)str; *c; c++) {
		lcd_char(lcd_frame, lcd_font, *c, x, y);
		if (x > EV3_LCD_WIDTH)
			break;          /* the rest is off the panel */
		x += w;
	}
	return lcd_show();
}

ER ev3_lcd_draw_line(int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
	ER ercd = lcd_begin();

	if (ercd != E_OK)
		return ercd;
	lcd_line(lcd_frame, x0, y0, x1, y1, true);
	return lcd_show();
}

ER ev3_lcd_fill_rect(int32_t x, int32_t y, int32_t w, int32_t h, lcdcolor_t color)
{
	ER ercd;

	if (color != EV3_LCD_WHITE && color != EV3_LCD_BLACK)
		return E_PAR;
	if ((ercd = lcd_begin()) != E_OK)
		return ercd;
	lcd_fill(lcd_frame, x, y, w, h, color == EV3_LCD_BLACK);
	return lcd_show();
}

ER ev3_lcd_draw_image(const image_t *image, int32_t x, int32_t y)
{
	size_t bytes;
	ER ercd;

	if (image == NULL)
		return E_PAR;
	if (!sns_ctx() && prb_mem(image, sizeof(*image), TSK_SELF, TPM_READ) != E_OK)
		return E_MACV;
	bytes = lcd_image_bytes(image->width, image->height);
	/* the bits are read by this code in the caller's context, as the caller could read them
	 * (ev3_image_load's malloc'd data is the task's own memory, outside prb_mem's areas) */
	if (image->data == NULL || bytes == 0)
		return E_PAR;
	if ((ercd = lcd_begin()) != E_OK)
		return ercd;
	lcd_blit(lcd_frame, image->data, image->width, image->height, x, y);
	return lcd_show();
}

ER ev3_image_load(const memfile_t *file, image_t *image)
{
	ER ercd;

	if ((ercd = API_CHECK_OUT(image)) != E_OK)
		return ercd;
	/* as EV3RT's: a failed load leaves an empty image, which draws nothing
	 * (E_PAR), never the caller's stale bytes */
	image->data = NULL;
	image->width = image->height = 0;
	if (file == NULL || file->buffer == NULL)
		return E_PAR;
	if (!sns_ctx() && prb_mem(file->buffer, file->filesz, TSK_SELF, TPM_READ) != E_OK)
		return E_MACV;
	return lcd_bmp_decode(file->buffer, file->filesz, image);
}

ER ev3_image_free(image_t *image)
{
	ER ercd = API_CHECK_OUT(image);

	if (ercd != E_OK)
		return ercd;
	if (image->data == NULL)
		return E_OBJ;
	free(image->data);
	image->data = NULL;
	image->width = image->height = 0;
	return E_OK;
}
