/*
 * st7586.c — the EV3's display controller, a Sitronix ST7586S on SPI1 with
 * A0, chip select and reset on GPIOs (ev3_lcd.h for what is modelled).
 */
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/regs.h"
#include "host_sim/syscfg.h"
#include "host_sim/devices/spi.h"
#include "host_sim/devices/ev3_lcd.h"

/* ST7586S command codes (data sheet, "Command Table"). */
enum {
	CMD_SOFT_RESET = 0x01, CMD_SLEEP_IN = 0x10, CMD_SLEEP_OUT = 0x11,
	CMD_INVERT_OFF = 0x20, CMD_INVERT_ON = 0x21, CMD_DISPLAY_OFF = 0x28, CMD_DISPLAY_ON = 0x29,
	CMD_COLUMN_SET = 0x2A, CMD_ROW_SET = 0x2B, CMD_WRITE_RAM = 0x2C,
	CMD_MONO_OFF = 0x38, CMD_MONO_ON = 0x39,
};

#define VISIBLE_COLS  ((EV3_LCD_PANEL_WIDTH + 2U) / 3U)      /* 60 column units show 180 pixels */
/* SPIFMTn fields (AM1808 TRM, SPI chapter): CHARLEN [4:0], PHASE 16, POLARITY 17, SHIFTDIR 20. */
#define FMT_CHARLEN   0x1FU
#define FMT_PHASE     (1U << 16)
#define FMT_POLARITY  (1U << 17)
#define FMT_SHIFTDIR  (1U << 20)
/* PINMUX5 fields of the SPI1 pads the panel uses (AM1808 data manual, pin multiplexing). */
#define PINMUX_SPI1   5U
#define SHIFT_CLK     8U
#define SHIFT_SIMO    20U
#define FUNC_SPI1     1U

static struct {
	bool ready;
	int watch_reset;
	bool in_reset, display_on, sleeping, inverted, mono;
	bool cs_at_start;           /* chip select was low when the frame began */
	uint8_t cmd;                /* the last command, whose parameters follow */
	unsigned nparam;
	uint8_t param[4];
	unsigned xs, xe, ys, ye;    /* window, column units and rows */
	unsigned x, y;              /* write-RAM address */
	bool writing;               /* data bytes go to the RAM (after 0x2C) */
	uint8_t ram[EV3_LCD_RAM_ROWS][EV3_LCD_RAM_COLS];
	struct ev3_lcd_stats stats;
} lcd;

/* Register state after a hardware or software reset (data sheet, "Reset"). */
static void lcd_reset_registers(void)
{
	lcd.display_on = lcd.inverted = lcd.mono = lcd.writing = false;
	lcd.sleeping = true;
	lcd.cmd = 0;
	lcd.nparam = 0;
	lcd.xs = lcd.ys = 0;
	lcd.xe = EV3_LCD_RAM_COLS - 1U;
	lcd.ye = EV3_LCD_RAM_ROWS - 1U;
	lcd.x = lcd.y = 0;
	lcd.stats.resets++;
}

/* A window bound from two parameter bytes, clamped to the RAM (reported). */
static unsigned window_bound(const uint8_t *p, unsigned limit, const char *what)
{
	unsigned v = ((unsigned)p[0] << 8) | p[1];

	if (v >= limit) {
		rtos_host_trace("ST7586", "%s address %u beyond the RAM (max %u): clamped", what, v, limit - 1U);
		v = limit - 1U;
	}
	return v;
}

/* A parameter byte of the current command. */
static void lcd_param(uint8_t b)
{
	lcd.stats.params++;
	if (lcd.nparam < sizeof(lcd.param))
		lcd.param[lcd.nparam] = b;
	lcd.nparam++;
	if (lcd.nparam != 4U)
		return;
	if (lcd.cmd == CMD_COLUMN_SET) {
		lcd.xs = window_bound(&lcd.param[0], EV3_LCD_RAM_COLS, "column");
		lcd.xe = window_bound(&lcd.param[2], EV3_LCD_RAM_COLS, "column");
	} else if (lcd.cmd == CMD_ROW_SET) {
		lcd.ys = window_bound(&lcd.param[0], EV3_LCD_RAM_ROWS, "row");
		lcd.ye = window_bound(&lcd.param[2], EV3_LCD_RAM_ROWS, "row");
	}
}

/* A data byte after write-RAM: stored at the address, which then advances in the window. */
static void lcd_ram_write(uint8_t b)
{
	lcd.ram[lcd.y][lcd.x] = b;
	lcd.stats.ram_bytes++;
	if (lcd.x < lcd.xe) {
		lcd.x++;
		return;
	}
	lcd.x = lcd.xs;
	if (lcd.y < lcd.ye) {
		lcd.y++;
		return;
	}
	lcd.y = lcd.ys;
	lcd.stats.frames++;
	lcd.stats.last_frame_ns = hs_now();
}

/* A command byte. */
static void lcd_command(uint8_t c)
{
	lcd.stats.commands++;
	lcd.cmd = c;
	lcd.nparam = 0;
	lcd.writing = false;
	switch (c) {
	case CMD_SOFT_RESET: lcd_reset_registers(); break;
	case CMD_SLEEP_IN: lcd.sleeping = true; break;
	case CMD_SLEEP_OUT: lcd.sleeping = false; break;
	case CMD_INVERT_OFF: lcd.inverted = false; break;
	case CMD_INVERT_ON: lcd.inverted = true; break;
	case CMD_DISPLAY_OFF: lcd.display_on = false; break;
	case CMD_DISPLAY_ON: lcd.display_on = true; break;
	case CMD_MONO_OFF: lcd.mono = false; break;
	case CMD_MONO_ON: lcd.mono = true; break;
	case CMD_WRITE_RAM:
		lcd.writing = true;
		lcd.x = lcd.xs;
		lcd.y = lcd.ys;
		break;
	default: break;             /* power, bias, Vop, scan direction, ...: no effect on the picture */
	}
}

/* SPI1 frame start: the chip select must already be low. */
static uint16_t lcd_frame(void *ctx, uint16_t word)
{
	(void)ctx; (void)word;
	lcd.cs_at_start = !hs_gpio_level(EV3_LCD_CS_PIN);
	return 0;                   /* write-only: SOMI is the A0 GPIO */
}

/* SPI1 frame end: the controller latches the byte with A0. */
static void lcd_frame_done(void *ctx, uint16_t word)
{
	uint32_t fmt = hs_spi_format(EV3_LCD_SPI_BUS);
	bool selected = lcd.cs_at_start && !hs_gpio_level(EV3_LCD_CS_PIN);

	(void)ctx;
	if (!selected || lcd.in_reset) {
		lcd.stats.dropped++;
		rtos_host_trace("ST7586", "byte 0x%02x dropped: %s", word & 0xFFU,
				lcd.in_reset ? "in reset" : "chip select not low for the whole frame");
		return;
	}
	if ((fmt & FMT_CHARLEN) != 8U || !(fmt & FMT_POLARITY) || (fmt & (FMT_PHASE | FMT_SHIFTDIR)) ||
	    hs_syscfg_pinmux_field(PINMUX_SPI1, SHIFT_CLK) != FUNC_SPI1 ||
	    hs_syscfg_pinmux_field(PINMUX_SPI1, SHIFT_SIMO) != FUNC_SPI1) {
		lcd.stats.dropped++;
		rtos_host_bug("host_sim", "ST7586: frame 0x%04x with SPIFMT 0x%08x, PINMUX5 0x%08x: the controller "
			      "needs 8-bit MSB-first mode-3 frames (POLARITY=1, PHASE=0) on SPI1_CLK/SPI1_SIMO",
			      word, fmt, hs_syscfg_pinmux(PINMUX_SPI1));
		return;
	}
	if (!hs_gpio_level(EV3_LCD_A0_PIN))
		lcd_command((uint8_t)word);
	else if (lcd.writing)
		lcd_ram_write((uint8_t)word);
	else
		lcd_param((uint8_t)word);
}

/* RESET low: registers to their reset state, bytes dropped until it rises. */
static void reset_changed(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	(void)ctx; (void)pin;
	if (!st->level && !lcd.in_reset)
		lcd_reset_registers();
	lcd.in_reset = !st->level;
}

const struct ev3_lcd_stats *ev3_lcd_get_stats(void)
{
	return &lcd.stats;
}

bool ev3_lcd_display_on(void)
{
	return lcd.ready && lcd.display_on && !lcd.sleeping && !lcd.in_reset;
}

uint8_t ev3_lcd_ram(unsigned col, unsigned row)
{
	return col < EV3_LCD_RAM_COLS && row < EV3_LCD_RAM_ROWS ? lcd.ram[row][col] : 0;
}

bool ev3_lcd_pixel(unsigned x, unsigned y)
{
	static const uint8_t dark_bit[3] = { 0x80, 0x10, 0x02 };

	if (x >= EV3_LCD_PANEL_WIDTH || y >= EV3_LCD_PANEL_HEIGHT || !ev3_lcd_display_on())
		return false;
	return ((lcd.ram[y][x / 3U] & dark_bit[x % 3U]) != 0) != lcd.inverted;
}

void ev3_lcd_pixels(uint8_t out[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH])
{
	for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++)
		for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x++)
			out[y][x] = ev3_lcd_pixel(x, y);
}

/* Sets a PINMUX field as the board code does (SYSCFG0 written directly, no unlock needed here). */
static void mux_field(unsigned n, unsigned shift, unsigned func)
{
	struct hs_region *syscfg0 = hs_region_by_name("SYSCFG0");

	if (syscfg0)
		hs_reg_update(syscfg0, 0x120U + 4U * n, 0xFU << shift, func << shift);
}

/* Connects the controller to SPI1 and its GPIOs, powered up and held in reset by nothing. */
static ER lcd_create(const struct hs_board_cfg *cfg, void **ctx)
{
	memset(&lcd, 0, sizeof(lcd));
	if (!(cfg && cfg->cold_reset)) {
		/* the board code's pin setup, as LEGO's kernel leaves it */
		mux_field(PINMUX_SPI1, SHIFT_CLK, FUNC_SPI1);
		mux_field(PINMUX_SPI1, SHIFT_SIMO, FUNC_SPI1);
		hs_gpio_mux_as_gpio(EV3_LCD_A0_PIN);
		hs_gpio_mux_as_gpio(EV3_LCD_CS_PIN);
		hs_gpio_mux_as_gpio(EV3_LCD_RESET_PIN);
	}
	/* the panel's RESET line idles high through its pull-up until the SoC drives it */
	hs_gpio_drive(EV3_LCD_RESET_PIN, HS_EXT_PULL_UP);
	hs_gpio_drive(EV3_LCD_CS_PIN, HS_EXT_PULL_UP);
	lcd.watch_reset = hs_gpio_watch(EV3_LCD_RESET_PIN, reset_changed, NULL);
	if (!lcd.watch_reset)
		return E_NOMEM;
	lcd_reset_registers();
	lcd.stats.resets = 0;
	lcd.in_reset = !hs_gpio_level(EV3_LCD_RESET_PIN);
	hs_spi_connect(EV3_LCD_SPI_BUS, &(struct hs_spi_peer){ .frame = lcd_frame, .frame_done = lcd_frame_done });
	lcd.ready = true;
	*ctx = &lcd;
	return E_OK;
}

static void lcd_destroy(void *ctx)
{
	(void)ctx;
	hs_gpio_unwatch(lcd.watch_reset);
	hs_spi_connect(EV3_LCD_SPI_BUS, NULL);
	/* the panel keeps its last picture readable after shutdown (a test reads it then) */
}

const struct hs_device ev3_lcd_device = { "ST7586", lcd_create, NULL, lcd_destroy };
