/*
 * test_adc.c — SPI0 transfers in virtual time and the EV3's ADC answering
 * two frames late with the voltage each port pin has: identification
 * voltages of motors and analog devices as LEGO's d_analog.c detection rules
 * expect them, all read the way d_analog reads them (SPIDAT0/SPIBUF polls).
 */
#include "devtest.h"
#include "host_sim/devices/spi_adc.h"

#define SPI (HS_SPI0_BASE)

static uint16_t xfer(uint16_t cmd)
{
	while (rd32(SPI + 0x40) & (1U << 29))       /* TXFULL */
		;
	wr32(SPI + 0x38, cmd);
	for (;;) {
		uint32_t b = rd32(SPI + 0x40);

		if (!(b & (1U << 31)))                  /* RXEMPTY clear */
			return (uint16_t)b;
	}
}

/* Reads channel ch in the converter's 0-5 V range (range_5v) or its 0-2.5 V
 * range (command bit 6 clear), in mV as LEGO scales it (12 bits, 4095 =
 * 5000 mV); *chan_out gets bits 15-12. */
static unsigned read_mv_in_range(unsigned ch, bool range_5v, unsigned *chan_out)
{
	uint16_t w;

	xfer((uint16_t)(0x1800U | (range_5v ? 0x40U : 0U) | (ch << 7)));
	xfer(0x1840U);
	w = xfer(0x1840U);
	if (chan_out)
		*chan_out = w >> 12;
	return (unsigned)((w & 0xFFFU) * 5000U / 4095U);
}

/* Reads channel ch in the 0-5 V range, as d_analog does. */
static unsigned read_mv(unsigned ch, unsigned *chan_out)
{
	return read_mv_in_range(ch, true, chan_out);
}

static void spi_setup(void)
{
	wr32(SPI + 0x04, 3);                    /* SPIGCR1: master */
	wr32(SPI + 0x14, 0x0E08);               /* SPIPC0: SOMI, SIMO, CLK, SCS3 */
	wr32(SPI + 0x50, 0x00010010U | (74U << 8));     /* SPIFMT0: 16 bits, 2 MHz */
	wr32(SPI + 0x48, 0x0A0A0A0A);
	wr32(SPI + 0x08, 0);
	wr32(SPI + 0x4C, 8);
	wr32(SPI + 0x04, 0x01000003);           /* enable */
}

#define NEAR(got, want, tol, ...) in_range((double)(got), (double)(want) - (tol), (double)(want) + (tol), __VA_ARGS__)

int main(void)
{
	unsigned ch, mv, v1, v2;
	uint64_t t0, dt;
	const struct ev3_output_pins *a = &ev3_output_pins[0];

	tap_plan(33);
	devtest_boot(3, NULL);
	spi_setup();

	/* timing: 16 bits at 150 MHz / 75 = 2 MHz is 8 us plus chip-select delays */
	t0 = hs_now();
	xfer(0x400F);
	dt = hs_now() - t0;
	in_range(dt, 8000, 9000, "one 16-bit frame takes 8 us of virtual time (%llu ns)", (unsigned long long)dt);
	ok(ev3_spi_get_stats()->stalls >= 1, "the RXEMPTY poll stalled instead of spinning");

	/* pipeline: result of a selection arrives two frames later */
	xfer(0x1840U | (6U << 7));
	xfer(0x1840U | (13U << 7));
	{
		uint16_t w = xfer(0x1840U | (1U << 7));

		is_int(w >> 12, 6, "frame n+2 carries channel 6 selected in frame n");
		w = xfer(0x1840U);
		is_int(w >> 12, 13, "and the next one channel 13");
	}

	/* nothing connected */
	mv = read_mv(6, &ch);
	is_int(ch, 6, "channel bits");
	NEAR(mv, 5000, 10, "input 1 pin 1 open: pulled up to 5 V (> 4800: no event)");
	NEAR(read_mv(5, NULL), 0, 10, "input 1 pin 6 open: low");
	NEAR(read_mv(1, NULL), 2470, 10, "output A pin 5 open: 2.47 V (in 2400-2600)");
	NEAR(read_mv(15, NULL), 0, 10, "no motor current");
	NEAR(read_mv(4, NULL), 4444, 10, "battery channel: 9 V less the 0.1 A drops (0.5 ohm, shunt, diode), halved");
	NEAR(read_mv_in_range(1, false, NULL), 4940, 10, "0-2.5 V range: output A pin 5's 2.47 V reads twice as high");
	NEAR(read_mv_in_range(6, false, NULL), 4996, 1, "0-2.5 V range: input 1 pin 1's 5 V clamps at full scale");

	/* motors: ID voltage follows the encoder level */
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(1, HS_MOTOR_MEDIUM, &(struct hs_motor_options){ .start_deg = 0.6 });
	gpio_out(a->det_5w, 0);
	NEAR(read_mv(1, NULL), 160, 10, "large motor, encoder low: 0.16 V (< 250: TACHO)");
	NEAR(read_mv(0, NULL), 4210, 10, "medium motor, encoder high: 4.21 V (> 2600)");
	gpio_out(ev3_output_pins[1].det_5w, 1);
	v1 = read_mv(0, NULL);
	ok(v1 >= 1600 && v1 < 2000, "medium, encoder high, 5w pulled high: MINITACHO window (%u)", v1);
	ev3_detach_output(1);
	ev3_attach_motor(1, HS_MOTOR_LARGE, &(struct hs_motor_options){ .start_deg = 0.6 });
	v2 = read_mv(0, NULL);
	ok(v2 >= 2000, "large, encoder high, 5w pulled high: TACHO (%u)", v2);
	gpio_out(ev3_output_pins[1].det_5w, 0);
	NEAR(read_mv(0, NULL), 4480, 10, "large motor, encoder high: 4.48 V");
	ev3_detach_output(1);
	ev3_attach_motor(1, HS_MOTOR_MEDIUM, NULL);
	v1 = read_mv(0, NULL);
	NEAR(v1, 360, 10, "medium, encoder low: 0.36 V (250-450: MINITACHO)");
	gpio_out(ev3_output_pins[1].tacho_dir, 0);
	v2 = read_mv(0, NULL);
	ok(v1 > v2 ? v1 - v2 < 50 : v2 - v1 < 50, "pulling pin 6 low does not move a motor's pin 5 (< 50 mV)");
	gpio_float(ev3_output_pins[1].tacho_dir);

	/* analog input devices */
	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	mv = read_mv(6, NULL);
	ok(mv > 100 && mv < 3100, "EV3 touch: ID resistor on pin 1 in the DUMB window (%u)", mv);
	NEAR(read_mv(5, NULL), 0, 10, "EV3 touch released: pin 6 low");
	ev3_set_touch(0, true);
	NEAR(read_mv(5, NULL), 5000, 10, "EV3 touch pressed: pin 6 high");
	ok(gpio_in(ev3_input_pins[0].pin6), "and its GPIO reads 1");

	ev3_attach_analog(1, EV3_INPUT_NXT_TOUCH, NULL);
	ok(!gpio_in(ev3_input_pins[1].pin2), "NXT touch grounds pin 2 (LEGDET)");
	ok(read_mv(8, NULL) > 4800, "NXT touch released: pin 1 > 4800 mV (touch)");
	ev3_set_touch(1, true);
	mv = read_mv(8, NULL);
	ok(mv >= 850 && mv <= 950, "NXT touch pressed: 850-950 mV (%u)", mv);

	ev3_attach_analog(2, EV3_INPUT_NXT_LIGHT, NULL);
	ok(!gpio_in(ev3_input_pins[2].pin5) && !gpio_in(ev3_input_pins[2].pin2),
	   "NXT light: pin 2 and pin 5 low");

	is_int(ev3_attach_analog(3, EV3_INPUT_DUMB, &(struct ev3_analog_options){ .id_ohms = 4700 }), E_OK,
	       "dumb device with a 4.7 kOhm ID resistor");
	NEAR(read_mv(12, NULL), 1599, 12, "its pin 1: 5 V * 4.7k / 14.7k");

	is_int(ev3_attach_uart_sensor(3, UART_SENSOR_TYPE_COLOR, NULL), E_OK, "colour sensor on port 4");
	NEAR(read_mv(12, NULL), 0, 10, "UART sensor grounds pin 1 (< 100 mV: CONN_INPUT_UART)");

	/* ADC noise fault */
	{
		struct ev3_fault f = { EV3_FAULT_ADC_NOISE, 0, 30.0, 0 };
		unsigned lo = 9999, hi = 0;

		ev3_fault_at(hs_now() + MS, &f);
		hs_sim_run_for(2 * MS);
		for (int i = 0; i < 20; i++) {
			mv = read_mv(1, NULL);
			lo = mv < lo ? mv : lo;
			hi = mv > hi ? mv : hi;
		}
		ok(hi - lo > 20 && hi - lo < 300, "ADC noise fault spreads readings (%u..%u)", lo, hi);
	}

	/* a transfer with SPI0 held in reset is a loud bug, not a silent hang */
	rtos_host_expect_bugs(true);
	{
		uint_t before = rtos_host_bug_count();

		wr32(SPI + 0x00, 0);
		wr32(SPI + 0x38, 0x1840);
		ok(rtos_host_bug_count() == before + 1, "SPIDAT0 write in reset reported: %s", rtos_host_last_bug());
	}
	rtos_host_expect_bugs(false);
	hs_sim_shutdown();
	return tap_done();
}
