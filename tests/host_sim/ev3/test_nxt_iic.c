/*
 * test_nxt_iic.c — the NXT I2C bus model at waveform level, driven by a
 * test-side master that bit-bangs the port pins through the GPIO registers
 * (SCL through the TX buffer from the SCL pad, SDA open-drain on pin 6):
 * the identification strings through a repeated START and through LEGO's
 * STOP/START turnaround, ACK/NACK of addresses and register pointers, a
 * START or STOP in the middle of a byte, the temperature sensor's pointer,
 * configuration and 12-bit reading, what detection sees on the pins, SCL
 * never held by the slave, unplug and replug; then TIMER64P1's period
 * interrupt on AINTC 24.
 */
#include <string.h>
#include "devtest.h"
#include "host_sim/intc.h"
#include "host_sim/trace.h"
#include "host_sim/devices/nxt_iic.h"

#define HALF_NS 50000U              /* half an SCL period, as d_iic */

static const unsigned scl_pads[4] = { HS_GPIO(1, 0), HS_GPIO(8, 3), HS_GPIO(1, 12), HS_GPIO(1, 11) };
static unsigned port;
static unsigned scl_held;           /* SCL on the connector differed from the pad */

static void tick(void)
{
	hs_sim_run_for(HALF_NS);
	if (gpio_in(ev3_input_pins[port].pin5) != gpio_in(scl_pads[port]))
		scl_held++;
}

static void scl(int high)
{
	gpio_out(scl_pads[port], high);
}

static void sda(int high)
{
	if (high)
		gpio_float(ev3_input_pins[port].pin6);
	else
		gpio_out(ev3_input_pins[port].pin6, 0);
}

static int sda_in(void)
{
	return gpio_in(ev3_input_pins[port].pin6);
}

static void bus_on(unsigned p)
{
	port = p;
	hs_gpio_mux_as_gpio(scl_pads[p]);
	scl(1);
	sda(1);
	gpio_out(ev3_input_pins[p].tx_buffer_off, 0);
	tick();
}

static void start(void)
{
	scl(1); sda(1); tick();
	sda(0); tick();
}

static void stop(void)
{
	scl(0); sda(0); tick();
	scl(1); tick();
	sda(1); tick();
}

/* Sends a byte; returns 1 for ACK. */
static int send(uint8_t b)
{
	int ack;

	for (int i = 7; i >= 0; i--) {
		scl(0); sda((b >> i) & 1); tick();
		scl(1); tick();
	}
	scl(0); sda(1); tick();
	scl(1); tick();
	ack = !sda_in();
	scl(0); tick();
	return ack;
}

static uint8_t receive(int ack)
{
	uint8_t b = 0;

	sda(1);
	for (int i = 0; i < 8; i++) {
		scl(0); tick();
		scl(1); tick();
		b = (uint8_t)(b << 1 | sda_in());
	}
	scl(0); sda(!ack); tick();
	scl(1); tick();
	scl(0); tick();
	sda(1);
	return b;
}

/* Register read with a repeated START (turnaround false) or LEGO's STOP, clock, START. */
static int read_regs(uint8_t addr, uint8_t reg, uint8_t *out, unsigned n, bool turnaround)
{
	start();
	if (!send((uint8_t)(addr << 1)) || !send(reg)) {
		stop();
		return 0;
	}
	if (turnaround) {
		scl(0); sda(0); tick();
		scl(1); tick();
		sda(1); tick();                 /* STOP */
		scl(0); tick();
		scl(1); tick();                 /* one more clock with SDA high */
		sda(0); tick();                 /* START */
	} else {
		scl(1); sda(1); tick();
		sda(0); tick();                 /* repeated START */
	}
	if (!send((uint8_t)(addr << 1 | 1))) {
		stop();
		return 0;
	}
	for (unsigned i = 0; i < n; i++)
		out[i] = receive(i + 1 < n);
	stop();
	return 1;
}

static struct nxt_iic_stats stats(unsigned p)
{
	struct nxt_iic_stats s;

	memset(&s, 0, sizeof(s));
	ev3_nxt_iic_stats(p, &s);
	return s;
}

static void test_ids(void)
{
	uint8_t id[8];
	struct nxt_iic_scene scene = { .accel = { 200, -100, 511 } };

	ok(ev3_attach_nxt_iic(0, NXT_IIC_HT_ACCEL, &scene) == E_OK, "HiTechnic accelerometer plugged into port 1");
	is_int(gpio_in(ev3_input_pins[0].pin2), 0, "pin 2 grounded (an NXT device)");
	is_int(gpio_in(ev3_input_pins[0].pin5), 1, "pin 5 pulled up by the sensor");
	is_int(gpio_in(ev3_input_pins[0].pin6), 1, "pin 6 pulled up by the sensor");
	bus_on(0);
	ok(read_regs(0x01, 0x08, id, 8, false), "address 0x01 and register 0x08 ACKed, repeated START");
	ok(!memcmp(id, "HITECHNC", 8), "manufacturer HITECHNC");
	ok(read_regs(0x01, 0x10, id, 8, true), "read through the STOP/START turnaround");
	ok(!memcmp(id, "Accel.  ", 8), "sensor type Accel.");
	ok(read_regs(0x01, 0x42, id, 6, true), "data registers");
	is_int((int8_t)id[0] * 4 + (id[3] & 3), 200, "X = 200 counts (upper 8 bits, lower 2)");
	is_int((int8_t)id[1] * 4 + (id[4] & 3), -100, "Y = -100");
	is_int((int8_t)id[2] * 4 + (id[5] & 3), 511, "Z = 511");
	is_int(stats(0).repeated_starts, 1, "one repeated START seen");
	ok(hs_trace_find("in1.iic", "byte") && hs_signal_value(hs_trace_find("in1.iic", "byte")) == (uint8_t)(511 & 3),
	   "trace in1.iic.byte: the last byte on the bus (Z's lower bits)");
	ok(hs_trace_find("in1.iic", "scl") && hs_signal_changes(hs_trace_find("in1.iic", "scl")) > 100,
	   "trace in1.iic.scl follows the clock");
	ok(stats(0).stops >= 3, "STOPs seen");
}

static void test_nacks(void)
{
	struct nxt_iic_stats before = stats(0), after;
	uint8_t b;

	start();
	ok(!send(0x05 << 1), "another address is NACKed");
	stop();
	start();
	ok(send(0x01 << 1), "own address ACKed");
	ok(!send(0x60), "a register pointer outside the file is NACKed");
	stop();
	/* a START, four address bits, then a STOP: the byte is dropped */
	start();
	for (int i = 3; i >= 0; i--) {
		scl(0); sda((0x02 >> i) & 1); tick();
		scl(1); tick();
	}
	scl(0); sda(0); tick();
	scl(1); tick();
	sda(1); tick();
	after = stats(0);
	is_int(after.address_nacks - before.address_nacks, 1, "address NACK counted");
	is_int(after.write_nacks - before.write_nacks, 1, "pointer NACK counted");
	is_int(after.aborted_bytes - before.aborted_bytes, 1, "a STOP inside a byte is counted");
	ok(read_regs(0x01, 0x00, &b, 1, false) && b == 'V', "the next transaction works (version 'V')");
	/* a write-only transaction: HiTechnic's command register */
	start();
	ok(send(0x01 << 1) && send(0x41) && send(0x03), "write to 0x41");
	stop();
	is_int(ev3_nxt_iic_register(0, 0x41), 3, "command register written");
	is_int(scl_held, 0, "SCL on the connector always followed the master (no clock stretching)");
}

static void test_temp(void)
{
	struct nxt_iic_scene scene = { .temp_c = 23.5625 };
	uint8_t t[2];

	ok(ev3_attach_nxt_iic(1, NXT_IIC_TEMP, &scene) == E_OK, "temperature sensor on port 2");
	bus_on(1);
	ok(read_regs(0x4C, 0x00, t, 2, true), "temperature read at power-up");
	is_int(t[0], 23, "23 degrees");
	is_int(t[1], 0x80, "9-bit resolution at power-up: .5");
	start();
	ok(send(0x4C << 1) && send(0x01) && send(0x60), "configuration 0x60 (12 bits) written");
	stop();
	ok(read_regs(0x4C, 0x01, t, 1, true) && t[0] == 0x60, "configuration reads back 0x60 (LEGO's probe)");
	ok(read_regs(0x4C, 0x00, t, 2, true), "temperature read");
	is_int(t[0], 23, "23 degrees");
	is_int(t[1], 0x90, "and 9/16 at 12 bits");
	scene.temp_c = -10.25;
	ev3_set_nxt_iic_scene(1, &scene);
	ok(read_regs(0x4C, 0x00, t, 2, false), "negative temperature read");
	is_int(((int8_t)t[0] * 16 + (t[1] >> 4)), -164, "-10.25 degrees = -164 sixteenths");
	start();
	ok(!send(0x4C << 1) || !send(0x04), "pointer 4 is NACKed");
	stop();
}

static void test_unplug(void)
{
	uint8_t id[8];
	struct nxt_iic_scene scene = { .rgb = { 10, 20, 30 }, .color_number = 4, .white = 99 };

	ok(ev3_attach_nxt_iic(2, NXT_IIC_HT_COLOR_V2, &scene) == E_OK, "colour sensor V2 on port 3");
	bus_on(2);
	ok(read_regs(0x01, 0x10, id, 8, false) && !memcmp(id, "ColorPD ", 8), "type ColorPD");
	ok(read_regs(0x01, 0x42, id, 5, false), "colour registers");
	ok(id[0] == 4 && id[1] == 10 && id[2] == 20 && id[3] == 30 && id[4] == 99, "number, RGB, white");
	ok(ev3_detach_input(2) == E_OK, "unplugged");
	is_int(gpio_in(ev3_input_pins[2].pin2), 1, "pin 2 released");
	ok(ev3_attach_nxt_iic(2, NXT_IIC_HT_COLOR, &scene) == E_OK, "colour sensor v1 plugged instead");
	bus_on(2);
	ok(read_regs(0x01, 0x10, id, 8, false) && !memcmp(id, "Color   ", 8), "type Color");
	ok(read_regs(0x01, 0x08, id, 8, false) && !memcmp(id, "HiTechnc", 8), "manufacturer HiTechnc");
}

/* Writes one register: START, address, pointer, value, STOP; 1 if all were ACKed. */
static int write_reg(uint8_t addr, uint8_t reg, uint8_t value)
{
	int acked;

	start();
	acked = send((uint8_t)(addr << 1)) && send(reg) && send(value);
	stop();
	return acked;
}

/* LEGO's NXT ultrasonic sensor (NXT Hardware Developer Kit's I2C register map). */
static void test_us(void)
{
	uint8_t id[8];
	struct nxt_iic_scene scene = { .distance_cm = 42 };

	ok(ev3_attach_nxt_iic(3, NXT_IIC_US, &scene) == E_OK, "ultrasonic sensor on port 4");
	bus_on(3);
	ok(read_regs(NXT_IIC_US_ADDRESS, 0x00, id, 8, true) && !memcmp(id, "V1.0    ", 8), "version V1.0 at 0x00");
	ok(read_regs(NXT_IIC_US_ADDRESS, 0x08, id, 8, true) && !memcmp(id, "LEGO    ", 8), "manufacturer LEGO at 0x08");
	ok(read_regs(NXT_IIC_US_ADDRESS, 0x10, id, 8, true) && !memcmp(id, "Sonar   ", 8), "type Sonar at 0x10");
	ok(read_regs(NXT_IIC_US_ADDRESS, 0x41, id, 3, true) && id[0] == 0x02 && id[1] == 42 && id[2] == 0,
	   "continuous at power-up (0x41 = 2); measurement byte 0 at 0x42 = 42 cm");
	scene.distance_cm = 100;
	ev3_set_nxt_iic_scene(3, &scene);
	ok(read_regs(NXT_IIC_US_ADDRESS, 0x42, id, 1, true) && id[0] == 100, "continuous: follows the scene (100 cm)");
	ok(write_reg(NXT_IIC_US_ADDRESS, 0x41, 0x01), "single-shot command written to 0x41");
	scene.distance_cm = 7;
	ev3_set_nxt_iic_scene(3, &scene);
	ok(read_regs(NXT_IIC_US_ADDRESS, 0x42, id, 1, true) && id[0] == 100, "single shot: the measurement is held");
	ok(write_reg(NXT_IIC_US_ADDRESS, 0x41, 0x04) &&
	   read_regs(NXT_IIC_US_ADDRESS, 0x41, id, 2, true) && id[0] == 0x02 && id[1] == 7,
	   "warm reset: continuous again, 7 cm");
	ev3_detach_input(3);
}

static void test_timer64p1(void)
{
	const uint32_t t1 = HS_TIMER64P1_BASE;
	uint64_t t0;
	unsigned n = 0;

	wr32(t1 + 0x24, 0);                         /* TGCR: reset */
	wr32(t1 + 0x1C, 1199);                      /* PRD34: 50 us of 24 MHz */
	wr32(t1 + 0x14, 0);
	wr32(t1 + 0x24, 0x6);                       /* dual unchained, TIM34 out of reset */
	wr32(t1 + 0x44, 0x10000);                   /* PRDINTEN34 */
	t0 = hs_now();
	wr32(t1 + 0x20, 2U << 22);                  /* continuous */
	hs_sim_run_for(49000);
	is_int(rd32(t1 + 0x44) & 0x20000, 0, "no period interrupt before 50 us");
	hs_sim_run_for(1000);
	ok(rd32(t1 + 0x44) & 0x20000, "PRDINTSTAT34 set at 50 us");
	ok(hs_intc_pending(24), "TINT34_1 (AINTC 24) raised");
	wr32(t1 + 0x44, 0x30000);                   /* clear the status, keep enabled */
	is_int(rd32(t1 + 0x44), 0x10000, "status is write-1-to-clear");
	while (hs_now() - t0 < 1000000U) {
		hs_sim_run_for(HALF_NS);
		if (rd32(t1 + 0x44) & 0x20000) {
			n++;
			wr32(t1 + 0x44, 0x30000);
		}
	}
	is_int(n, 19, "one period interrupt every 50 us");
	wr32(t1 + 0x20, 0);
}

int main(void)
{
	tap_plan(61);
	devtest_boot(3, NULL);
	test_ids();
	test_nacks();
	test_temp();
	test_unplug();
	test_us();
	test_timer64p1();
	hs_sim_shutdown();
	return tap_done();
}
