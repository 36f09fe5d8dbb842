/*
 * test_lcd.c — SPI1 and the ST7586S display model: LEGO's command framing
 * (A0 low for a command, high for each parameter and for the frame data,
 * chip select around each), the window and write-RAM commands, three pixels
 * a byte, the reset line, display on/off, bytes dropped without chip select,
 * frame timing at LEGO's 9.43 MHz, and SPI0 still answering beside SPI1.
 */
#include <string.h>
#include "devtest.h"
#include "host_sim/devices/spi.h"
#include "host_sim/devices/spi_adc.h"
#include "host_sim/devices/ev3_lcd.h"

#define SPI1 HS_SPI1_BASE

static void spi1_setup(uint32_t fmt)
{
	wr32(SPI1 + 0x00, 1);                   /* SPIGCR0: out of reset */
	wr32(SPI1 + 0x04, 3);                   /* SPIGCR1: master */
	wr32(SPI1 + 0x14, 0x0E00);              /* SPIPC0: SOMI, SIMO, CLK functional */
	wr32(SPI1 + 0x50, fmt);
	wr32(SPI1 + 0x48, 0x0A0A0000);          /* C2T 10, T2C 10 clocks */
	wr32(SPI1 + 0x04, 0x01000003);          /* enable */
}

/* One byte out, waiting for it to finish (RXEMPTY clears at the frame's end). */
static void spi1_byte(uint8_t b)
{
	wr32(SPI1 + 0x3C, b);
	while (rd32(SPI1 + 0x40) & (1U << 31))
		;
}

static void send(int a0, const uint8_t *b, size_t n)
{
	gpio_out(EV3_LCD_A0_PIN, a0);
	gpio_out(EV3_LCD_CS_PIN, 0);
	for (size_t i = 0; i < n; i++)
		spi1_byte(b[i]);
	gpio_out(EV3_LCD_CS_PIN, 1);
}

/* A command and its parameters, framed one byte per chip select as LEGO's driver does. */
static void cmd(uint8_t c, const uint8_t *p, size_t n)
{
	send(0, &c, 1);
	for (size_t i = 0; i < n; i++)
		send(1, &p[i], 1);
}

static void window(uint8_t xs, uint8_t xe, uint8_t ys, uint8_t ye)
{
	cmd(0x2A, (const uint8_t[]){ 0, xs, 0, xe }, 4);
	cmd(0x2B, (const uint8_t[]){ 0, ys, 0, ye }, 4);
}

static uint8_t frame[128 * 60];
static uint8_t px[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];

/* The expected pixels of frame (dark = top bit of a field). */
static bool frame_pixel(unsigned x, unsigned y)
{
	static const uint8_t bit[3] = { 0x80, 0x10, 0x02 };

	return (frame[y * 60 + x / 3] & bit[x % 3]) != 0;
}

int main(void)
{
	const uint32_t lego_fmt = (1U << 17) | (13U << 8) | 8U;   /* POLARITY, prescale 13, 8 bits */
	unsigned bad = 0;
	uint64_t t0, dt;
	uint32_t dropped;

	tap_plan(28);
	devtest_boot(5, NULL);
	ok(hs_psc_state(HS_PSC1_MODULE(HS_LPSC1_SPI1)) == HS_PSC_ENABLE, "SPI1 is powered as Linux leaves it");
	spi1_setup(lego_fmt);
	/* idle state of LEGO's driver: RESET high, A0 low, CS high */
	gpio_out(EV3_LCD_RESET_PIN, 1);
	gpio_out(EV3_LCD_A0_PIN, 0);
	gpio_out(EV3_LCD_CS_PIN, 1);
	ok(!ev3_lcd_display_on(), "the panel is blank before the init sequence");

	/* reset pulse */
	gpio_out(EV3_LCD_RESET_PIN, 0);
	rtos_host_run_for(10 * MS);
	{
		uint8_t b = 0x29;

		send(0, &b, 1);
	}
	is_int(ev3_lcd_get_stats()->dropped, 1, "a byte sent with RESET low is dropped");
	gpio_out(EV3_LCD_RESET_PIN, 1);
	rtos_host_run_for(120 * MS);
	cmd(0x11, NULL, 0);
	cmd(0x39, NULL, 0);
	cmd(0xC0, (const uint8_t[]){ 0xE3, 0x00 }, 2);
	ok(!ev3_lcd_display_on(), "display still off after sleep out");
	is_int(ev3_lcd_get_stats()->commands, 3, "three commands latched");
	is_int(ev3_lcd_get_stats()->params, 2, "two parameter bytes latched");

	/* RAM clear over the whole RAM, as LEGO's INIT does */
	window(0, 0x7F, 0, 0x9F);
	cmd(0x2C, NULL, 0);
	memset(frame, 0xFF, sizeof(frame));
	gpio_out(EV3_LCD_A0_PIN, 1);
	gpio_out(EV3_LCD_CS_PIN, 0);
	for (unsigned i = 0; i < 128U * 160U; i++)
		spi1_byte(0);
	gpio_out(EV3_LCD_CS_PIN, 1);
	is_int(ev3_lcd_get_stats()->frames, 1, "the RAM clear fills the window once");
	is_int(ev3_lcd_ram(127, 159), 0, "the last RAM byte is written");
	cmd(0x29, NULL, 0);
	ok(ev3_lcd_display_on(), "display on");
	ev3_lcd_pixels(px);
	{
		unsigned dark = 0;

		for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++)
			for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x++)
				dark += px[y][x];
		is_int(dark, 0, "a cleared RAM shows a white panel");
	}

	/* a frame push: window 0..59 x 0..127, then 7680 bytes in one chip-select period */
	for (unsigned i = 0; i < sizeof(frame); i++)
		frame[i] = (uint8_t)((i * 37U + i / 60U) ^ (i >> 3));
	window(0, 0x3B, 0, 0x7F);
	cmd(0x2C, NULL, 0);
	t0 = hs_now();
	send(1, frame, sizeof(frame));
	dt = hs_now() - t0;
	/* 8 bits at 132 MHz / 14 plus 22 clocks of chip-select delay: (8 * 14 + 22) / 132 MHz = 1.015 us
	 * a byte (7.80 ms), plus the CPU's two register accesses a byte */
	in_range((double)dt / 1e6, 7.80, 8.40, "7680 bytes at 9.43 MHz take %.2f ms", (double)dt / 1e6);
	is_int(ev3_lcd_get_stats()->frames, 2, "the frame fills its window");
	ev3_lcd_pixels(px);
	for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++)
		for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x++)
			bad += px[y][x] != frame_pixel(x, y);
	is_int(bad, 0, "all 178 x 128 pixels show the frame (3 pixels a byte, dark = top bit of each field)");
	is_int(ev3_lcd_pixel(0, 0), (frame[0] & 0x80) != 0, "pixel (0,0) is bit 7 of byte 0");
	ok(ev3_lcd_pixel(1, 0) == ((frame[0] & 0x10) != 0) && ev3_lcd_pixel(2, 0) == ((frame[0] & 0x02) != 0),
	   "pixels (1,0) and (2,0) are bits 4 and 1");
	ok(ev3_lcd_pixel(177, 127) == frame_pixel(177, 127) && !ev3_lcd_pixel(178, 0), "the panel ends at column 177");
	is_int(ev3_lcd_ram(60, 0), 0, "column unit 60 (off screen) is untouched");

	/* a small window: 2 units x 2 rows at (10, 20) */
	window(10, 11, 20, 21);
	cmd(0x2C, NULL, 0);
	send(1, (const uint8_t[]){ 0xE0, 0x1C, 0x03, 0x00 }, 4);
	ok(ev3_lcd_pixel(30, 20) && !ev3_lcd_pixel(31, 20) && ev3_lcd_pixel(34, 20) && ev3_lcd_pixel(32, 21),
	   "a 2 x 2 window is filled column first, then row (lms2012's 0xE0/0x1C/0x03 are black)");
	is_int(ev3_lcd_ram(10, 22), frame[22 * 60 + 10], "bytes stay inside the window");

	/* without chip select the panel ignores the bus */
	dropped = ev3_lcd_get_stats()->dropped;
	gpio_out(EV3_LCD_A0_PIN, 0);
	spi1_byte(0x28);
	is_int(ev3_lcd_get_stats()->dropped, dropped + 1, "a byte without chip select is dropped");
	ok(ev3_lcd_display_on(), "and did not switch the display off");

	/* inversion, display off */
	cmd(0x21, NULL, 0);
	ok(ev3_lcd_pixel(31, 20), "inversion shows a light pixel dark");
	cmd(0x20, NULL, 0);
	cmd(0x28, NULL, 0);
	ok(!ev3_lcd_display_on() && !ev3_lcd_pixel(30, 20), "display off: the panel is blank");

	/* a wrong frame format is a bug (16-bit frames, or mode 0) */
	spi1_setup((13U << 8) | 8U);
	rtos_host_expect_bugs(true);
	send(0, (const uint8_t[]){ 0x29 }, 1);
	rtos_host_expect_bugs(false);
	ok(rtos_host_bug_count() == 1 && strstr(rtos_host_last_bug(), "mode-3") != NULL,
	   "a mode-0 frame is reported: %s", rtos_host_last_bug());
	ok(!ev3_lcd_display_on(), "and not latched");

	/* RESET resets the registers but keeps the RAM */
	gpio_out(EV3_LCD_RESET_PIN, 0);
	gpio_out(EV3_LCD_RESET_PIN, 1);
	is_int(ev3_lcd_ram(10, 20), 0xE0, "RESET keeps the RAM");

	/* SPI0 and SPI1 are separate instances */
	ok(hs_spi_stats(1)->transfers > 20000U, "SPI1 counted its own transfers (%u)", hs_spi_stats(1)->transfers);
	is_int(ev3_spi_get_stats()->transfers, 0, "SPI0 saw none of them");
	return tap_done();
}
