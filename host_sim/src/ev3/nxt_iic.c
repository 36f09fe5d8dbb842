/*
 * nxt_iic.c — the NXT I2C bus on an input port's pins and the sensors on it
 * as I2C slaves (nxt_iic.h describes the electrics, the protocol and the
 * registers).  Host only.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/gpio.h"
#include "host_sim/trace.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/nxt_iic.h"
#include "nxt_iic_bus.h"

/* The SCL pads behind each port's TX buffer (EP2 board). */
static const unsigned scl_pad[EV3_INPUT_PORTS] = {
	HS_GPIO(1, 0), HS_GPIO(8, 3), HS_GPIO(1, 12), HS_GPIO(1, 11),
};

#define REGS 256U

enum slave_state {
	SL_IDLE,        /* waiting for a START */
	SL_ADDRESS,     /* receiving the address byte */
	SL_WRITE,       /* receiving a data byte */
	SL_ACK,         /* driving its ACK during the ninth clock */
	SL_READ,        /* sending a data byte */
	SL_MASTER_ACK,  /* the master's ACK/NACK clock */
	SL_READ_NEXT,   /* ACKed by the master: the next byte goes out at the fall */
	SL_IGNORE,      /* NACKed or done: waiting for START or STOP */
};

struct bus {
	unsigned port;
	bool present;               /* a slave is attached */
	bool plugged;
	enum nxt_iic_kind kind;
	uint8_t address;
	struct nxt_iic_scene scene;
	int watch[3];
	bool scl, sda;              /* resolved levels last seen */
	bool pulling;               /* the slave pulls SDA low */
	bool updating;              /* inside our own pin update */
	/* protocol */
	enum slave_state state;
	bool in_transaction;        /* between START and STOP */
	bool read_dir;
	bool first_byte;            /* next written byte is the register pointer */
	unsigned bits;
	uint8_t shift;
	uint8_t pointer;
	unsigned byte_in_reg;       /* temperature sensor: byte of a 16-bit register */
	uint8_t regs[REGS];
	struct nxt_iic_stats stats;
	/* traces (scope "in<N>.iic"): the connector's lines and each byte as it completes */
	struct hs_signal *sig_scl, *sig_sda, *sig_byte;
};

static struct bus buses[EV3_INPUT_PORTS];

/* ---- the sensors' register files ---- */

static void put_string(uint8_t *regs, unsigned at, const char *s)
{
	memset(regs + at, ' ', 8);
	memcpy(regs + at, s, strlen(s) < 8 ? strlen(s) : 8);
}

/* The NXT ultrasonic sensor's commands (register 0x41). */
enum { US_OFF = 0x00, US_SINGLE_SHOT = 0x01, US_CONTINUOUS = 0x02, US_EVENT_CAPTURE = 0x03, US_WARM_RESET = 0x04 };

/* The ultrasonic sensor's identification and settings at power-up (and warm reset). */
static void us_identify(uint8_t *regs)
{
	put_string(regs, 0x00, "V1.0");
	put_string(regs, 0x08, "LEGO");
	put_string(regs, 0x10, "Sonar");
	regs[0x40] = 0x01;              /* continuous measurement interval */
	regs[0x41] = US_CONTINUOUS;
}

/* Refreshes the data registers from the scene (at each START: a consistent snapshot). */
static void sensor_sample(struct bus *b)
{
	uint8_t *r = b->regs;
	const struct nxt_iic_scene *s = &b->scene;

	switch (b->kind) {
	case NXT_IIC_HT_ACCEL:
		for (unsigned i = 0; i < 3; i++) {
			int v = s->accel[i] < -512 ? -512 : s->accel[i] > 511 ? 511 : s->accel[i];

			r[0x42 + i] = (uint8_t)((unsigned)v >> 2 & 0xFFU);
			r[0x45 + i] = (uint8_t)((unsigned)v & 3U);
		}
		break;
	case NXT_IIC_HT_COLOR:
		r[0x42] = s->color_number;
		for (unsigned i = 0; i < 3; i++) {
			uint16_t raw = (uint16_t)(s->rgb[i] * 4U);

			r[0x43 + i] = s->rgb[i];
			r[0x46 + 2 * i] = (uint8_t)(raw >> 8);
			r[0x47 + 2 * i] = (uint8_t)raw;
			r[0x4D + i] = s->rgb[i];
		}
		r[0x4C] = (uint8_t)((s->rgb[0] >> 6) << 4 | (s->rgb[1] >> 6) << 2 | (s->rgb[2] >> 6));
		break;
	case NXT_IIC_HT_COLOR_V2:
		r[0x42] = s->color_number;
		r[0x43] = s->rgb[0];
		r[0x44] = s->rgb[1];
		r[0x45] = s->rgb[2];
		r[0x46] = s->white;
		r[0x47] = (uint8_t)((s->rgb[0] >> 6) << 4 | (s->rgb[1] >> 6) << 2 | (s->rgb[2] >> 6));
		for (unsigned i = 0; i < 3; i++)
			r[0x48 + i] = s->rgb[i];
		break;
	case NXT_IIC_US:
		/* continuous: byte 0 follows the scene; a single shot (or off) holds its bytes */
		if (r[0x41] == US_CONTINUOUS) {
			r[0x42] = s->distance_cm;
			memset(r + 0x43, 0, 7);
		}
		break;
	case NXT_IIC_TEMP: {
		/* resolution from configuration bits 6:5: 9 + R bits; 1/16 degree units */
		unsigned res = 9U + ((r[0x01] >> 5) & 3U);
		double t = s->temp_c < -55.0 ? -55.0 : s->temp_c > 128.0 ? 127.9375 : s->temp_c;
		int sixteenths = (int)lround(t * 16.0);
		int16_t v;

		sixteenths &= ~((1 << (12U - res)) - 1);       /* drop the bits below the resolution */
		v = (int16_t)(sixteenths * 16);
		r[0x80] = (uint8_t)((uint16_t)v >> 8);           /* register 0, MSB first, kept at 0x80 */
		r[0x81] = (uint8_t)v;
		break;
	}
	}
}

static void sensor_reset(struct bus *b)
{
	memset(b->regs, 0, sizeof(b->regs));
	b->pointer = 0;
	b->byte_in_reg = 0;
	switch (b->kind) {
	case NXT_IIC_HT_ACCEL:
		put_string(b->regs, 0x00, "V1.1");
		put_string(b->regs, 0x08, "HITECHNC");
		put_string(b->regs, 0x10, "Accel.");
		break;
	case NXT_IIC_HT_COLOR:
		put_string(b->regs, 0x00, "V1.2");
		put_string(b->regs, 0x08, "HiTechnc");
		put_string(b->regs, 0x10, "Color");
		break;
	case NXT_IIC_HT_COLOR_V2:
		put_string(b->regs, 0x00, "V2.1");
		put_string(b->regs, 0x08, "HiTechnc");
		put_string(b->regs, 0x10, "ColorPD");
		break;
	case NXT_IIC_TEMP:
		break;
	case NXT_IIC_US:
		us_identify(b->regs);
		break;
	}
	sensor_sample(b);
}

/* Whether the sensor takes byte as the register pointer. */
static bool sensor_pointer_ok(const struct bus *b, uint8_t reg)
{
	return b->kind == NXT_IIC_TEMP ? reg <= 3U : reg < 0x50U;
}

/* The master wrote a data byte (after the pointer) at the current pointer. */
static void sensor_write(struct bus *b, uint8_t byte)
{
	if (b->kind == NXT_IIC_TEMP) {
		if (b->pointer == 1U)
			b->regs[0x01] = byte & 0x7FU;    /* configuration (bit 7 one-shot reads 0) */
		else if (b->pointer >= 2U)
			b->regs[0x82 + 2U * (b->pointer - 2U) + (b->byte_in_reg++ & 1U)] = byte;
		return;
	}
	if (b->kind == NXT_IIC_US && (b->pointer == 0x40U || b->pointer == 0x41U)) {
		if (b->pointer == 0x41U && byte == US_WARM_RESET) {
			us_identify(b->regs);
		} else if (b->pointer == 0x41U && byte == US_SINGLE_SHOT) {
			b->regs[0x41] = byte;
			b->regs[0x42] = b->scene.distance_cm;   /* one measurement, held */
			memset(b->regs + 0x43, 0, 7);
		} else {
			b->regs[b->pointer] = byte;
		}
		b->pointer++;
		return;
	}
	/* HiTechnic: 0x41 is the command/mode register; the rest is read-only. */
	if (b->pointer == 0x41U)
		b->regs[0x41] = byte;
	b->pointer++;
}

/* The next byte the sensor sends. */
static uint8_t sensor_read(struct bus *b)
{
	if (b->kind == NXT_IIC_TEMP) {
		unsigned i = b->byte_in_reg++ & 1U;

		switch (b->pointer) {
		case 0: return b->regs[0x80 + i];
		case 1: return b->regs[0x01];
		default: return b->regs[0x82 + 2U * (b->pointer - 2U) + i];
		}
	}
	return b->regs[b->pointer++];
}

/* ---- the slave on the wires ---- */

static void apply_sda(struct bus *b)
{
	const struct ev3_input_pins *pins = &ev3_input_pins[b->port];

	b->updating = true;
	hs_gpio_drive(pins->pin6, b->pulling ? HS_EXT_LOW : HS_EXT_PULL_UP);
	b->updating = false;
}

static void slave_pull(struct bus *b, bool low)
{
	bool lvl;

	if (b->pulling == low)
		return;
	b->pulling = low;
	apply_sda(b);
	if (low && hs_gpio_soc_output(ev3_input_pins[b->port].pin6, &lvl) && lvl)
		b->stats.contention++;
}

static void on_start(struct bus *b)
{
	b->stats.starts++;
	if (b->in_transaction)
		b->stats.repeated_starts++;
	if ((b->state == SL_ADDRESS || b->state == SL_WRITE) && b->bits > 1)
		b->stats.aborted_bytes++;
	b->in_transaction = true;
	slave_pull(b, false);
	b->byte_in_reg = 0;
	sensor_sample(b);
	b->state = SL_ADDRESS;
	b->bits = 0;
	b->shift = 0;
}

static void on_stop(struct bus *b)
{
	b->stats.stops++;
	if ((b->state == SL_ADDRESS || b->state == SL_WRITE) && b->bits > 1)
		b->stats.aborted_bytes++;
	b->in_transaction = false;
	slave_pull(b, false);
	b->state = SL_IDLE;
}

/* SCL rose: sample the master's bit. */
static void on_scl_rise(struct bus *b)
{
	switch (b->state) {
	case SL_ADDRESS:
	case SL_WRITE:
		b->shift = (uint8_t)(b->shift << 1 | (b->sda ? 1U : 0U));
		b->bits++;
		break;
	case SL_MASTER_ACK:
		hs_trace_set(b->sig_byte, b->shift);
		/* low: the master wants more; high: NACK, the end of the read */
		b->state = b->sda ? SL_IGNORE : SL_READ_NEXT;
		break;
	default:
		break;
	}
}

/* A byte came in: the address or a data byte.  Returns whether the slave ACKs it. */
static bool byte_received(struct bus *b)
{
	hs_trace_set(b->sig_byte, b->shift);
	if (b->state == SL_ADDRESS) {
		if ((b->shift >> 1) != b->address) {
			b->stats.address_nacks++;
			return false;
		}
		b->stats.address_acks++;
		b->read_dir = b->shift & 1U;
		b->first_byte = !b->read_dir;
		return true;
	}
	if (b->first_byte) {
		b->first_byte = false;
		if (!sensor_pointer_ok(b, b->shift)) {
			b->stats.write_nacks++;
			return false;
		}
		b->pointer = b->shift;
		b->byte_in_reg = 0;
		b->stats.bytes_written++;
		return true;
	}
	sensor_write(b, b->shift);
	b->stats.bytes_written++;
	return true;
}

/* Puts the current bit of the byte being sent on SDA. */
static void drive_read_bit(struct bus *b)
{
	slave_pull(b, !(b->shift & (0x80U >> b->bits)));
}

/* Starts sending the next byte of the register file. */
static void send_next_byte(struct bus *b)
{
	b->state = SL_READ;
	b->bits = 0;
	b->shift = sensor_read(b);
	b->stats.bytes_read++;
	drive_read_bit(b);
}

/* SCL fell: the slave changes SDA. */
static void on_scl_fall(struct bus *b)
{
	switch (b->state) {
	case SL_ADDRESS:
	case SL_WRITE:
		if (b->bits < 8)
			break;
		if (byte_received(b)) {
			slave_pull(b, true);
			b->state = SL_ACK;
		} else {
			slave_pull(b, false);
			b->state = SL_IGNORE;
		}
		break;
	case SL_ACK:
		/* the ninth clock is over */
		if (b->read_dir) {
			send_next_byte(b);
		} else {
			slave_pull(b, false);
			b->state = SL_WRITE;
			b->bits = 0;
			b->shift = 0;
		}
		break;
	case SL_READ:
		/* rising edges of a read byte are the master's; count them on the falls */
		if (++b->bits < 8) {
			drive_read_bit(b);
		} else {
			slave_pull(b, false);
			b->state = SL_MASTER_ACK;
		}
		break;
	case SL_MASTER_ACK:
		break;
	case SL_READ_NEXT:
		send_next_byte(b);
		break;
	case SL_IGNORE:
		slave_pull(b, false);
		break;
	default:
		break;
	}
}

/* SCL as the connector sees it: the pad through the buffer, else the pull-up. */
static bool scl_line(const struct bus *b)
{
	bool buffer_off = true, pad;

	if (hs_gpio_soc_output(ev3_input_pins[b->port].tx_buffer_off, &buffer_off) && !buffer_off &&
	    hs_gpio_soc_output(scl_pad[b->port], &pad))
		return pad;
	return true;
}

/* Re-reads both lines and plays the edges to the slave. */
static void bus_update(struct bus *b)
{
	const struct ev3_input_pins *pins = &ev3_input_pins[b->port];
	bool scl, sda;

	if (!b->present || !b->plugged)
		return;
	scl = scl_line(b);
	if (scl != b->scl) {
		b->updating = true;
		hs_gpio_drive(pins->pin5, scl ? HS_EXT_HIGH : HS_EXT_LOW);
		b->updating = false;
		b->scl = scl;
		hs_trace_set(b->sig_scl, scl);
		if (scl)
			on_scl_rise(b);
		else
			on_scl_fall(b);
	}
	sda = hs_gpio_level(pins->pin6);
	if (sda != b->sda) {
		b->sda = sda;
		hs_trace_set(b->sig_sda, sda);
		if (b->scl) {
			if (sda)
				on_stop(b);
			else
				on_start(b);
		}
	}
}

static void pin_changed(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	struct bus *b = ctx;

	(void)pin; (void)st;
	if (b->updating) {
		/* our own drive: only remember where SDA is now */
		b->sda = hs_gpio_level(ev3_input_pins[b->port].pin6);
		hs_trace_set(b->sig_sda, b->sda);
		return;
	}
	bus_update(b);
}

void nxt_iic_bus_apply(unsigned port, bool plugged)
{
	struct bus *b = &buses[port];
	const struct ev3_input_pins *pins = &ev3_input_pins[port];

	if (!b->present)
		return;
	if (plugged && !b->plugged) {
		/* powered up again: registers at their reset values, bus idle */
		sensor_reset(b);
		b->state = SL_IDLE;
		b->in_transaction = false;
	}
	b->plugged = plugged;
	if (!plugged) {
		b->pulling = false;
		b->state = SL_IDLE;
		b->in_transaction = false;
		return;         /* the caller floats the pins */
	}
	b->scl = scl_line(b);
	b->updating = true;
	hs_gpio_drive(pins->pin5, b->scl ? HS_EXT_HIGH : HS_EXT_LOW);
	b->updating = false;
	apply_sda(b);
	b->sda = hs_gpio_level(pins->pin6);
	hs_trace_set(b->sig_scl, b->scl);
	hs_trace_set(b->sig_sda, b->sda);
}

void nxt_iic_bus_detach(unsigned port)
{
	struct bus *b = &buses[port];

	for (unsigned i = 0; i < 3; i++)
		hs_gpio_unwatch(b->watch[i]);
	memset(b, 0, sizeof(*b));
}

bool nxt_iic_bus_attach(unsigned port, enum nxt_iic_kind kind, const struct nxt_iic_scene *scene)
{
	struct bus *b = &buses[port];
	const struct ev3_input_pins *pins = &ev3_input_pins[port];

	nxt_iic_bus_detach(port);
	b->port = port;
	b->kind = kind;
	b->address = kind == NXT_IIC_TEMP ? NXT_IIC_TEMP_ADDRESS : NXT_IIC_HT_ADDRESS;
	if (scene)
		b->scene = *scene;
	sensor_reset(b);
	b->watch[0] = hs_gpio_watch(pins->pin6, pin_changed, b);
	b->watch[1] = hs_gpio_watch(scl_pad[port], pin_changed, b);
	b->watch[2] = hs_gpio_watch(pins->tx_buffer_off, pin_changed, b);
	if (!b->watch[0] || !b->watch[1] || !b->watch[2]) {
		nxt_iic_bus_detach(port);
		return false;
	}
	{
		char scope[16];

		snprintf(scope, sizeof(scope), "in%u.iic", port + 1U);
		b->sig_scl = hs_trace_signal(scope, "scl", 1);
		b->sig_sda = hs_trace_signal(scope, "sda", 1);
		b->sig_byte = hs_trace_signal(scope, "byte", 8);
	}
	b->present = true;
	return true;
}

ER ev3_set_nxt_iic_scene(unsigned port, const struct nxt_iic_scene *scene)
{
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	if (!scene)
		return E_PAR;
	if (!buses[port].present)
		return E_OBJ;
	buses[port].scene = *scene;
	return E_OK;
}

ER ev3_nxt_iic_stats(unsigned port, struct nxt_iic_stats *out)
{
	if (port >= EV3_INPUT_PORTS)
		return E_ID;
	if (!out)
		return E_PAR;
	if (!buses[port].present)
		return E_OBJ;
	*out = buses[port].stats;
	return E_OK;
}

int ev3_nxt_iic_register(unsigned port, unsigned reg)
{
	if (port >= EV3_INPUT_PORTS || reg >= REGS || !buses[port].present)
		return -1;
	return buses[port].regs[reg];
}
