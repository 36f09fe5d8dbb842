/*
 * test_ads7957_adc.c — ads7957_adc.c, an upstream-style IIO driver for the
 * EV3's analog-to-digital converter (a TI ADS7957 on SPI0), taken
 * unchanged, on host_sim's converter.  The hack's init gives the board's
 * part — SPI0 as bus 0, the converter on chip select 3 with the maps of an
 * input port's consumer as platform data — then runs the driver's init.
 * The test reads every channel as user space does, from
 * /sys/bus/iio/devices/iio:device0/in_voltage<n>_raw and in_voltage_scale,
 * and as a consumer driver does (iio_channel_get, iio_read_channel_raw and
 * _processed), against the voltages host_sim puts on the channels: input
 * port 1's pins with an NXT light sensor at two brightnesses, the battery.
 */
#define KBUILD_MODNAME "ads7957_adc"
#define LX_HACK_DRIVER_INIT adc_driver_init
#define LX_HACK_DRIVER_EXIT adc_driver_exit
#include "ads7957_adc.c"

#include "driver_common.h"

#include "tap.h"
#include "brick_test.h"
#include "rtos_host.h"
#include <linux/err.h>
#include <linux/iio/consumer.h>
#include <mach/spi.h>
#include <linux_compat/config.h>
#include <linux_compat/sysfs.h>
#include "host_sim/board.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ports.h"

static char pin1_label[8], pin6_label[8];

/* Input port 1's pins for its port driver ("ev3-in1"), as the board maps them. */
static struct iio_map port1_maps[] = {
	IIO_MAP(pin1_label, "ev3-in1", "pin1"),
	IIO_MAP(pin6_label, "ev3-in1", "pin6"),
	IIO_MAP("CH4", "ev3-battery", NULL),
	{ }
};

static struct spi_board_info board_adc = {
	.modalias = "ads7957", .bus_num = 0, .chip_select = 3, .max_speed_hz = 10000000,
	.mode = SPI_MODE_0, .platform_data = port1_maps,
};

static int __init hack_init(void)
{
	int ret;

	snprintf(pin1_label, sizeof(pin1_label), "CH%u", ev3_input_pins[0].adc_pin1);
	snprintf(pin6_label, sizeof(pin6_label), "CH%u", ev3_input_pins[0].adc_pin6);
	ret = da8xx_register_spi_bus(0, 4, NULL);
	if (!ret)
		ret = spi_register_board_info(&board_adc, 1);
	return ret ? ret : adc_driver_init();
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	adc_driver_exit();
	da8xx_unregister_spi_bus(0);
}
module_exit(hack_exit);

static struct device port1 = { .init_name = "ev3-in1" };
static struct device battery = { .init_name = "ev3-battery" };
static struct device stranger = { .init_name = "ev3-in9" };

/* The millivolts of code, as the scale says (5000 / 1024 mV per code). */
static unsigned int code_mv(int code)
{
	return (unsigned int)(code * 5000 / 1024);
}

/* Within two codes: host_sim's converter puts 5000 mV at code 1023, the
 * datasheet's 2 * VREF at 1024 codes, a code apart at the top of the range. */
static bool close_mv(unsigned int a, unsigned int b)
{
	return a + 10 >= b && b + 10 >= a;
}

static void body(void)
{
	struct iio_channel *pin1, *pin6, *batt;
	char path[64], text[32];
	unsigned int ch, good = 0;
	int raw, mv, n;

	n = (int)lx_sysfs_read("/sys/bus/iio/devices/iio:device0/name", text, sizeof(text) - 1);
	text[n > 0 ? n : 0] = '\0';
	is_str(text, "ads7957\n", "iio:device0/name");
	n = (int)lx_sysfs_read("/sys/bus/iio/devices/iio:device0/in_voltage_scale", text, sizeof(text) - 1);
	text[n > 0 ? n : 0] = '\0';
	is_str(text, "4.882812500\n", "in_voltage_scale: 5000 / 1024 mV (IIO_VAL_FRACTIONAL_LOG2)");

	ev3_attach_analog(0, EV3_INPUT_NXT_LIGHT, NULL);
	ev3_set_light(0, 30);
	msleep(5);
	for (ch = 0; ch < ADS7957_CHANNELS; ch++) {
		snprintf(path, sizeof(path), "/sys/bus/iio/devices/iio:device0/in_voltage%u_raw", ch);
		n = (int)lx_sysfs_read(path, text, sizeof(text) - 1);
		text[n > 0 ? n : 0] = '\0';
		if (n > 0 && close_mv(code_mv(simple_strtol(text, NULL, 10)), ev3_adc_channel_mv(ch)))
			good++;
		else
			tap_diag("channel %u: '%s' for %u mV", ch, text, ev3_adc_channel_mv(ch));
	}
	is_int(good, ADS7957_CHANNELS, "every in_voltage<n>_raw reads its channel's voltage");

	pin1 = iio_channel_get(&port1, "pin1");
	pin6 = iio_channel_get(&port1, "pin6");
	batt = iio_channel_get(&battery, NULL);
	ok(!IS_ERR(pin1) && !IS_ERR(pin6) && !IS_ERR(batt), "iio_channel_get through the board's maps");
	ok(PTR_ERR(iio_channel_get(&stranger, "pin1")) == -ENODEV, "a device without a map: -ENODEV");
	if (IS_ERR(pin1) || IS_ERR(pin6) || IS_ERR(batt))
		return;
	is_int(iio_read_channel_raw(pin1, &raw), IIO_VAL_INT, "iio_read_channel_raw");
	ok(close_mv(code_mv(raw), ev3_input_pin_mv(0, 1)), "pin 1 at 30 %% light: code %d for %u mV", raw,
	   ev3_input_pin_mv(0, 1));
	ev3_set_light(0, 80);
	msleep(5);
	is_int(iio_read_channel_processed(pin1, &mv), 0, "iio_read_channel_processed");
	ok(close_mv((unsigned int)mv, ev3_input_pin_mv(0, 1)), "pin 1 at 80 %%: %d mV for %u mV", mv,
	   ev3_input_pin_mv(0, 1));
	is_int(iio_read_channel_processed(batt, &mv), 0, "the battery channel");
	ok(close_mv((unsigned int)mv, ev3_adc_channel_mv(EV3_ADC_BATTERY_VOLTAGE)), "%d mV for %u mV", mv,
	   ev3_adc_channel_mv(EV3_ADC_BATTERY_VOLTAGE));
	iio_channel_release(pin6);
	iio_channel_release(batt);

	adc_driver_exit();
	is_int(iio_read_channel_raw(pin1, &raw), -ENODEV, "the driver gone: a held channel reads -ENODEV");
	is_int((int)lx_sysfs_read("/sys/bus/iio/devices/iio:device0/name", text, 8), -ENOENT,
	       "and iio:device0 is gone");
	iio_channel_release(pin1);
	is_int(adc_driver_init(), 0, "the driver again");
	is_int((int)lx_sysfs_read("/sys/bus/iio/devices/iio:device0/name", text, 8), 8, "iio:device0 again");
}

int main(void)
{
	tap_plan(17);
	lx_test_on_brick(body, "the simulated brick with its converter");
	return tap_done();
}
