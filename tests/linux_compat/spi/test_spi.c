/*
 * test_spi.c — the SPI core and the DaVinci SPI controller.  Core: a test
 * controller records what it is asked to shift; board devices declared
 * before their controller, drivers bound by id_table and by name,
 * spi_get_device_id, probe failure, remove on unregister, the chip select
 * around a message and between cs_change transfers, argument errors.
 * Controller: SPI1 on host_sim with the EV3's display behind it — mode 3 at
 * 10 MHz becomes SPIFMT0 prescale 13 with POLARITY, the chip select GPIO
 * frames the message, the bytes reach the ST7586 model and take 1.015 us each.
 */
#include "lx_test.h"
#include <linux/delay.h>
#include <linux/gpio.h>
#include <linux/spi/spi.h>
#include <linux/platform_data/spi-davinci.h>
#include <mach/spi.h>
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/devices/spi.h"
#include "host_sim/devices/ev3_lcd.h"

#define TEST_BUS 3

static char shifted[256];
static unsigned int nshifted;

static void log_cs(struct spi_device *spi, bool level)
{
	if (nshifted < sizeof(shifted) - 1)
		shifted[nshifted++] = level ? ']' : '[';
}

static int test_transfer_one(struct spi_controller *ctlr, struct spi_device *spi, struct spi_transfer *t)
{
	const u8 *tx = t->tx_buf;
	u8 *rx = t->rx_buf;
	unsigned int i;

	for (i = 0; i < t->len; i++) {
		if (nshifted < sizeof(shifted) - 1)
			shifted[nshifted++] = tx ? (char)tx[i] : '.';
		if (rx)
			rx[i] = (u8)(0xA0 + i);
	}
	return 0;
}

static int probes, removes;
static struct spi_device *probed;

static int dev_probe(struct spi_device *spi)
{
	probes++;
	probed = spi;
	return strcmp(spi->modalias, "broken") ? 0 : -EIO;
}

static void dev_remove(struct spi_device *spi)
{
	removes++;
}

static const struct spi_device_id test_ids[] = {
	{ "lms2012_lcd", 7 },
	{ "broken", 0 },
	{ }
};

static struct spi_driver by_id = {
	.id_table = test_ids, .probe = dev_probe, .remove = dev_remove, .driver = { .name = "by_id" },
};
static struct spi_driver by_name = {
	.probe = dev_probe, .remove = dev_remove, .driver = { .name = "plain" },
};
static struct spi_driver dup = { .driver = { .name = "by_id" } };

static void core_tests(void)
{
	static const struct spi_board_info board[] = {
		{ .modalias = "lms2012_lcd", .bus_num = TEST_BUS, .chip_select = 0, .max_speed_hz = 1000000,
		  .mode = SPI_MODE_3 },
	};
	struct spi_controller *ctlr = spi_alloc_master(NULL, 16);
	struct spi_transfer xfers[3] = {
		{ .tx_buf = "ab", .len = 2, .cs_change = 1 },
		{ .tx_buf = "cd", .len = 2 },
		{ .rx_buf = NULL, .len = 0 },
	};
	struct spi_message msg;
	struct spi_device *plain, *broken;
	u8 rx[2];

	ok(ctlr != NULL && spi_controller_get_devdata(ctlr) != NULL, "spi_alloc_master with driver data");
	ctlr->bus_num = TEST_BUS;
	ctlr->num_chipselect = 2;
	ctlr->transfer_one = test_transfer_one;
	ctlr->set_cs = log_cs;
	ctlr->mode_bits = SPI_NO_CS;
	is_int(spi_register_board_info(board, 1), 0, "board info declared before the controller");
	is_int(spi_register_driver(&by_id), 0, "driver registered");
	is_int(probes, 0, "nothing to probe yet");
	is_int(spi_register_controller(ctlr), 0, "controller registered");
	is_int(probes, 1, "the board's device was created and probed");
	ok(probed && probed->mode == SPI_MODE_3 && probed->max_speed_hz == 1000000 && probed->bits_per_word == 8,
	   "with the board's mode and speed, 8 bits");
	is_str(dev_name(&probed->dev), "spi3.0", "named spi<bus>.<cs>");
	is_int(spi_get_device_id(probed)->driver_data, 7, "spi_get_device_id finds the id_table entry");
	is_int(spi_register_driver(&dup), -EBUSY, "a second driver of the same name: -EBUSY");

	nshifted = 0;
	is_int(spi_write(probed, "xyz", 3), 0, "spi_write");
	shifted[nshifted] = '\0';
	is_str(shifted, "[xyz]", "chip select asserted (low) around the bytes");
	nshifted = 0;
	spi_message_init_with_transfers(&msg, xfers, 2);
	is_int(spi_sync(probed, &msg), 0, "spi_sync of two transfers");
	shifted[nshifted] = '\0';
	is_str(shifted, "[ab][cd]", "cs_change releases the chip select between them");
	is_int(msg.actual_length, 4, "actual_length");
	xfers[0].cs_change = 0;
	nshifted = 0;
	is_int(spi_read(probed, rx, 2), 0, "spi_read");
	ok(rx[0] == 0xA0 && rx[1] == 0xA1, "gets what the controller shifted in");

	spi_message_init(&msg);
	is_int(spi_sync(probed, &msg), -EINVAL, "an empty message: -EINVAL");
	xfers[2].len = 4;
	spi_message_init_with_transfers(&msg, &xfers[2], 1);
	is_int(spi_sync(probed, &msg), -EINVAL, "a transfer without buffers: -EINVAL");
	xfers[1].bits_per_word = 12;
	spi_message_init_with_transfers(&msg, &xfers[1], 1);
	is_int(spi_sync(probed, &msg), -EINVAL, "12-bit words the controller lacks: -EINVAL");
	is_int(spi_sync(NULL, &msg), -EINVAL, "NULL device: -EINVAL");

	plain = spi_new_device(ctlr, &(struct spi_board_info){ .modalias = "plain", .bus_num = TEST_BUS,
							      .chip_select = 1 });
	ok(plain && !plain->dev.driver, "spi_new_device without a matching driver stays unbound");
	is_int(spi_register_driver(&by_name), 0, "a driver without id_table");
	ok(plain->dev.driver == &by_name.driver, "binds by driver name");
	ok(spi_new_device(ctlr, &(struct spi_board_info){ .modalias = "x", .chip_select = 2 }) == NULL,
	   "a chip select beyond num_chipselect is refused");
	ok(spi_new_device(ctlr, &(struct spi_board_info){ .modalias = "x", .chip_select = 1 }) == NULL,
	   "a chip select in use is refused");
	spi_unregister_device(plain);
	broken = spi_new_device(ctlr, &(struct spi_board_info){ .modalias = "broken", .chip_select = 1 });
	ok(broken && !broken->dev.driver && !spi_get_drvdata(broken), "a failed probe leaves the device unbound");
	spi_unregister_device(broken);

	removes = 0;
	spi_unregister_driver(&by_id);
	is_int(removes, 1, "unregistering the driver removes its device");
	spi_unregister_driver(&by_name);
	spi_unregister_controller(ctlr);
}

#define LCD_A0	GPIO_TO_PIN(2, 11)
#define LCD_CS	GPIO_TO_PIN(2, 12)
#define LCD_RST	GPIO_TO_PIN(5, 0)

static void davinci_tests(void)
{
	static const int cs_gpios[] = { LCD_CS };
	static struct davinci_spi_config lcd_cfg = { .c2tdelay = 10, .t2cdelay = 10 };
	static u8 frame[60 * 128];
	struct spi_device *lcd;
	uint64_t t0, dt;
	unsigned int i, bad = 0;

	is_int(da8xx_register_spi_bus(2, 1, NULL), -EINVAL, "no SPI2 on the AM1808");
	is_int(da8xx_register_spi_bus(1, 1, cs_gpios), 0, "SPI1 registered as bus 1, chip select GP2_12");
	is_int(da8xx_register_spi_bus(1, 1, cs_gpios), -EBUSY, "only once");
	lcd = spi_new_device(NULL, NULL);
	ok(lcd == NULL, "spi_new_device(NULL) refused");
	{
		static const struct spi_board_info info = {
			.modalias = "lms2012_lcd", .bus_num = 1, .chip_select = 0, .max_speed_hz = 10000000,
			.mode = SPI_MODE_3, .controller_data = &lcd_cfg,
		};
		is_int(spi_register_board_info(&info, 1), 0, "the display declared on bus 1");
	}
	is_int(spi_register_driver(&by_id), 0, "driver");
	lcd = probed;
	ok(lcd && lcd->controller->bus_num == 1, "the display probed on SPI1");
	ok(lcd->max_speed_hz == 10000000, "at 10 MHz");
	is_int(gpio_get_value(LCD_CS), 1, "chip select idles high");

	gpio_direction_output(LCD_RST, 0);
	udelay(10);
	gpio_set_value(LCD_RST, 1);
	gpio_direction_output(LCD_A0, 0);
	is_int(spi_write(lcd, (const u8[]){ 0x11 }, 1), 0, "sleep out");
	is_int((int)hs_spi_format(1), (int)((1U << 17) | (13U << 8) | 8U),
	       "SPIFMT0: POLARITY, PHASE 0 (mode 3), prescale ceil(132/10)-1 = 13, 8 bits");
	spi_write(lcd, (const u8[]){ 0x2A }, 1);
	gpio_set_value(LCD_A0, 1);
	spi_write(lcd, (const u8[]){ 0, 0, 0, 59 }, 4);
	gpio_set_value(LCD_A0, 0);
	spi_write(lcd, (const u8[]){ 0x2B }, 1);
	gpio_set_value(LCD_A0, 1);
	spi_write(lcd, (const u8[]){ 0, 0, 0, 127 }, 4);
	gpio_set_value(LCD_A0, 0);
	spi_write(lcd, (const u8[]){ 0x2C }, 1);
	gpio_set_value(LCD_A0, 1);
	for (i = 0; i < sizeof(frame); i++)
		frame[i] = (u8)(i * 7 + i / 60);
	t0 = hs_now();
	is_int(spi_write(lcd, frame, sizeof(frame)), 0, "a 7680-byte frame in one spi_write");
	dt = hs_now() - t0;
	in_range((double)dt / 1e6, 7.8, 8.6, "takes %.2f ms (1.015 us a byte at 9.43 MHz plus the polling)",
		 (double)dt / 1e6);
	gpio_set_value(LCD_A0, 0);
	spi_write(lcd, (const u8[]){ 0x29 }, 1);
	is_int(ev3_lcd_get_stats()->dropped, 0, "no byte dropped: the chip select framed every message");
	is_int(ev3_lcd_get_stats()->frames, 1, "the model saw one complete frame");
	for (i = 0; i < sizeof(frame); i++)
		bad += ev3_lcd_ram(i % 60, i / 60) != frame[i];
	is_int(bad, 0, "the display RAM holds the frame byte for byte");
	ok(ev3_lcd_display_on(), "display on");
	spi_unregister_driver(&by_id);
	da8xx_unregister_spi_bus(1);
	is_int(da8xx_register_spi_bus(1, 1, cs_gpios), 0, "SPI1 can be registered again after unregistering");
	da8xx_unregister_spi_bus(1);
}

static void body(void)
{
	core_tests();
	davinci_tests();
}

int main(void)
{
	static const struct hs_device *const devices[] = { &hs_spi1_device, &ev3_lcd_device, NULL };
	struct hs_board_cfg board = { .devices = devices };

	tap_plan(48);
	is_int(hs_board_init(&board), E_OK, "host_sim board with SPI1 and the display");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
