/*
 * ev3_lcd.h — the EV3's display: a Sitronix ST7586S controller on SPI1
 * (ST7586S data sheet; the wiring as LEGO's kernel board file and display
 * driver use it).  Host only.
 *
 * Wiring: SCL = SPI1_CLK, SI = SPI1_SIMO (PINMUX5 [11:8] and [23:20] = 1);
 * A0 (0 command, 1 data) = GP2_11, the SPI1_SOMI pad as a GPIO (PINMUX5
 * [19:16] = 8); chip select = GP2_12, active low (PINMUX5 [15:12] = 8);
 * RESET = GP5_0, active low (PINMUX12 [31:28] = 8).  The controller takes
 * 8-bit frames, MSB first, SPI mode 3 (on the AM1808: SPIFMT POLARITY = 1,
 * PHASE = 0, SHIFTDIR = 0); it latches a byte on its last clock with the
 * A0 level then, and only while the chip select has been low for the whole
 * frame.  A byte sent otherwise is dropped and counted; a byte in another
 * format is reported as a bug (the panel would see garbage).
 *
 * The model: the display data RAM of 128 column units × 160 rows, one byte
 * per unit holding three pixels (bits 7:5, 4:2, 1:0 from left to right);
 * commands 0x2A/0x2B (column/row window, 4 parameter bytes each: start and
 * end, high byte first), 0x2C (write RAM: the data bytes that follow fill
 * the window from its start, column first, wrapping to the window's start),
 * 0x28/0x29 (display off/on), 0x10/0x11 (sleep in/out), 0x20/0x21
 * (inversion off/on), 0x38/0x39 (monochrome mode off/on), 0x01 (software
 * reset); other commands and their parameters (power, bias, Vop, ...) are
 * accepted and counted.  RESET low resets the registers (display off,
 * sleeping, window 0..127 × 0..159) and drops the bytes sent meanwhile; the
 * RAM keeps its contents.
 *
 * The visible 178 × 128 panel shows column units 0..59 (pixels 0..177; 178
 * and 179 are padding) of rows 0..127.  A pixel is dark when the top bit of
 * its field (bit 7, 4 or 1) is set: LEGO's user space writes all bits of a
 * field for black, EV3RT's only the top two, and both satisfy the rule.
 * With the display off, asleep or in reset the panel is blank.  After
 * hs_board_shutdown the last state stays readable until the next boot.
 */
#ifndef HOST_SIM_DEVICES_EV3_LCD_H
#define HOST_SIM_DEVICES_EV3_LCD_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"

#define EV3_LCD_PANEL_WIDTH       178U
#define EV3_LCD_PANEL_HEIGHT      128U
#define EV3_LCD_RAM_COLS    128U        /* column units of three pixels */
#define EV3_LCD_RAM_ROWS    160U
#define EV3_LCD_SPI_BUS     1U
#define EV3_LCD_A0_PIN      HS_GPIO(2, 11)
#define EV3_LCD_CS_PIN      HS_GPIO(2, 12)
#define EV3_LCD_RESET_PIN   HS_GPIO(5, 0)

extern const struct hs_device ev3_lcd_device;

struct ev3_lcd_stats {
	uint32_t commands;          /* command bytes latched */
	uint32_t params;            /* parameter bytes latched */
	uint32_t ram_bytes;         /* data bytes written to the RAM */
	uint32_t frames;            /* write-RAM sequences that reached the window's end */
	uint32_t dropped;           /* bytes sent in reset or without the chip select */
	uint32_t resets;            /* hardware and software resets */
	uint64_t last_frame_ns;     /* when the last complete frame ended */
};
const struct ev3_lcd_stats *ev3_lcd_get_stats(void);

/* true while the panel shows the RAM (display on, awake, not in reset). */
bool ev3_lcd_display_on(void);
/* What the panel shows at (x, y): true = dark; false outside the panel. */
bool ev3_lcd_pixel(unsigned x, unsigned y);
/* The whole panel, row by row: 1 = dark, 0 = light. */
void ev3_lcd_pixels(uint8_t out[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH]);
/* A byte of the display data RAM (0 outside it). */
uint8_t ev3_lcd_ram(unsigned col, unsigned row);

#endif /* HOST_SIM_DEVICES_EV3_LCD_H */
