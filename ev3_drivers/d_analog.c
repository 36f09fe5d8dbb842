// SPDX-License-Identifier: GPL-2.0
/*
 * d_analog.c - EV3 analog front end: ADC sampling over SPI0 and the device connection
 * manager (DCM) that tells which device is plugged into each input and output port.
 *
 * Interface-compatible with LEGO's lms2012 d_analog (see lms_analog.h):
 *   /dev/lms_analog  mmap: struct lms_analog; read: text dump; write: ignored.
 *   /dev/lms_dcm     read: detected types; write: input-port pin levels.
 *
 * Sampling: an hrtimer runs a 1 ms cycle of three bursts (at 0, 200 and 800 us) of polled
 * 16-bit SPI frames to the ADC.  Pin 1 and pin 6 of the four input ports are converted
 * every cycle and logged into 300-sample rings; the eight other channels (output-port
 * pin 5, battery and motor currents, battery temperature and voltage) take turns, one per
 * cycle, so each is converted every 8 ms.
 *
 * Detection: a second hrtimer, every 10 ms after dcm_start_ms, floats each unconnected
 * port, watches its pins for connection events, waits 350 ms for them to hold still,
 * identifies the device from pin levels and voltages, and waits for 100 ms without events
 * before declaring it gone.
 *
 * GPIO ownership.  gpiolib grants each pin to one requester, and three drivers touch the
 * port pins, so the split is:
 *   d_analog requests  input ports: pin 1's 9 V switch, pin 2, pin 5 and pin 6;
 *                      output ports: pin 5w (the DETx0 pull).
 *   d_pwm owns         output ports: pins 1 and 2 (H-bridge), pin 5 (tacho INT) and
 *                      pin 6 (tacho DIR), which it drives and reads through the GPIO bank
 *                      registers without requests.  d_analog borrows pin 6 only while it
 *                      identifies a newly attached device (pulled low for 20 ms, then floated
 *                      again); d_pwm only reads it.  Detection needs pins 1 and 2 low, which
 *                      is d_pwm's coast state for a port without a motor type.
 *   d_uart requests    the TX-buffer disable pins and the UART pins.  While an input port
 *                      is in UART mode d_uart may float and read its pins 5 and 6; d_analog
 *                      then only reads them and drives them solely on a /dev/lms_dcm write.
 */

#include <linux/module.h>
#include <linux/init.h>
#include <linux/kernel.h>
#include <linux/types.h>
#include <linux/bits.h>
#include <linux/errno.h>
#include <linux/string.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/io.h>
#include <linux/ioport.h>
#include <linux/gpio.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/spinlock.h>
#include <linux/uaccess.h>
#include <linux/delay.h>

#include "lms_analog.h"

/* ---- Hardware: AM1808 physical addresses and register offsets ---- */

#define SPI0_PHYS		0x01C41000
#define SPI0_SIZE		0x68
#define SPIGCR0			0x00	/* bit 0: out of reset */
#define SPIGCR1			0x04
#define SPIINT0			0x08
#define SPIPC0			0x14
#define SPIDAT0			0x38
#define SPIBUF			0x40
#define SPIDELAY		0x48
#define SPIDEF			0x4C
#define SPIFMT0			0x50

#define SPIGCR0_OUT_OF_RESET	0x00000001
#define SPIGCR1_MASTER		0x00000003	/* CLKMOD | MASTER */
#define SPIGCR1_ENABLE		0x01000000
#define SPIPC0_PINS		0x00000E08	/* SOMI, SIMO, CLK, SCS3 */
#define SPIFMT0_ADC		(0x00010010 | (74 << 8))	/* phase 1, 16 bits, 150/75 MHz */
#define SPIDELAY_ADC		0x0A0A0A0A
#define SPIDEF_ADC		0x00000008	/* SCS3 high between frames */
#define SPIBUF_TXFULL		BIT(29)
#define SPIBUF_RXEMPTY		BIT(31)
#define SPI_POLL_LIMIT		20	/* 1 us apart: 2.5 frame times of 8 us at 2 MHz */

#define SYSCFG1_PHYS		0x01E2C000
#define SYSCFG1_SIZE		0x10
#define SYSCFG1_PUPD_ENA	0x0C

/* ADC: manual-mode command selecting a channel; the answer comes two frames later. */
#define ADC_SELECT(channel)	(0x1840 | ((channel) << 7))
#define ADC_INIT_FRAME		0x400F
#define ADC_INIT_FRAMES		6
#define ADC_DATA_MASK		0x0FFF
#define ADC_PIPELINE_DEPTH	2

#define GPIO_PIN(bank, bit)	((bank) * 16 + (bit))

/* ---- Sampling schedule ---- */

#define ANALOG_CHANNELS		16	/* logical channels: the u16s at the start of ANALOG */
#define ANALOG_INPUT_CHANNELS	8	/* pin 1 and pin 6 of each input port, every cycle */
#define ANALOG_OTHER_CHANNELS	(ANALOG_CHANNELS - ANALOG_INPUT_CHANNELS)
#define ANALOG_NO_CHANNEL	(-1)
#define ANALOG_NS_PER_US	1000

/* Logical channel -> ADC input (per the EV3 board wiring). */
static const u8 analog_adc_input[ANALOG_CHANNELS] = {
	6, 8, 10, 12,		/* InPin1 of ports 1..4 */
	5, 7, 9, 11,		/* InPin6 of ports 1..4 */
	1, 0, 13, 14,		/* OutPin5 of ports A..D */
	2, 15, 3, 4,		/* BatteryTemp, MotorCurrent, BatteryCurrent, Cell123456 */
};

/*
 * One cycle is ten frames.  Slots 0..7 select the input channels; slots 8 and 9 both
 * select this cycle's round-robin channel so that the kept (second) conversion is taken
 * after the multiplexer has settled on a possibly high-impedance source.
 */
struct analog_burst {
	u8 first_slot;
	u8 slots;
	u16 gap_us;		/* until the next burst */
};

static const struct analog_burst analog_bursts[] = {
	{ 0, 4, 200 },		/* pin 1 of ports 1..4 */
	{ 4, 4, 600 },		/* pin 6 of ports 1..4 */
	{ 8, 2, 200 },		/* one of the other eight channels */
};

/* ---- Detection ---- */

#define DCM_PERIOD_MS		10
#define DCM_SETTLE_MS		20	/* after floating a port */
#define DCM_CONNECT_MS		350	/* events stable this long: evaluate */
#define DCM_DISCONNECT_MS	100	/* no events this long: device gone */
#define DCM_REREAD_MS		20	/* second reading during evaluation */
#define DCM_HOLD_PERIODS	3	/* an event counts while seen in this many periods */

/* Input-port events. */
#define DCM_IN_PIN2_LOW		BIT(0)	/* NXT device */
#define DCM_IN_PIN1_LOADED	BIT(1)	/* pin 1 below 4800 mV: ID resistor or NXT sensor */
#define DCM_IN_PIN5_LOW		BIT(2)
#define DCM_IN_PIN6_HIGH	BIT(3)

/*
 * Output-port events.  LEGO's notes call the pin 6 event "pin 6 low", but the branch its
 * driver is built with tests for high, which is what works: pin 6 of an empty port floats
 * low, and a motor's encoder or a load pulls it up.
 */
#define DCM_OUT_PIN6_HIGH	BIT(0)
#define DCM_OUT_PIN5_ACTIVE	BIT(1)	/* pin 5 outside 2400..2600 mV */

enum analog_dcm_state {
	DCM_FLOATING,		/* just floated: let the pins settle */
	DCM_IDLE,		/* nothing connected: watch for events */
	DCM_STABILISING,	/* events seen: wait for them to hold */
	DCM_RECHECK,		/* input: pin 1 in 850..950 mV, read it again */
	DCM_PIN6_LOW,		/* output: pin 6 pulled low, read pin 5 again */
	DCM_PIN5_HIGH,		/* output: pin 5 pulled high, read it again */
	DCM_CONNECTED,		/* identified: watch for the device to go */
};

/* What detection concluded, as the (type, connection) pair published in ANALOG. */
enum analog_device {
	DEV_NONE,
	DEV_ERROR,
	DEV_NXT_TOUCH,
	DEV_NXT_LIGHT,
	DEV_NXT_SOUND,
	DEV_NXT_COLOR,
	DEV_NXT_IIC,
	DEV_NXT_TEST,
	DEV_INPUT_UART,
	DEV_INPUT_DUMB,
	DEV_TACHO,
	DEV_MINITACHO,
	DEV_NEWTACHO,
	DEV_OUTPUT_DUMB,
};

static const struct {
	s8 type;
	s8 conn;
} analog_device_codes[] = {
	[DEV_NONE]		= { LMS_TYPE_NONE,	LMS_CONN_NONE },
	[DEV_ERROR]		= { LMS_TYPE_ERROR,	LMS_CONN_ERROR },
	[DEV_NXT_TOUCH]		= { LMS_TYPE_NXT_TOUCH,	LMS_CONN_NXT_DUMB },
	[DEV_NXT_LIGHT]		= { LMS_TYPE_NXT_LIGHT,	LMS_CONN_NXT_DUMB },
	[DEV_NXT_SOUND]		= { LMS_TYPE_NXT_SOUND,	LMS_CONN_NXT_DUMB },
	[DEV_NXT_COLOR]		= { LMS_TYPE_NXT_COLOR,	LMS_CONN_NXT_COLOR },
	[DEV_NXT_IIC]		= { LMS_TYPE_NXT_IIC,	LMS_CONN_NXT_IIC },
	[DEV_NXT_TEST]		= { LMS_TYPE_NXT_TEST,	LMS_CONN_NXT_DUMB },
	[DEV_INPUT_UART]	= { LMS_TYPE_UNKNOWN,	LMS_CONN_INPUT_UART },
	[DEV_INPUT_DUMB]	= { LMS_TYPE_UNKNOWN,	LMS_CONN_INPUT_DUMB },
	[DEV_TACHO]		= { LMS_TYPE_TACHO,	LMS_CONN_OUTPUT_TACHO },
	[DEV_MINITACHO]		= { LMS_TYPE_MINITACHO,	LMS_CONN_OUTPUT_TACHO },
	[DEV_NEWTACHO]		= { LMS_TYPE_NEWTACHO,	LMS_CONN_OUTPUT_TACHO },
	[DEV_OUTPUT_DUMB]	= { LMS_TYPE_UNKNOWN,	LMS_CONN_OUTPUT_DUMB },
};

/* ---- Port pins (EP2 board) ---- */

struct analog_input_pins {
	unsigned int pin1_9v;	/* switches the 9 V supply onto pin 1 */
	unsigned int pin2;	/* LEGDET: low for NXT devices */
	unsigned int pin5;
	unsigned int pin6;
};

static const struct analog_input_pins analog_input_pins[LMS_ANALOG_INPUTS] = {
	{ GPIO_PIN(8, 10), GPIO_PIN(2, 2),  GPIO_PIN(0, 2),  GPIO_PIN(0, 15) },
	{ GPIO_PIN(8, 12), GPIO_PIN(8, 15), GPIO_PIN(0, 14), GPIO_PIN(0, 13) },
	{ GPIO_PIN(8, 9),  GPIO_PIN(7, 11), GPIO_PIN(0, 12), GPIO_PIN(1, 14) },
	{ GPIO_PIN(6, 4),  GPIO_PIN(7, 8),  GPIO_PIN(0, 1),  GPIO_PIN(1, 15) },
};

struct analog_output_pins {
	unsigned int pin5w;	/* DETx0: pulls pin 5 */
	unsigned int pin6;	/* tacho DIR, owned by d_pwm */
};

static const struct analog_output_pins analog_output_pins[LMS_ANALOG_OUTPUTS] = {
	{ GPIO_PIN(5, 4),  GPIO_PIN(0, 4) },
	{ GPIO_PIN(2, 5),  GPIO_PIN(2, 9) },
	{ GPIO_PIN(3, 8),  GPIO_PIN(3, 14) },
	{ GPIO_PIN(5, 15), GPIO_PIN(2, 8) },
};

#define ANALOG_OWNED_PINS	(LMS_ANALOG_INPUTS * 4 + LMS_ANALOG_OUTPUTS)

/* ---- Driver state ---- */

struct analog_port {
	enum analog_dcm_state state;
	unsigned int state_ms;		/* time spent in the state */
	u8 events;			/* the events being stabilised */
	bool bus_pins;			/* input: an NXT I2C device, pins 5 and 6 are its bus */
	u8 recent[DCM_HOLD_PERIODS - 1];	/* events of the previous periods, newest first */
	unsigned int first_mv;		/* output: pin 5 before pulling pin 6 low */
};

struct analog_spi_regs {
	u32 gcr0, gcr1, int0, pc0, delay, def, fmt0;
};

static struct {
	struct lms_analog *shm;		/* the mmap'ed ANALOG area, user-writable */
	u8 __iomem *spi;
	u8 __iomem *syscfg1;
	struct analog_spi_regs spi_saved;
	u32 pupd_saved;
	unsigned int owned_pins[ANALOG_OWNED_PINS];
	unsigned int owned_count;

	struct hrtimer sample_timer;
	struct hrtimer dcm_timer;

	/* Sampling: touched by the sample timer only (and init before it starts). */
	u16 raw[ANALOG_CHANNELS];	/* latest conversions, private copy for detection */
	s8 pipeline[ADC_PIPELINE_DEPTH];	/* channels selected one and two frames ago */
	unsigned int burst;
	unsigned int other;		/* round-robin index among the other channels */
	u16 log_in[LMS_ANALOG_INPUTS];
	u16 log_out[LMS_ANALOG_INPUTS];
	u32 cycles;
	u32 late_bursts;
	u32 spi_timeouts;

	/* Detection: the DCM timer and /dev/lms_dcm writes, under lock. */
	spinlock_t lock;
	struct analog_port in[LMS_ANALOG_INPUTS];
	struct analog_port out[LMS_ANALOG_OUTPUTS];
} analog;

static int dcm_start_ms = 2000;
module_param(dcm_start_ms, int, 0444);
MODULE_PARM_DESC(dcm_start_ms, "Delay before device detection starts, ms (0..60000, default 2000)");

/* ---- SPI0 and the ADC ---- */

/* Waits until SPIBUF's busy_bit clears; returns the last SPIBUF value or -ETIMEDOUT. */
static s64 analog_spi_wait(u32 busy_bit)
{
	unsigned int polls;
	u32 buf;

	for (polls = 0; polls < SPI_POLL_LIMIT; polls++) {
		buf = ioread32(analog.spi + SPIBUF);
		if (!(buf & busy_bit))
			return buf;
		udelay(1);
	}
	analog.spi_timeouts++;
	return -ETIMEDOUT;
}

/* Sends one frame to the ADC; returns the frame received meanwhile or -ETIMEDOUT. */
static int analog_spi_transfer(u16 frame)
{
	s64 buf;

	buf = analog_spi_wait(SPIBUF_TXFULL);
	if (buf < 0)
		return buf;
	iowrite32(frame, analog.spi + SPIDAT0);
	buf = analog_spi_wait(SPIBUF_RXEMPTY);
	if (buf < 0)
		return buf;
	return buf & 0xFFFF;
}

/* Saves SPI0's setup and configures it as a 2 MHz 16-bit master for the ADC. */
static void analog_spi_setup(void)
{
	u8 __iomem *spi = analog.spi;
	struct analog_spi_regs *saved = &analog.spi_saved;

	saved->gcr0 = ioread32(spi + SPIGCR0);
	saved->gcr1 = ioread32(spi + SPIGCR1);
	saved->int0 = ioread32(spi + SPIINT0);
	saved->pc0 = ioread32(spi + SPIPC0);
	saved->delay = ioread32(spi + SPIDELAY);
	saved->def = ioread32(spi + SPIDEF);
	saved->fmt0 = ioread32(spi + SPIFMT0);

	/* Not every boot loader releases SPI0 from reset; the register is idempotent. */
	iowrite32(SPIGCR0_OUT_OF_RESET, spi + SPIGCR0);
	iowrite32(SPIGCR1_MASTER, spi + SPIGCR1);
	iowrite32(SPIPC0_PINS, spi + SPIPC0);
	iowrite32(SPIFMT0_ADC, spi + SPIFMT0);
	iowrite32(SPIDELAY_ADC, spi + SPIDELAY);
	iowrite32(0, spi + SPIINT0);
	iowrite32(SPIDEF_ADC, spi + SPIDEF);
	iowrite32(SPIGCR1_MASTER | SPIGCR1_ENABLE, spi + SPIGCR1);
}

/* Puts SPI0 back the way analog_spi_setup found it. */
static void analog_spi_restore(void)
{
	u8 __iomem *spi = analog.spi;
	const struct analog_spi_regs *saved = &analog.spi_saved;

	iowrite32(saved->gcr1 & ~SPIGCR1_ENABLE, spi + SPIGCR1);
	iowrite32(saved->pc0, spi + SPIPC0);
	iowrite32(saved->fmt0, spi + SPIFMT0);
	iowrite32(saved->delay, spi + SPIDELAY);
	iowrite32(saved->int0, spi + SPIINT0);
	iowrite32(saved->def, spi + SPIDEF);
	iowrite32(saved->gcr1, spi + SPIGCR1);
	if (!(saved->gcr0 & SPIGCR0_OUT_OF_RESET))
		iowrite32(saved->gcr0, spi + SPIGCR0);
}

/* Programs the ADC's operating mode; returns 0 or -EIO if SPI0 does not answer. */
static int analog_adc_init(void)
{
	int i;

	for (i = 0; i < ADC_INIT_FRAMES; i++)
		if (analog_spi_transfer(ADC_INIT_FRAME) < 0)
			return -EIO;
	for (i = 0; i < ADC_PIPELINE_DEPTH; i++)
		analog.pipeline[i] = ANALOG_NO_CHANNEL;
	return 0;
}

/* ---- Sampling (sample timer context) ---- */

/* Publishes one conversion of a logical channel. */
static void analog_store(unsigned int channel, u16 raw)
{
	struct lms_analog *shm = analog.shm;

	analog.raw[channel] = raw;
	if (channel < 4)
		shm->in_pin1[channel] = raw;
	else if (channel < 8)
		shm->in_pin6[channel - 4] = raw;
	else if (channel < 12)
		shm->out_pin5[channel - 8] = raw;
	else if (channel == 12)
		shm->battery_temp = raw;
	else if (channel == 13)
		shm->motor_current = raw;
	else if (channel == 14)
		shm->battery_current = raw;
	else
		shm->cell123456 = raw;
}

/*
 * Selects a logical channel and stores the conversion selected two frames earlier.
 * Returns false if SPI0 timed out.
 */
static bool analog_sample(unsigned int channel)
{
	int frame = analog_spi_transfer(ADC_SELECT(analog_adc_input[channel]));
	s8 done = analog.pipeline[0];

	analog.pipeline[0] = analog.pipeline[1];
	analog.pipeline[1] = channel;
	if (frame < 0) {
		/* The ADC may or may not have seen the frame: trust nothing in flight. */
		analog.pipeline[0] = ANALOG_NO_CHANNEL;
		analog.pipeline[1] = ANALOG_NO_CHANNEL;
		return false;
	}
	if (done != ANALOG_NO_CHANNEL)
		analog_store(done, frame & ADC_DATA_MASK);
	return true;
}

/* Appends this cycle's pin 1 and pin 6 values of every input port to the rings. */
static void analog_log_inputs(void)
{
	struct lms_analog *shm = analog.shm;
	unsigned int port;
	u16 in;

	for (port = 0; port < LMS_ANALOG_INPUTS; port++) {
		/* Indexes live in private copies: the mapped ones are user-writable. */
		in = analog.log_in[port];
		shm->pin1[port][in] = analog.raw[port];
		shm->pin6[port][in] = analog.raw[4 + port];
		shm->actual[port] = in;
		in = (in + 1) % LMS_ANALOG_LOG_SIZE;
		if (in == analog.log_out[port])
			analog.log_out[port] = (in + 1) % LMS_ANALOG_LOG_SIZE;
		analog.log_in[port] = in;
		shm->log_in[port] = in;
		shm->log_out[port] = analog.log_out[port];
		shm->updated[port] = 1;
	}
}

/* Runs one burst of the 1 ms cycle and re-arms for the next burst, drift-free. */
static enum hrtimer_restart analog_sample_tick(struct hrtimer *timer)
{
	const struct analog_burst *burst = &analog_bursts[analog.burst];
	unsigned int slot, channel;
	u64 overruns;

	for (slot = burst->first_slot; slot < burst->first_slot + burst->slots; slot++) {
		channel = slot < ANALOG_INPUT_CHANNELS ? slot : ANALOG_INPUT_CHANNELS + analog.other;
		/* A stuck SPI0 costs one poll limit per burst, not per frame. */
		if (!analog_sample(channel))
			break;
	}
	if (++analog.burst == ARRAY_SIZE(analog_bursts)) {
		/* The last input result of the cycle arrived in this burst's frames. */
		analog_log_inputs();
		analog.other = (analog.other + 1) % ANALOG_OTHER_CHANNELS;
		analog.burst = 0;
		analog.cycles++;
	}
	overruns = hrtimer_forward_now(timer, ns_to_ktime((u64)burst->gap_us * ANALOG_NS_PER_US));
	if (overruns > 1)
		analog.late_bursts += overruns - 1;
	return HRTIMER_RESTART;
}

/* ---- Detection (DCM timer context, or process context with the lock held) ---- */

/* Latest voltage of a logical channel in mV. */
static unsigned int analog_mv(unsigned int channel)
{
	return lms_analog_raw_to_mv(analog.raw[channel]);
}

/* Publishes what an input port has, or DEV_NONE. */
static void analog_set_input(unsigned int port, enum analog_device dev)
{
	analog.shm->in_dcm[port] = analog_device_codes[dev].type;
	analog.shm->in_conn[port] = analog_device_codes[dev].conn;
	analog.in[port].bus_pins = dev == DEV_NXT_IIC;
}

/* Publishes what an output port has, or DEV_NONE. */
static void analog_set_output(unsigned int port, enum analog_device dev)
{
	analog.shm->out_dcm[port] = analog_device_codes[dev].type;
	analog.shm->out_conn[port] = analog_device_codes[dev].conn;
}

/* Moves a port to a state, restarting its clock. */
static void analog_dcm_enter(struct analog_port *p, enum analog_dcm_state state)
{
	p->state = state;
	p->state_ms = 0;
}

/* Starts detection on a port from scratch (its pins have just been floated). */
static void analog_dcm_restart(struct analog_port *p)
{
	memset(p->recent, 0, sizeof(p->recent));
	p->events = 0;
	analog_dcm_enter(p, DCM_FLOATING);
}

enum analog_dcm_step {
	DCM_STEP_WAIT,		/* nothing to do this period */
	DCM_STEP_EVALUATE,	/* events held still for 350 ms: identify the device */
	DCM_STEP_GONE,		/* no events for 100 ms: the device was unplugged */
};

/*
 * Advances the timing both port kinds share by one DCM period, given the port's events
 * now.  For connecting, an event counts while it was seen in any of the last
 * DCM_HOLD_PERIODS periods: UART traffic and contact bounce toggle pins faster than the
 * DCM samples, and a flickering set of events would never hold still for 350 ms.  A
 * disconnect looks at the events as they are, so that it is seen within 100 ms.
 */
static enum analog_dcm_step analog_dcm_step(struct analog_port *p, u8 events)
{
	u8 held = events;
	unsigned int i;

	for (i = ARRAY_SIZE(p->recent); i > 0; i--) {
		held |= p->recent[i - 1];
		p->recent[i - 1] = i > 1 ? p->recent[i - 2] : events;
	}

	p->state_ms += DCM_PERIOD_MS;
	switch (p->state) {
	case DCM_FLOATING:
		if (p->state_ms >= DCM_SETTLE_MS)
			analog_dcm_enter(p, DCM_IDLE);
		break;
	case DCM_IDLE:
		if (held) {
			p->events = held;
			analog_dcm_enter(p, DCM_STABILISING);
		}
		break;
	case DCM_STABILISING:
		if (held != p->events) {
			p->events = held;
			analog_dcm_enter(p, held ? DCM_STABILISING : DCM_IDLE);
		} else if (p->state_ms >= DCM_CONNECT_MS) {
			return DCM_STEP_EVALUATE;
		}
		break;
	case DCM_CONNECTED:
		if (events)
			p->state_ms = 0;
		else if (p->state_ms >= DCM_DISCONNECT_MS)
			return DCM_STEP_GONE;
		break;
	default:
		break;		/* evaluation re-reads: the port kind's own business */
	}
	return DCM_STEP_WAIT;
}

/* Releases an input port's pins: 9 V off, pins 2, 5 and 6 floating. */
static void analog_input_release_pins(unsigned int port)
{
	const struct analog_input_pins *pins = &analog_input_pins[port];

	gpio_direction_output(pins->pin1_9v, 0);
	gpio_direction_input(pins->pin2);
	gpio_direction_input(pins->pin5);
	gpio_direction_input(pins->pin6);
}

/* Floats an input port so that a newly attached device can show itself. */
static void analog_input_float(unsigned int port)
{
	analog_input_release_pins(port);
	analog_dcm_restart(&analog.in[port]);
}

/* Drives an input port's pins as a /dev/lms_dcm LMS_DCM_PINS() character asks. */
static void analog_input_drive(unsigned int port, unsigned int bits)
{
	const struct analog_input_pins *pins = &analog_input_pins[port];

	gpio_direction_output(pins->pin5, !!(bits & LMS_DCM_PIN5_HIGH));
	gpio_direction_output(pins->pin6, !!(bits & LMS_DCM_PIN6_HIGH));
	gpio_direction_output(pins->pin1_9v, !!(bits & LMS_DCM_PIN1_9V));
}

/* Current connection events of an input port. */
static u8 analog_input_events(unsigned int port)
{
	const struct analog_input_pins *pins = &analog_input_pins[port];
	u8 events = 0;

	if (!gpio_get_value(pins->pin2))
		events |= DCM_IN_PIN2_LOW;
	if (analog_mv(port) < 4800)
		events |= DCM_IN_PIN1_LOADED;
	if (!gpio_get_value(pins->pin5))
		events |= DCM_IN_PIN5_LOW;
	if (gpio_get_value(pins->pin6))
		events |= DCM_IN_PIN6_HIGH;
	return events;
}

/* Declares an input port's device identified. */
static void analog_input_connect(unsigned int port, enum analog_device dev)
{
	analog_set_input(port, dev);
	analog_dcm_enter(&analog.in[port], DCM_CONNECTED);
}

/* Identifies the device on an input port whose events have held for 350 ms. */
static void analog_input_evaluate(unsigned int port)
{
	const struct analog_input_pins *pins = &analog_input_pins[port];
	struct analog_port *p = &analog.in[port];
	bool pin5_high = gpio_get_value(pins->pin5);
	bool pin6_high = gpio_get_value(pins->pin6);
	unsigned int pin1 = analog_mv(port);
	enum analog_device dev;

	if (p->events & DCM_IN_PIN2_LOW) {
		if (pin5_high && pin6_high)
			dev = pin1 < 100 ? DEV_NXT_COLOR : DEV_NXT_IIC;
		else if (!pin5_high)
			dev = pin6_high ? DEV_NXT_TEST : DEV_NXT_LIGHT;
		else if (pin1 < 100)
			dev = DEV_NXT_COLOR;
		else if (pin1 > 4800)
			dev = DEV_NXT_TOUCH;
		else if (pin1 >= 850 && pin1 <= 950) {
			/* A pressed NXT touch sensor or a sound sensor passing by: look again. */
			analog_dcm_enter(p, DCM_RECHECK);
			return;
		} else {
			dev = DEV_NXT_SOUND;
		}
	} else if (p->events & DCM_IN_PIN1_LOADED) {
		if (pin1 > 3100)
			dev = DEV_ERROR;
		else if (pin1 < 100)
			dev = DEV_INPUT_UART;	/* UART sensors ground their ID pin */
		else
			dev = DEV_INPUT_DUMB;	/* user space reads the ID resistor on InPin1 */
	} else if (p->events & DCM_IN_PIN6_HIGH) {
		dev = DEV_NXT_IIC;
	} else {
		/* Only pin 5 low: something we cannot name (LEGO never reached this branch). */
		dev = DEV_ERROR;
	}
	analog_input_connect(port, dev);
}

/*
 * Connection events of an input port as detection weighs them.  While an NXT I2C device is
 * connected, pins 5 and 6 are its bus, toggled by d_iic: only pin 2 (grounded by every NXT
 * device) tells that the device is still there.
 */
static u8 analog_input_weighed_events(unsigned int port)
{
	u8 events = analog_input_events(port);

	if (analog.in[port].state == DCM_CONNECTED && analog.in[port].bus_pins)
		events &= DCM_IN_PIN2_LOW;
	return events;
}

/* Advances the detection of one input port by one DCM period. */
static void analog_input_tick(unsigned int port)
{
	struct analog_port *p = &analog.in[port];
	unsigned int pin1;

	switch (analog_dcm_step(p, analog_input_weighed_events(port))) {
	case DCM_STEP_EVALUATE:
		analog_input_evaluate(port);
		break;
	case DCM_STEP_GONE:
		analog_set_input(port, DEV_NONE);
		analog_input_float(port);
		break;
	case DCM_STEP_WAIT:
		if (p->state == DCM_RECHECK && p->state_ms >= DCM_REREAD_MS) {
			pin1 = analog_mv(port);
			analog_input_connect(port, pin1 >= 850 && pin1 <= 950 ?
					     DEV_NXT_TOUCH : DEV_NXT_SOUND);
		}
		break;
	}
}

/* Floats an output port for detection: pin 5w low, pin 6 released to d_pwm's input. */
static void analog_output_float(unsigned int port)
{
	const struct analog_output_pins *pins = &analog_output_pins[port];

	gpio_direction_output(pins->pin5w, 0);
	gpio_direction_input(pins->pin6);
	analog_dcm_restart(&analog.out[port]);
}

/* Latest voltage on an output port's pin 5 in mV. */
static unsigned int analog_output_pin5_mv(unsigned int port)
{
	return analog_mv(ANALOG_INPUT_CHANNELS + port);
}

/* Current connection events of an output port. */
static u8 analog_output_events(unsigned int port)
{
	unsigned int pin5 = analog_output_pin5_mv(port);
	u8 events = 0;

	if (gpio_get_value(analog_output_pins[port].pin6))
		events |= DCM_OUT_PIN6_HIGH;
	if (pin5 < 2400 || pin5 > 2600)
		events |= DCM_OUT_PIN5_ACTIVE;
	return events;
}

/* Declares an output port's device identified (DEV_NONE: look again from scratch). */
static void analog_output_connect(unsigned int port, enum analog_device dev)
{
	if (dev == DEV_NONE) {
		analog_output_float(port);
		return;
	}
	analog_set_output(port, dev);
	analog_dcm_enter(&analog.out[port], DCM_CONNECTED);
}

/* Classifies an output port from pin 5 read with pin 6 floating (first) and pulled low. */
static void analog_output_evaluate(unsigned int port, unsigned int low_mv)
{
	struct analog_port *p = &analog.out[port];
	unsigned int first = p->first_mv;
	unsigned int diff = first > low_mv ? first - low_mv : low_mv - first;
	enum analog_device dev;

	if (diff >= 50) {
		/* Pin 5 follows pin 6: a plain load between them. */
		dev = low_mv >= 100 && low_mv <= 2400 ? DEV_OUTPUT_DUMB : DEV_ERROR;
	} else if ((first >= 2400 && first <= 2600 && (p->events & DCM_OUT_PIN6_HIGH)) ||
		   first < 100 || (first >= 650 && first <= 850) ||
		   (first >= 2800 && first <= 3700)) {
		dev = DEV_ERROR;
	} else if (first < 2400) {
		if (first > 450)
			dev = DEV_NEWTACHO;
		else if (first >= 250)
			dev = DEV_MINITACHO;
		else
			dev = DEV_TACHO;
	} else if (first > 2600) {
		/* Encoder output high: pull pin 5 up to tell the motors apart. */
		gpio_direction_output(analog_output_pins[port].pin5w, 1);
		analog_dcm_enter(p, DCM_PIN5_HIGH);
		return;
	} else {
		dev = DEV_NONE;		/* back inside the idle window: nothing after all */
	}
	analog_output_connect(port, dev);
}

/* Advances the detection of one output port by one DCM period. */
static void analog_output_tick(unsigned int port)
{
	const struct analog_output_pins *pins = &analog_output_pins[port];
	struct analog_port *p = &analog.out[port];
	unsigned int mv;

	switch (analog_dcm_step(p, analog_output_events(port))) {
	case DCM_STEP_EVALUATE:
		p->first_mv = analog_output_pin5_mv(port);
		gpio_direction_output(pins->pin6, 0);
		analog_dcm_enter(p, DCM_PIN6_LOW);
		break;
	case DCM_STEP_GONE:
		analog_set_output(port, DEV_NONE);
		analog_output_float(port);
		break;
	case DCM_STEP_WAIT:
		if (p->state_ms < DCM_REREAD_MS)
			break;
		if (p->state == DCM_PIN6_LOW) {
			analog.shm->out_pin5_low[port] = analog.raw[ANALOG_INPUT_CHANNELS + port];
			mv = analog_output_pin5_mv(port);
			gpio_direction_input(pins->pin6);
			analog_output_evaluate(port, mv);
		} else if (p->state == DCM_PIN5_HIGH) {
			mv = analog_output_pin5_mv(port);
			gpio_direction_output(pins->pin5w, 0);
			if (mv < 1600)
				analog_output_connect(port, DEV_ERROR);
			else if (mv < 2000)
				analog_output_connect(port, DEV_MINITACHO);
			else
				analog_output_connect(port, DEV_TACHO);
		}
		break;
	}
}

/* Runs detection on every port every 10 ms, drift-free. */
static enum hrtimer_restart analog_dcm_tick(struct hrtimer *timer)
{
	unsigned int port;

	spin_lock(&analog.lock);
	for (port = 0; port < LMS_ANALOG_INPUTS; port++)
		analog_input_tick(port);
	for (port = 0; port < LMS_ANALOG_OUTPUTS; port++)
		analog_output_tick(port);
	spin_unlock(&analog.lock);
	hrtimer_forward_now(timer, ms_to_ktime(DCM_PERIOD_MS));
	return HRTIMER_RESTART;
}

/* ---- /dev/lms_analog ---- */

#define ANALOG_DUMP_SIZE	1024

/* Writes the human-readable state into text; returns its length. */
static size_t analog_dump(char *text, size_t size)
{
	const struct lms_analog *shm = analog.shm;
	unsigned long flags;
	size_t len = 0;
	unsigned int port;

	spin_lock_irqsave(&analog.lock, flags);
	len += scnprintf(text + len, size - len, "port conn type pin1_mv pin6_mv\n");
	for (port = 0; port < LMS_ANALOG_INPUTS; port++)
		len += scnprintf(text + len, size - len, "%u %d %d %u %u\n", port + 1,
				 shm->in_conn[port], shm->in_dcm[port], analog_mv(port),
				 analog_mv(4 + port));
	len += scnprintf(text + len, size - len, "port conn type pin5_mv\n");
	for (port = 0; port < LMS_ANALOG_OUTPUTS; port++)
		len += scnprintf(text + len, size - len, "%c %d %d %u\n", 'A' + port,
				 shm->out_conn[port], shm->out_dcm[port],
				 analog_output_pin5_mv(port));
	len += scnprintf(text + len, size - len,
			 "battery_mv %u battery_current %u motor_current %u battery_temp %u\n",
			 analog_mv(15), analog_mv(14), analog_mv(13), analog_mv(12));
	len += scnprintf(text + len, size - len, "cycles %u late_bursts %u spi_timeouts %u\n",
			 analog.cycles, analog.late_bursts, analog.spi_timeouts);
	spin_unlock_irqrestore(&analog.lock, flags);
	return len;
}

/* Copies the text dump from *ppos on; a read at position 0 takes a fresh snapshot. */
static ssize_t analog_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	char *text;
	size_t len;
	ssize_t ret;

	if (*ppos < 0)
		return -EINVAL;
	text = kmalloc(ANALOG_DUMP_SIZE, GFP_KERNEL);
	if (!text)
		return -ENOMEM;
	len = analog_dump(text, ANALOG_DUMP_SIZE);
	if (*ppos >= (loff_t)len) {
		ret = 0;
	} else {
		ret = min_t(size_t, count, len - *ppos);
		if (copy_to_user(buf, text + *ppos, ret))
			ret = -EFAULT;
		else
			*ppos += ret;
	}
	kfree(text);
	return ret;
}

/* Accepts and ignores data, as LEGO's driver does. */
static ssize_t analog_write(struct file *file, const char __user *buf, size_t count,
			    loff_t *ppos)
{
	return 0;
}

/* Repositions the dump (SEEK_SET and SEEK_CUR only: the dump has no fixed end). */
static loff_t analog_llseek(struct file *file, loff_t offset, int whence)
{
	loff_t pos;

	if (whence == SEEK_SET)
		pos = offset;
	else if (whence == SEEK_CUR)
		pos = file->f_pos + offset;
	else
		return -EINVAL;
	if (pos < 0)
		return -EINVAL;
	file->f_pos = pos;
	return pos;
}

/* Maps struct lms_analog (at most its page-rounded size, from offset 0). */
static int analog_mmap(struct file *file, struct vm_area_struct *vma)
{
	unsigned long len = vma->vm_end - vma->vm_start;

	if (vma->vm_pgoff || len > PAGE_ALIGN(sizeof(struct lms_analog)))
		return -EINVAL;
	if (remap_pfn_range(vma, vma->vm_start, virt_to_phys(analog.shm) >> PAGE_SHIFT, len,
			    vma->vm_page_prot))
		return -EAGAIN;
	return 0;
}

static const struct file_operations analog_fops = {
	.owner = THIS_MODULE,
	.read = analog_read,
	.write = analog_write,
	.llseek = analog_llseek,
	.mmap = analog_mmap,
};

static struct miscdevice analog_misc = {
	.minor = MISC_DYNAMIC_MINOR,
	.name = LMS_ANALOG_DEVICE_NAME,
	.fops = &analog_fops,
};

/* ---- /dev/lms_dcm ---- */

/* Returns in_dcm[4], out_dcm[4], '\r', 0: a status snapshot on every read. */
static ssize_t dcm_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	char status[LMS_DCM_READ_SIZE];
	unsigned long flags;

	if (count < LMS_DCM_READ_SIZE)
		return -EINVAL;
	spin_lock_irqsave(&analog.lock, flags);
	memcpy(status, analog.shm->in_dcm, LMS_ANALOG_INPUTS);
	memcpy(status + LMS_ANALOG_INPUTS, analog.shm->out_dcm, LMS_ANALOG_OUTPUTS);
	spin_unlock_irqrestore(&analog.lock, flags);
	status[LMS_ANALOG_INPUTS + LMS_ANALOG_OUTPUTS] = '\r';
	status[LMS_ANALOG_INPUTS + LMS_ANALOG_OUTPUTS + 1] = 0;
	if (copy_to_user(buf, status, sizeof(status)))
		return -EFAULT;
	return sizeof(status);
}

/* Applies one pin command per input port; all four are checked before any is applied. */
static ssize_t dcm_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	char cmd[LMS_DCM_WRITE_SIZE];
	unsigned long flags;
	unsigned int port;

	if (count < LMS_DCM_WRITE_SIZE)
		return -EINVAL;
	if (copy_from_user(cmd, buf, sizeof(cmd)))
		return -EFAULT;
	for (port = 0; port < LMS_ANALOG_INPUTS; port++) {
		if (cmd[port] >= 0x0D && cmd[port] <= 0x11)
			return -EOPNOTSUPP;	/* NXT colour sensor protocol */
		if (cmd[port] != LMS_DCM_KEEP && cmd[port] != LMS_DCM_FLOAT &&
		    (cmd[port] < '0' || cmd[port] > '7'))
			return -EINVAL;
	}

	spin_lock_irqsave(&analog.lock, flags);
	for (port = 0; port < LMS_ANALOG_INPUTS; port++) {
		/* Levels belong to the attached device; empty ports stay floating. */
		if (analog.in[port].state != DCM_CONNECTED || cmd[port] == LMS_DCM_KEEP)
			continue;
		if (cmd[port] == LMS_DCM_FLOAT) {
			analog_input_release_pins(port);
		} else {
			analog_input_drive(port, cmd[port] - '0');
		}
	}
	spin_unlock_irqrestore(&analog.lock, flags);
	return count;
}

static const struct file_operations dcm_fops = {
	.owner = THIS_MODULE,
	.read = dcm_read,
	.write = dcm_write,
};

static struct miscdevice dcm_misc = {
	.minor = MISC_DYNAMIC_MINOR,
	.name = LMS_DCM_DEVICE_NAME,
	.fops = &dcm_fops,
};

/* ---- Module ---- */

/* Requests one pin for d_analog, remembering it for analog_free_pins. */
static int analog_request_pin(unsigned int gpio)
{
	int ret = gpio_request(gpio, "d_analog");

	if (ret) {
		pr_err("d_analog: GPIO %u: request failed (%d)\n", gpio, ret);
		return ret;
	}
	analog.owned_pins[analog.owned_count++] = gpio;
	return 0;
}

/* Releases every pin analog_request_pins obtained. */
static void analog_free_pins(void)
{
	while (analog.owned_count)
		gpio_free(analog.owned_pins[--analog.owned_count]);
}

/* Requests the detection pins d_analog owns (see the ownership note at the top). */
static int analog_request_pins(void)
{
	unsigned int port;
	int ret = 0;

	for (port = 0; port < LMS_ANALOG_INPUTS && !ret; port++) {
		ret = analog_request_pin(analog_input_pins[port].pin1_9v);
		if (!ret)
			ret = analog_request_pin(analog_input_pins[port].pin2);
		if (!ret)
			ret = analog_request_pin(analog_input_pins[port].pin5);
		if (!ret)
			ret = analog_request_pin(analog_input_pins[port].pin6);
	}
	for (port = 0; port < LMS_ANALOG_OUTPUTS && !ret; port++)
		ret = analog_request_pin(analog_output_pins[port].pin5w);
	if (ret)
		analog_free_pins();
	return ret;
}

/* Allocates the shared ANALOG area: whole reserved pages, as remap_pfn_range needs. */
static int analog_alloc_shm(void)
{
	size_t size = PAGE_ALIGN(sizeof(struct lms_analog));
	size_t off;
	unsigned int port;

	analog.shm = kzalloc(size, GFP_KERNEL);
	if (!analog.shm)
		return -ENOMEM;
	for (off = 0; off < size; off += PAGE_SIZE)
		SetPageReserved(virt_to_page((char *)analog.shm + off));
	for (port = 0; port < LMS_ANALOG_INPUTS; port++)
		analog_set_input(port, DEV_NONE);
	for (port = 0; port < LMS_ANALOG_OUTPUTS; port++)
		analog_set_output(port, DEV_NONE);
	return 0;
}

/* Frees the shared ANALOG area. */
static void analog_free_shm(void)
{
	size_t size = PAGE_ALIGN(sizeof(struct lms_analog));
	size_t off;

	for (off = 0; off < size; off += PAGE_SIZE)
		ClearPageReserved(virt_to_page((char *)analog.shm + off));
	kfree(analog.shm);
	analog.shm = NULL;
}

/* Maps SPI0 (claimed: d_analog is its only user) and SYSCFG1 (system-wide, not claimed). */
static int analog_map_registers(void)
{
	if (!request_mem_region(SPI0_PHYS, SPI0_SIZE, "d_analog"))
		return -EBUSY;
	analog.spi = ioremap(SPI0_PHYS, SPI0_SIZE);
	if (!analog.spi)
		goto err_release;
	analog.syscfg1 = ioremap(SYSCFG1_PHYS, SYSCFG1_SIZE);
	if (!analog.syscfg1)
		goto err_unmap_spi;
	return 0;

err_unmap_spi:
	iounmap(analog.spi);
err_release:
	release_mem_region(SPI0_PHYS, SPI0_SIZE);
	return -ENOMEM;
}

/* Undoes analog_map_registers. */
static void analog_unmap_registers(void)
{
	iounmap(analog.syscfg1);
	iounmap(analog.spi);
	release_mem_region(SPI0_PHYS, SPI0_SIZE);
}

/* Floats every port this driver drives (at init and on the way out). */
static void analog_float_all(void)
{
	unsigned int port;

	for (port = 0; port < LMS_ANALOG_INPUTS; port++)
		analog_input_float(port);
	for (port = 0; port < LMS_ANALOG_OUTPUTS; port++)
		analog_output_float(port);
}

static int __init analog_init(void)
{
	int ret;

	BUILD_BUG_ON(sizeof(struct lms_analog) != LMS_ANALOG_SIZE);
	BUILD_BUG_ON(offsetof(struct lms_analog, battery_temp) != 24);
	BUILD_BUG_ON(offsetof(struct lms_analog, pin1) != 32);
	BUILD_BUG_ON(offsetof(struct lms_analog, pin6) != 2432);
	BUILD_BUG_ON(offsetof(struct lms_analog, actual) != 4832);
	BUILD_BUG_ON(offsetof(struct lms_analog, nxt_col) != 4856);
	BUILD_BUG_ON(offsetof(struct lms_analog, out_pin5_low) != 5144);
	BUILD_BUG_ON(offsetof(struct lms_analog, updated) != 5152);
	BUILD_BUG_ON(offsetof(struct lms_analog, out_conn) != 5168);

	if (dcm_start_ms < 0 || dcm_start_ms > 60000) {
		pr_err("d_analog: dcm_start_ms %d out of range 0..60000\n", dcm_start_ms);
		return -EINVAL;
	}
	/* Start from a clean slate even where the image is not reloaded between inits. */
	memset(&analog, 0, sizeof(analog));
	spin_lock_init(&analog.lock);

	ret = analog_alloc_shm();
	if (ret)
		return ret;
	ret = analog_map_registers();
	if (ret)
		goto err_free_shm;
	ret = analog_request_pins();
	if (ret)
		goto err_unmap;

	/* Pulls off: the port circuits' own resistors define the idle levels. */
	analog.pupd_saved = ioread32(analog.syscfg1 + SYSCFG1_PUPD_ENA);
	iowrite32(0, analog.syscfg1 + SYSCFG1_PUPD_ENA);
	analog_float_all();
	analog_spi_setup();
	ret = analog_adc_init();
	if (ret) {
		pr_err("d_analog: ADC does not answer on SPI0\n");
		goto err_restore;
	}

	hrtimer_init(&analog.sample_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	analog.sample_timer.function = analog_sample_tick;
	hrtimer_init(&analog.dcm_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	analog.dcm_timer.function = analog_dcm_tick;
	hrtimer_start(&analog.sample_timer, ms_to_ktime(1), HRTIMER_MODE_REL);
	hrtimer_start(&analog.dcm_timer, ms_to_ktime(dcm_start_ms), HRTIMER_MODE_REL);

	ret = misc_register(&analog_misc);
	if (ret)
		goto err_timers;
	ret = misc_register(&dcm_misc);
	if (ret)
		goto err_analog_misc;
	return 0;

err_analog_misc:
	misc_deregister(&analog_misc);
err_timers:
	hrtimer_cancel(&analog.dcm_timer);
	hrtimer_cancel(&analog.sample_timer);
err_restore:
	analog_spi_restore();
	iowrite32(analog.pupd_saved, analog.syscfg1 + SYSCFG1_PUPD_ENA);
	analog_free_pins();
err_unmap:
	analog_unmap_registers();
err_free_shm:
	analog_free_shm();
	return ret;
}

static void __exit analog_exit(void)
{
	misc_deregister(&dcm_misc);
	misc_deregister(&analog_misc);
	hrtimer_cancel(&analog.dcm_timer);
	hrtimer_cancel(&analog.sample_timer);
	analog_float_all();
	analog_spi_restore();
	iowrite32(analog.pupd_saved, analog.syscfg1 + SYSCFG1_PUPD_ENA);
	analog_free_pins();
	analog_unmap_registers();
	analog_free_shm();
}

module_init(analog_init);
module_exit(analog_exit);

MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("EV3 analog inputs and device connection manager (lms2012 d_analog)");
