// SPDX-License-Identifier: GPL-2.0
/*
 * d_iic.c - NXT I2C sensors on the EV3's input ports (/dev/lms_iic).
 *
 * Interface-compatible with LEGO's lms2012 d_iic (see lms_iic.h): LEGO's ioctls, the IIC shared
 * memory, a port state machine on a 2 ms hrtimer that probes the sensor (the NXT temperature
 * sensor at 0x4C, else the manufacturer and sensor type strings at registers 0x08 and 0x10 of
 * the first address from 0x01 that answers), sends its setup string and polls it.
 *
 * The bus is bit-banged on the port pins, one half SCL period per tick of a 50 us periodic
 * interrupt (SCL about 10 kHz), the interrupt running only while a transaction is under way.
 * LEGO routes that interrupt to the ARM's FIQ so that nothing delays it; a Linux driver cannot
 * claim the FIQ portably, so here it is a normal IRQ which the platform should give the highest
 * priority among the device interrupts.  The waveform (the bus has no clock stretching):
 *   START         SCL and SDA high for a tick, then SDA falls while SCL is high;
 *   a bit         SCL low and SDA set in one tick, SCL high (the slave samples) the next;
 *   ACK slot      SDA released with SCL low, sampled with SCL high (low = ACK, high = NACK);
 *   after an ACKed byte the master holds SCL low for 5 more ticks (3 after a byte it read);
 *   write->read   not a repeated START: SDA low, SCL high, SDA high (a STOP), one more SCL
 *                 low/high period with SDA high, then a START and the address with R = 1;
 *   the end       SDA low with SCL low, SCL high, SDA released: a STOP;
 *   bus clear     a START finding SDA held low (a slave still sending after an aborted
 *                 transaction) first gives up to 9 clocks until the slave lets go; if SDA
 *                 stays low (no sensor, so no pull-up) the transaction fails at once.
 * A poll that fails withdraws the port's data (DATA_READY cleared) until an answer comes; a
 * sensor answering again after failed polls (plugged in again) gets its setup string again.
 * SCL is driven push-pull; SDA is open-drain (driven low, or released to the sensor's pull-up),
 * so a port with nothing on it never reads as ACK.
 *
 * Hardware (EV3 EP2 board; AM1808 TRM, Timer64P and GPIO chapters):
 *   port        buffer enable (low = on)   SCL (connector pin 5)    SDA (connector pin 6)
 *   1           GP8_11                     GP1_0                    GP0_15
 *   2           GP8_14                     GP8_3                    GP0_13
 *   3           GP7_9                      GP1_12                   GP1_14
 *   4           GP7_10                     GP1_11                   GP1_15
 * SCL reaches pin 5 through the port's buffer (the UART TX path), so the buffer is enabled while
 * the port is an I2C port.  The SCL pads of ports 1 and 2 are the UART1/UART0 TX pads: they are
 * muxed to GPIO when the port starts (PINMUX4[31:28] = 8, PINMUX3[23:20] = 4).  Internal pulls
 * are off on the EV3 (SYSCFG1 PUPD_ENA = 0), so the lines rest on the sensor's pull-ups.
 * The tick is Timer64P1's TIM34 (0x01C21000) in dual 32-bit unchained mode, continuous, period
 * 50 us of its 24 MHz input (PRD34 = 1199), its period interrupt TINT34_1 (AINTC 24).
 *
 * GPIO ownership: d_analog requests pins 5 and 6 of the input ports and d_uart the buffer
 * enables; while a port is connected as NXT I2C (SET_CONN), d_iic drives them and its SCL pad
 * through the GPIO bank registers (without requests, as the tick must not sleep or lock gpiolib
 * for each bit); d_analog then only reads them.
 */
#include <linux/module.h>
#include <linux/init.h>
#include <linux/kernel.h>
#include <linux/types.h>
#include <linux/errno.h>
#include <linux/bits.h>
#include <linux/string.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/io.h>
#include <linux/ioport.h>
#include <linux/interrupt.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/spinlock.h>
#include <linux/uaccess.h>

#include "lms_iic.h"

#define GP(bank, bit)		((bank) * 16 + (bit))	/* DaVinci GPIO number */

static char *HwId = "03";
module_param(HwId, charp, 0444);
MODULE_PARM_DESC(HwId, "LEGO hardware id (accepted for lms2012 compatibility; EP2 wiring is used)");

static uint timer_clock_hz = 24000000;
module_param(timer_clock_hz, uint, 0444);
MODULE_PARM_DESC(timer_clock_hz, "Timer64P1 input clock in Hz (default 24 MHz)");

static int timer_irq = 24;
module_param(timer_irq, int, 0444);
MODULE_PARM_DESC(timer_irq, "IRQ of Timer64P1's TINT34 (default AINTC 24)");

/* ---- Registers ---- */

#define GPIO_PHYS		0x01E26000
#define GPIO_SIZE		0x100
#define GPIO_BANK_REGS(pin)	(0x10 + 0x28 * ((pin) / 32))
#define GPIO_DIR		0x00	/* bit = 1: input */
#define GPIO_SET_DATA		0x08
#define GPIO_CLR_DATA		0x0C
#define GPIO_IN_DATA		0x10

#define SYSCFG0_PHYS		0x01C14000
#define SYSCFG0_SIZE		0x200
#define SYSCFG0_KICK0R		0x38
#define SYSCFG0_KICK1R		0x3C
#define SYSCFG0_KICK0_KEY	0x83E70B13
#define SYSCFG0_KICK1_KEY	0x95A4F1E0
#define SYSCFG0_PINMUX(n)	(0x120 + 4 * (n))

#define TIMER64P1_PHYS		0x01C21000
#define TIMER64_SIZE		0x80
#define TIMER64_TIM34		0x14
#define TIMER64_PRD34		0x1C
#define TIMER64_TCR		0x20
#define TIMER64_TGCR		0x24
#define TIMER64_INTCTLSTAT	0x44
#define TCR_ENAMODE34_MASK	(3U << 22)
#define TCR_ENAMODE34_CONT	(2U << 22)
#define TGCR_TIM34RS		BIT(1)
#define TGCR_TIMMODE_DUAL_UNCHAINED (1U << 2)
#define INTCTLSTAT_PRDINTEN34	BIT(16)
#define INTCTLSTAT_PRDINTSTAT34	BIT(17)

#define BIT_PERIOD_NS		50000	/* one tick: half an SCL period */

/* ---- Timing, in port ticks of 2 ms ---- */

#define PORT_TICK_MS		2
#define PROBE_TIMEOUT_TICKS	25	/* an ID or setup transaction (50 ms) */
#define READ_TIMEOUT_TICKS	250	/* a poll or SETUP transaction (0.5 s) */
#define SETUP_WAIT_TICKS	500	/* 1 s for user space to react to the ID */
#define RESTART_TICKS		5	/* port off before probing again */
#define PROBE_ROUNDS		3
#define FIRST_ADDRESS		0x01
#define LAST_ADDRESS		0x50
#define TEMP_ADDRESS		0x4C	/* NXT temperature sensor */
#define TEMP_CONFIG_REG		0x01
#define TEMP_CONFIG_12BIT	0x60
#define MANUFACTURER_REG	0x08	/* NXT I2C sensors: 8 characters */
#define SENSOR_TYPE_REG		0x10	/* 8 characters */
#define ID_LENGTH		8
#define WRITE_HOLD_TICKS	5	/* SCL low after an ACKed byte written */
#define READ_HOLD_TICKS		3	/* SCL low after a byte read */
#define RECOVER_CLOCKS		9	/* bus clear: clocks until a slave lets SDA go */

struct iic_pins {
	unsigned int buffer;	/* TX buffer enable, low = on */
	unsigned int scl;
	unsigned int sda;
	int mux_reg;		/* PINMUX of the SCL pad, -1: left to the board */
	unsigned int mux_shift;
	u32 mux_gpio;
};

static const struct iic_pins iic_pins[LMS_IIC_PORTS] = {
	{ GP(8, 11), GP(1, 0),  GP(0, 15), 4, 28, 8 },
	{ GP(8, 14), GP(8, 3),  GP(0, 13), 3, 20, 4 },
	{ GP(7, 9),  GP(1, 12), GP(1, 14), -1, 0, 0 },
	{ GP(7, 10), GP(1, 11), GP(1, 15), -1, 0, 0 },
};

/* ---- The bit engine: one transaction per port, advanced every tick ---- */

enum bus_step {
	BUS_IDLE,
	BUS_START,		/* both lines high */
	BUS_RECOVER,		/* SCL low: one clock for a slave holding SDA */
	BUS_START_SDA,		/* SDA falls with SCL high: START */
	BUS_BIT_LOW,		/* SCL low, next data bit on SDA (or SDA released to read) */
	BUS_BIT_HIGH,		/* SCL high: the bit is valid */
	BUS_ACK_LOW,		/* SCL low, SDA released for the slave's ACK */
	BUS_ACK_HIGH,		/* SCL high: sample the ACK */
	BUS_MACK_LOW,		/* SCL low, master's ACK/NACK on SDA */
	BUS_MACK_HIGH,
	BUS_HOLD,		/* SCL held low */
	BUS_TURN_LOW,		/* write->read turnaround: SCL low, SDA low */
	BUS_TURN_HIGH,		/* SCL high */
	BUS_TURN_STOP,		/* SDA high: STOP */
	BUS_TURN_CLOCK_LOW,	/* one more clock with SDA high */
	BUS_TURN_CLOCK_HIGH,
	BUS_STOP_LOW,		/* SCL low, SDA low */
	BUS_STOP_HIGH,		/* SCL high */
	BUS_STOP_SDA,		/* SDA released: STOP */
};

enum bus_result {
	BUS_DONE_OK,
	BUS_DONE_NACK,
};

struct iic_bus {
	u8 step;		/* enum bus_step; BUS_IDLE when no transaction runs */
	u8 result;		/* enum bus_result, valid once step is BUS_IDLE */
	u8 addr;		/* 7-bit address */
	u8 wr_len;		/* bytes after the address byte to write */
	u8 rd_len;		/* bytes to read */
	u8 pos;			/* index in data of the byte being moved */
	u8 bit;			/* bits of the current byte done */
	u8 shift;		/* the byte being sent or received */
	u8 hold;		/* ticks left in BUS_HOLD */
	u8 recover;		/* bus-clear clocks given before this START */
	bool reading;		/* the address went with R = 1 */
	bool addr_byte;		/* the byte on the bus is the address */
	u8 data[LMS_IIC_DATA_SIZE];	/* written bytes; the read bytes overwrite them from 0 */
};

/* ---- Ports ---- */

enum req_state {
	REQ_NONE,
	REQ_PENDING,		/* latched by IIC_SETUP, waiting for the bus */
	REQ_RUNNING,
	REQ_DONE,		/* answer ready (DATA_READY) */
};

struct iic_port {
	u8 state;		/* LMS_IIC_STATE_* */
	u8 mode;
	u16 timer;		/* port ticks in the current state */
	u8 addr;		/* the sensor's address once probed */
	u8 round;		/* manufacturer scan rounds */
	bool identified;
	struct iic_bus bus;
	/* IIC_SET */
	bool configured;	/* IIC_SET given: go on from the ID to setup and polling */
	bool poll_failed;	/* the last poll got no answer (the sensor may be re-plugged) */
	bool resetup;		/* answering again after failing: send the setup string again */
	u16 time_ms;
	u8 setup_lng, poll_lng;
	u8 setup[LMS_IIC_STRING_SIZE], poll[LMS_IIC_STRING_SIZE];
	s8 read_lng;
	char manufacturer[LMS_IIC_NAME_SIZE];
	char sensor_type[LMS_IIC_NAME_SIZE];
	/* IIC_SETUP */
	u8 req_state;		/* enum req_state */
	bool request;		/* the transaction under way is a SETUP's */
	bool request_failed;
	bool req_answered;	/* req_answer holds an answer not yet taken */
	u8 req_left;		/* transactions left after this one */
	bool req_forever;
	u16 req_time_ms;
	u8 req_wr_len;
	u8 req_wr[LMS_IIC_DATA_SIZE];
	s8 req_rd_lng;
	u8 req_answer[LMS_IIC_DATA_SIZE];
};

static struct {
	spinlock_t lock;	/* ports, buses, shared memory, timer start/stop */
	struct lms_iic *shm;
	struct iic_port port[LMS_IIC_PORTS];
	u8 __iomem *gpio;
	u8 __iomem *syscfg0;
	u8 __iomem *timer;
	bool ticking;		/* Timer64P1 runs */
	struct hrtimer port_timer;
	int irq;
} iic;

/* ---- GPIO ---- */

static void pin_drive(unsigned int pin, bool high)
{
	u8 __iomem *bank = iic.gpio + GPIO_BANK_REGS(pin);
	u32 mask = BIT(pin % 32);

	writel(mask, bank + (high ? GPIO_SET_DATA : GPIO_CLR_DATA));
	writel(readl(bank + GPIO_DIR) & ~mask, bank + GPIO_DIR);
}

static void pin_release(unsigned int pin)
{
	u8 __iomem *bank = iic.gpio + GPIO_BANK_REGS(pin);

	writel(readl(bank + GPIO_DIR) | BIT(pin % 32), bank + GPIO_DIR);
}

static bool pin_level(unsigned int pin)
{
	return readl(iic.gpio + GPIO_BANK_REGS(pin) + GPIO_IN_DATA) & BIT(pin % 32);
}

/* SCL is push-pull: no clock stretching on this bus. */
static void scl_set(unsigned int port, bool high)
{
	pin_drive(iic_pins[port].scl, high);
}

/* SDA is open-drain: low is driven, high is the pull-up's. */
static void sda_set(unsigned int port, bool high)
{
	if (high)
		pin_release(iic_pins[port].sda);
	else
		pin_drive(iic_pins[port].sda, false);
}

static void iic_pinmux(const struct iic_pins *pins)
{
	u8 __iomem *reg;

	if (pins->mux_reg < 0)
		return;
	reg = iic.syscfg0 + SYSCFG0_PINMUX(pins->mux_reg);
	writel(SYSCFG0_KICK0_KEY, iic.syscfg0 + SYSCFG0_KICK0R);
	writel(SYSCFG0_KICK1_KEY, iic.syscfg0 + SYSCFG0_KICK1R);
	writel((readl(reg) & ~(0xFU << pins->mux_shift)) | pins->mux_gpio << pins->mux_shift, reg);
	writel(0, iic.syscfg0 + SYSCFG0_KICK0R);
	writel(0, iic.syscfg0 + SYSCFG0_KICK1R);
}

/* Gives the port's pins to the bus: buffer on, SCL and SDA high (idle bus). */
static void iic_port_enable(unsigned int port)
{
	const struct iic_pins *pins = &iic_pins[port];

	iic_pinmux(pins);
	pin_drive(pins->scl, true);
	pin_release(pins->sda);
	pin_drive(pins->buffer, false);
}

/* Gives the pins back: buffer off, SCL pad and SDA floating. */
static void iic_port_disable(unsigned int port)
{
	const struct iic_pins *pins = &iic_pins[port];

	pin_drive(pins->buffer, true);
	pin_release(pins->sda);
	pin_release(pins->scl);
}

/* ---- Timer64P1 tick ---- */

static void tick_start(void)
{
	if (iic.ticking)
		return;
	writel(0, iic.timer + TIMER64_TIM34);
	writel((readl(iic.timer + TIMER64_TCR) & ~TCR_ENAMODE34_MASK) | TCR_ENAMODE34_CONT,
	       iic.timer + TIMER64_TCR);
	iic.ticking = true;
}

static void tick_stop(void)
{
	writel(readl(iic.timer + TIMER64_TCR) & ~TCR_ENAMODE34_MASK, iic.timer + TIMER64_TCR);
	iic.ticking = false;
}

static void tick_setup(void)
{
	u32 period = timer_clock_hz / (NSEC_PER_SEC / BIT_PERIOD_NS);

	writel(0, iic.timer + TIMER64_TCR);
	writel(0, iic.timer + TIMER64_TGCR);		/* both halves in reset */
	writel(period - 1, iic.timer + TIMER64_PRD34);
	writel(0, iic.timer + TIMER64_TIM34);
	writel(TGCR_TIMMODE_DUAL_UNCHAINED | TGCR_TIM34RS, iic.timer + TIMER64_TGCR);
	writel(INTCTLSTAT_PRDINTEN34 | INTCTLSTAT_PRDINTSTAT34, iic.timer + TIMER64_INTCTLSTAT);
}

/* ---- Bit engine ---- */

/* Starts a transaction: write wr_len bytes of data to addr, then read rd_len bytes. */
static void bus_start(unsigned int port, u8 addr, const u8 *data, u8 wr_len, u8 rd_len)
{
	struct iic_bus *b = &iic.port[port].bus;

	b->addr = addr;
	b->wr_len = wr_len;
	b->rd_len = rd_len;
	memcpy(b->data, data, wr_len);
	b->step = BUS_START;
	b->reading = false;
	tick_start();
}

static void bus_abort(unsigned int port)
{
	struct iic_bus *b = &iic.port[port].bus;

	if (b->step == BUS_IDLE)
		return;
	b->step = BUS_IDLE;
	b->result = BUS_DONE_NACK;
	scl_set(port, true);
	sda_set(port, true);
}

/* Drops the port's transaction; a SETUP request that was on the bus is sent again. */
static void port_abort(unsigned int port)
{
	struct iic_port *p = &iic.port[port];

	bus_abort(port);
	if (p->request && p->req_state == REQ_RUNNING)
		p->req_state = REQ_PENDING;
	p->request = false;
}

/* Forgets a SETUP request (the port starts or stops). */
static void port_forget_request(struct iic_port *p)
{
	p->req_state = REQ_NONE;
	p->request = false;
	p->req_answered = false;
}

/* What follows a byte written and ACKed. */
static enum bus_step bus_after_write(struct iic_bus *b)
{
	if (b->reading) {
		b->pos = 0;
		b->bit = 0;
		return BUS_BIT_LOW;
	}
	if (b->pos < b->wr_len) {
		b->shift = b->data[b->pos++];
		b->bit = 0;
		return BUS_BIT_LOW;
	}
	return b->rd_len ? BUS_TURN_LOW : BUS_STOP_LOW;
}

/* Advances one port's transaction by one tick (half an SCL period). */
static void bus_tick(unsigned int port)
{
	struct iic_bus *b = &iic.port[port].bus;
	bool receiving = b->reading && !b->addr_byte;

	switch (b->step) {
	case BUS_START:
		scl_set(port, true);
		sda_set(port, true);
		if (!pin_level(iic_pins[port].sda)) {
			if (b->recover < RECOVER_CLOCKS) {
				/* a slave still holds SDA (an aborted read): clock it out (bus clear) */
				b->recover++;
				b->step = BUS_RECOVER;
				break;
			}
			/* SDA stays low: no sensor's pull-up (unplugged), or a slave that hangs */
			b->recover = 0;
			b->result = BUS_DONE_NACK;
			b->step = BUS_IDLE;
			break;
		}
		b->recover = 0;
		b->step = BUS_START_SDA;
		break;
	case BUS_RECOVER:
		scl_set(port, false);
		b->step = BUS_START;
		break;
	case BUS_START_SDA:
		sda_set(port, false);
		/* the address goes with R = 1 only when there is nothing to write */
		if (!b->wr_len && b->rd_len)
			b->reading = true;
		b->shift = (u8)(b->addr << 1 | (b->reading ? 1 : 0));
		b->addr_byte = true;
		b->bit = 0;
		b->pos = 0;
		b->step = BUS_BIT_LOW;
		break;
	case BUS_BIT_LOW:
		scl_set(port, false);
		sda_set(port, receiving ? true : (b->shift & 0x80) != 0);
		b->step = BUS_BIT_HIGH;
		break;
	case BUS_BIT_HIGH:
		scl_set(port, true);
		if (receiving)
			b->shift = (u8)(b->shift << 1 | (pin_level(iic_pins[port].sda) ? 1 : 0));
		else
			b->shift <<= 1;
		if (++b->bit < 8)
			b->step = BUS_BIT_LOW;
		else
			b->step = receiving ? BUS_MACK_LOW : BUS_ACK_LOW;
		break;
	case BUS_ACK_LOW:
		scl_set(port, false);
		sda_set(port, true);
		b->step = BUS_ACK_HIGH;
		break;
	case BUS_ACK_HIGH:
		scl_set(port, true);
		if (pin_level(iic_pins[port].sda)) {
			b->result = BUS_DONE_NACK;
			b->step = BUS_STOP_LOW;
			break;
		}
		b->hold = WRITE_HOLD_TICKS;
		b->step = BUS_HOLD;
		break;
	case BUS_MACK_LOW:
		b->data[b->pos++] = b->shift;
		scl_set(port, false);
		sda_set(port, b->pos >= b->rd_len);	/* ACK for more, NACK for the last */
		b->step = BUS_MACK_HIGH;
		break;
	case BUS_MACK_HIGH:
		scl_set(port, true);
		if (b->pos >= b->rd_len) {
			b->result = BUS_DONE_OK;
			b->step = BUS_STOP_LOW;
		} else {
			b->bit = 0;
			b->hold = READ_HOLD_TICKS;
			b->step = BUS_HOLD;
		}
		break;
	case BUS_HOLD:
		scl_set(port, false);
		if (--b->hold)
			break;
		if (receiving) {
			b->step = BUS_BIT_LOW;
			break;
		}
		b->addr_byte = false;
		b->step = bus_after_write(b);
		if (b->step == BUS_STOP_LOW)
			b->result = BUS_DONE_OK;
		break;
	case BUS_TURN_LOW:
		scl_set(port, false);
		sda_set(port, false);
		b->step = BUS_TURN_HIGH;
		break;
	case BUS_TURN_HIGH:
		scl_set(port, true);
		b->step = BUS_TURN_STOP;
		break;
	case BUS_TURN_STOP:
		sda_set(port, true);
		b->step = BUS_TURN_CLOCK_LOW;
		break;
	case BUS_TURN_CLOCK_LOW:
		scl_set(port, false);
		b->step = BUS_TURN_CLOCK_HIGH;
		break;
	case BUS_TURN_CLOCK_HIGH:
		scl_set(port, true);
		b->reading = true;
		b->step = BUS_START_SDA;
		break;
	case BUS_STOP_LOW:
		scl_set(port, false);
		sda_set(port, false);
		b->step = BUS_STOP_HIGH;
		break;
	case BUS_STOP_HIGH:
		scl_set(port, true);
		b->step = BUS_STOP_SDA;
		break;
	case BUS_STOP_SDA:
		sda_set(port, true);
		b->step = BUS_IDLE;
		break;
	default:
		b->step = BUS_IDLE;
		break;
	}
}

/* TINT34 of Timer64P1, every 50 us while a transaction runs. */
static irqreturn_t iic_tick_irq(int irq, void *dev_id)
{
	unsigned int port;
	bool busy = false;

	if (!(readl(iic.timer + TIMER64_INTCTLSTAT) & INTCTLSTAT_PRDINTSTAT34))
		return IRQ_NONE;
	writel(INTCTLSTAT_PRDINTEN34 | INTCTLSTAT_PRDINTSTAT34, iic.timer + TIMER64_INTCTLSTAT);
	spin_lock(&iic.lock);
	for (port = 0; port < LMS_IIC_PORTS; port++) {
		if (iic.port[port].bus.step == BUS_IDLE)
			continue;
		bus_tick(port);
		busy |= iic.port[port].bus.step != BUS_IDLE;
	}
	if (!busy)
		tick_stop();
	spin_unlock(&iic.lock);
	return IRQ_HANDLED;
}

/* ---- Port state machine (2 ms) ---- */

static void port_enter(struct iic_port *p, u8 state)
{
	p->state = state;
	p->timer = 0;
}

static bool bus_done(const struct iic_port *p)
{
	return p->bus.step == BUS_IDLE;
}

/* Unpacks an MSB-first string of lng bytes (address first). */
static void unpack_string(u8 *out, u32 packed, u8 lng)
{
	unsigned int i;

	for (i = 0; i < lng; i++)
		out[i] = (u8)(packed >> (24 - 8 * i));
}

/* Stores a read answer as LEGO lays it out: reversed for n > 1, bus order for n < 0. */
static void store_answer(u8 *dst, const u8 *bytes, s8 rd_lng)
{
	unsigned int n = rd_lng < 0 ? (unsigned int)-rd_lng : (unsigned int)rd_lng;
	unsigned int i;

	memset(dst, 0, LMS_IIC_DATA_SIZE);
	if (rd_lng > 1) {
		for (i = 0; i < n; i++)
			dst[i] = bytes[n - 1 - i];
	} else {
		memcpy(dst, bytes, n);
	}
}

static unsigned int read_count(s8 rd_lng)
{
	return rd_lng < 0 ? (unsigned int)-rd_lng : (unsigned int)rd_lng;
}

/* Copies an 8-byte ID answer into a string; empty if the sensor sent nothing printable. */
static void id_string(char *dst, const u8 *src, const char *if_zero)
{
	unsigned int i;

	if (!src[0]) {
		strscpy(dst, if_zero, LMS_IIC_NAME_SIZE);
		return;
	}
	for (i = 0; i < ID_LENGTH; i++)
		dst[i] = (src[i] >= 0x20 && src[i] < 0x7F) ? (char)src[i] : '\0';
	dst[ID_LENGTH] = '\0';
}

static void port_identified(unsigned int index, struct iic_port *p)
{
	p->identified = true;
	iic.shm->changed[index] = 1;
	iic.shm->status[index] |= LMS_IIC_PORT_CHANGED;
	port_enter(p, LMS_IIC_STATE_SETUP_WAIT);
}

/* Puts a poll answer into the raw ring. */
static void log_sample(unsigned int index, const u8 *answer)
{
	struct lms_iic *shm = iic.shm;
	u16 slot = shm->log_in[index];

	memcpy(shm->raw[index][slot], answer, LMS_IIC_DATA_SIZE);
	shm->repeat[index][slot] = 0;
	shm->actual[index] = slot;
	shm->log_in[index] = (u16)((slot + 1) % LMS_IIC_LOG_SIZE);
	shm->status[index] |= LMS_IIC_DATA_READY;
}

/* Starts the next poll or pending SETUP transaction; false if there is none. */
static bool port_start_transfer(unsigned int index, struct iic_port *p)
{
	if (p->req_state == REQ_PENDING) {
		p->req_state = REQ_RUNNING;
		p->request = true;
		bus_start(index, p->req_wr[0], p->req_wr + 1, (u8)(p->req_wr_len - 1),
			  (u8)read_count(p->req_rd_lng));
		return true;
	}
	if (p->poll_lng) {
		p->request = false;
		bus_start(index, p->poll[0], p->poll + 1, (u8)(p->poll_lng - 1), (u8)read_count(p->read_lng));
		return true;
	}
	return false;
}

/* A poll or SETUP transaction ended (or timed out: ok false). */
static void port_transfer_done(unsigned int index, struct iic_port *p, bool ok)
{
	if (p->request) {
		if (ok)
			store_answer(p->req_answer, p->bus.data, p->req_rd_lng);
		p->request_failed = !ok;
		p->req_answered = true;
		p->req_state = REQ_DONE;
		iic.shm->status[index] |= LMS_IIC_DATA_READY;
		return;
	}
	if (ok) {
		u8 answer[LMS_IIC_DATA_SIZE];

		store_answer(answer, p->bus.data, p->read_lng);
		log_sample(index, answer);
		if (p->poll_failed && p->setup_lng)
			p->resetup = true;	/* plugged in again, its settings at power-up values */
		p->poll_failed = false;
	} else {
		/* no answer (unplugged?): the data is withdrawn until the sensor answers again */
		iic.shm->status[index] &= ~LMS_IIC_DATA_READY;
		p->poll_failed = true;
	}
}

static void port_tick(unsigned int index)
{
	struct iic_port *p = &iic.port[index];
	struct lms_iic *shm = iic.shm;
	static const u8 temp_setup[] = { TEMP_CONFIG_REG, TEMP_CONFIG_12BIT };
	u8 reg;

	p->timer++;
	if (p->poll_lng && p->identified)
		shm->repeat[index][shm->actual[index]] += PORT_TICK_MS;
	switch (p->state) {
	case LMS_IIC_STATE_INIT:
		bus_abort(index);
		port_forget_request(p);
		p->manufacturer[0] = p->sensor_type[0] = '\0';
		p->identified = false;
		shm->changed[index] = 0;
		shm->status[index] = 0;
		port_enter(p, LMS_IIC_STATE_ENABLE);
		break;
	case LMS_IIC_STATE_RESTART:
		if (p->timer >= RESTART_TICKS)
			port_enter(p, LMS_IIC_STATE_ENABLE);
		break;
	case LMS_IIC_STATE_ENABLE:
		iic_port_enable(index);
		p->round = 0;
		p->addr = FIRST_ADDRESS;
		port_enter(p, LMS_IIC_STATE_TEMP_START);
		break;
	case LMS_IIC_STATE_TEMP_START:
		bus_start(index, TEMP_ADDRESS, temp_setup, sizeof(temp_setup), 1);
		port_enter(p, LMS_IIC_STATE_TEMP_WRITE);
		break;
	case LMS_IIC_STATE_MANUF_START:
	case LMS_IIC_STATE_TYPE_START:
		reg = p->state == LMS_IIC_STATE_MANUF_START ? MANUFACTURER_REG : SENSOR_TYPE_REG;
		bus_start(index, p->addr, &reg, 1, ID_LENGTH);
		port_enter(p, p->state + 1);
		break;
	case LMS_IIC_STATE_TEMP_WRITE:
	case LMS_IIC_STATE_MANUF_WRITE:
	case LMS_IIC_STATE_TYPE_WRITE:
	case LMS_IIC_STATE_SETUP_WRITE:
		if (bus_done(p)) {
			port_enter(p, p->state + 1);
		} else if (p->timer > PROBE_TIMEOUT_TICKS) {
			bus_abort(index);
			port_enter(p, p->state + 1);
		}
		break;
	case LMS_IIC_STATE_TEMP_READ:
		if (p->bus.result == BUS_DONE_OK && p->bus.data[0] == TEMP_CONFIG_12BIT) {
			p->addr = TEMP_ADDRESS;
			strscpy(p->manufacturer, "LEGO", sizeof(p->manufacturer));
			strscpy(p->sensor_type, "Temp.", sizeof(p->sensor_type));
			port_identified(index, p);
		} else {
			port_enter(p, LMS_IIC_STATE_MANUF_START);
		}
		break;
	case LMS_IIC_STATE_MANUF_READ:
		if (p->bus.result == BUS_DONE_OK) {
			id_string(p->manufacturer, p->bus.data, "LEGO");
			port_enter(p, LMS_IIC_STATE_TYPE_START);
			break;
		}
		if (++p->addr > LAST_ADDRESS) {
			p->addr = FIRST_ADDRESS;
			if (++p->round >= PROBE_ROUNDS) {
				port_enter(p, LMS_IIC_STATE_SETUP_START);	/* no ID */
				break;
			}
		}
		port_enter(p, LMS_IIC_STATE_MANUF_START);
		break;
	case LMS_IIC_STATE_TYPE_READ:
		if (p->bus.result == BUS_DONE_OK)
			id_string(p->sensor_type, p->bus.data, "Store");
		else
			p->sensor_type[0] = '\0';
		port_identified(index, p);
		break;
	case LMS_IIC_STATE_SETUP_WAIT:
		if (p->configured) {
			port_enter(p, LMS_IIC_STATE_SETUP_START);
		} else if (p->req_state == REQ_PENDING) {
			port_enter(p, LMS_IIC_STATE_WAITING);
		} else if (p->timer >= SETUP_WAIT_TICKS) {
			/* nobody took the sensor: start over, it may have been exchanged */
			iic_port_disable(index);
			port_enter(p, LMS_IIC_STATE_RESTART);
		}
		break;
	case LMS_IIC_STATE_SETUP_START:
		if (p->setup_lng) {
			bus_start(index, p->setup[0], p->setup + 1, (u8)(p->setup_lng - 1), 0);
			port_enter(p, LMS_IIC_STATE_SETUP_WRITE);
		} else {
			port_enter(p, LMS_IIC_STATE_SETUP_READ);
		}
		break;
	case LMS_IIC_STATE_SETUP_READ:
		port_enter(p, p->poll_lng ? LMS_IIC_STATE_WRITING : LMS_IIC_STATE_WAITING);
		break;
	case LMS_IIC_STATE_WAITING:
		if (port_start_transfer(index, p))
			port_enter(p, LMS_IIC_STATE_READING);
		break;
	case LMS_IIC_STATE_WRITING:
		if (port_start_transfer(index, p))
			port_enter(p, LMS_IIC_STATE_READING);
		else
			port_enter(p, LMS_IIC_STATE_WAITING);
		break;
	case LMS_IIC_STATE_READING:
		if (bus_done(p)) {
			port_transfer_done(index, p, p->bus.result == BUS_DONE_OK);
			port_enter(p, p->resetup ? LMS_IIC_STATE_SETUP_START : LMS_IIC_STATE_REPEAT);
			p->resetup = false;
		} else if (p->timer >= READ_TIMEOUT_TICKS) {
			bus_abort(index);
			if (p->request) {
				p->req_state = REQ_NONE;
				p->request = false;
				shm->status[index] &= ~(LMS_IIC_WRITE_REQUEST | LMS_IIC_DATA_READY);
			}
			port_enter(p, LMS_IIC_STATE_WAITING);
		}
		break;
	case LMS_IIC_STATE_REPEAT: {
		u16 wait_ms = p->request ? p->req_time_ms : p->time_ms;

		if ((u32)p->timer * PORT_TICK_MS < wait_ms)
			break;
		if (p->request && p->req_state == REQ_DONE && (p->req_forever || p->req_left)) {
			if (p->req_left)
				p->req_left--;
			p->req_state = REQ_PENDING;	/* again; the last answer stays readable */
		}
		p->request = false;
		port_enter(p, p->poll_lng ? LMS_IIC_STATE_WRITING : LMS_IIC_STATE_WAITING);
		break;
	}
	case LMS_IIC_STATE_EXIT:
		port_enter(p, LMS_IIC_STATE_IDLE);	/* port_stop() did the work */
		break;
	default:
		break;
	}
}

static enum hrtimer_restart iic_port_timer(struct hrtimer *t)
{
	unsigned long flags;
	unsigned int i;

	spin_lock_irqsave(&iic.lock, flags);
	for (i = 0; i < LMS_IIC_PORTS; i++)
		port_tick(i);
	spin_unlock_irqrestore(&iic.lock, flags);
	hrtimer_forward_now(t, ms_to_ktime(PORT_TICK_MS));
	return HRTIMER_RESTART;
}

/* ---- ioctls ---- */

/*
 * Gives a port's pins back at once, so that the driver taking the port next (d_uart drives the
 * same TX buffer) never sees them changed after it has started; the tick then goes to IDLE.
 */
static void port_stop(unsigned int index)
{
	struct iic_port *p = &iic.port[index];

	bus_abort(index);
	port_forget_request(p);
	iic_port_disable(index);
	iic.shm->status[index] = 0;
	iic.shm->changed[index] = 0;
	p->identified = false;
	p->configured = false;
	p->setup_lng = p->poll_lng = 0;
	port_enter(p, LMS_IIC_STATE_EXIT);
}

static long iic_set_conn(void __user *argp)
{
	struct lms_iic_devcon dc;
	unsigned long flags;
	unsigned int i;

	if (copy_from_user(&dc, argp, sizeof(dc)))
		return -EFAULT;
	spin_lock_irqsave(&iic.lock, flags);
	for (i = 0; i < LMS_IIC_PORTS; i++) {
		struct iic_port *p = &iic.port[i];

		if (dc.connection[i] == LMS_CONN_NXT_IIC) {
			if (p->state == LMS_IIC_STATE_IDLE || p->state == LMS_IIC_STATE_EXIT) {
				p->mode = (u8)dc.mode[i];
				port_enter(p, LMS_IIC_STATE_INIT);
			} else if (p->identified && p->mode != (u8)dc.mode[i]) {
				p->mode = (u8)dc.mode[i];
				if (p->state >= LMS_IIC_STATE_SETUP_WAIT) {
					port_abort(i);
					port_enter(p, LMS_IIC_STATE_SETUP_START);
				}
			}
		} else if (p->state != LMS_IIC_STATE_IDLE && p->state != LMS_IIC_STATE_EXIT) {
			port_stop(i);
		}
	}
	spin_unlock_irqrestore(&iic.lock, flags);
	return 0;
}

static long iic_read_type_info(void __user *argp)
{
	struct lms_iic_str s;
	unsigned long flags;
	struct iic_port *p;

	if (copy_from_user(&s, argp, sizeof(s)))
		return -EFAULT;
	if (s.port < 0 || s.port >= LMS_IIC_PORTS)
		return -EINVAL;
	p = &iic.port[s.port];
	spin_lock_irqsave(&iic.lock, flags);
	memcpy(s.manufacturer, p->manufacturer, sizeof(s.manufacturer));
	memcpy(s.sensor_type, p->sensor_type, sizeof(s.sensor_type));
	iic.shm->changed[s.port] = 0;
	iic.shm->status[s.port] &= ~LMS_IIC_PORT_CHANGED;
	spin_unlock_irqrestore(&iic.lock, flags);
	return copy_to_user(argp, &s, sizeof(s)) ? -EFAULT : 0;
}

static long iic_set(void __user *argp)
{
	struct lms_iic_str s;
	unsigned long flags;
	struct iic_port *p;

	if (copy_from_user(&s, argp, sizeof(s)))
		return -EFAULT;
	if (s.port < 0 || s.port >= LMS_IIC_PORTS || s.setup_lng < 0 ||
	    s.setup_lng > LMS_IIC_STRING_SIZE || s.poll_lng < 0 || s.poll_lng > LMS_IIC_STRING_SIZE ||
	    s.read_lng < -LMS_IIC_DATA_SIZE || s.read_lng > LMS_IIC_DATA_SIZE || s.time < 0 ||
	    (s.poll_lng && !s.read_lng))
		return -EINVAL;
	p = &iic.port[s.port];
	spin_lock_irqsave(&iic.lock, flags);
	p->time_ms = (u16)s.time;
	p->setup_lng = (u8)s.setup_lng;
	p->poll_lng = (u8)s.poll_lng;
	unpack_string(p->setup, s.setup_string, p->setup_lng);
	unpack_string(p->poll, s.poll_string, p->poll_lng);
	p->read_lng = s.read_lng;
	p->configured = true;
	/* once probed, at once; while probing, SETUP_WAIT goes on to it */
	if (p->state >= LMS_IIC_STATE_SETUP_WAIT && p->state <= LMS_IIC_STATE_REPEAT) {
		port_abort(s.port);
		iic.shm->status[s.port] &= ~LMS_IIC_DATA_READY;
		port_enter(p, LMS_IIC_STATE_SETUP_START);
	}
	spin_unlock_irqrestore(&iic.lock, flags);
	return 0;
}

static long iic_setup(void __user *argp)
{
	struct lms_iic_dat d;
	unsigned long flags;
	struct iic_port *p;
	s8 *status;

	if (copy_from_user(&d, argp, sizeof(d)))
		return -EFAULT;
	if (d.port < 0 || d.port >= LMS_IIC_PORTS || d.wr_lng < 1 || d.wr_lng > LMS_IIC_DATA_SIZE ||
	    d.rd_lng < -LMS_IIC_DATA_SIZE || d.rd_lng > LMS_IIC_DATA_SIZE || d.repeat < 0 || d.time < 0)
		return -EINVAL;
	p = &iic.port[d.port];
	status = &iic.shm->status[d.port];
	spin_lock_irqsave(&iic.lock, flags);
	if (p->state == LMS_IIC_STATE_IDLE || p->state == LMS_IIC_STATE_EXIT ||
	    p->state == LMS_IIC_STATE_ERROR) {
		d.result = LMS_IIC_FAIL;
	} else if (p->req_state == REQ_NONE) {
		p->req_left = d.repeat ? (u8)(d.repeat - 1) : 0;
		p->req_forever = !d.repeat;
		p->req_state = REQ_PENDING;
		p->req_time_ms = (u16)d.time;
		p->req_wr_len = (u8)d.wr_lng;
		memcpy(p->req_wr, d.wr_data, sizeof(p->req_wr));
		p->req_rd_lng = d.rd_lng;
		p->request_failed = false;
		p->req_answered = false;
		memset(p->req_answer, 0, sizeof(p->req_answer));
		*status = (s8)((*status & ~LMS_IIC_DATA_READY) | LMS_IIC_WRITE_REQUEST);
		d.result = LMS_IIC_BUSY;
	} else if (p->req_state == REQ_DONE || (p->req_state == REQ_PENDING && p->req_answered)) {
		/* an answer is there (a repeating request may already be queued again): take it */
		memcpy(d.rd_data, p->req_answer, sizeof(d.rd_data));
		d.result = p->request_failed ? LMS_IIC_FAIL : LMS_IIC_OK;
		*status = (s8)(*status & ~(LMS_IIC_WRITE_REQUEST | LMS_IIC_DATA_READY));
		p->req_state = REQ_NONE;
	} else {
		d.result = LMS_IIC_BUSY;
	}
	spin_unlock_irqrestore(&iic.lock, flags);
	return copy_to_user(argp, &d, sizeof(d)) ? -EFAULT : 0;
}

static long iic_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	void __user *argp = (void __user *)arg;

	switch (cmd) {
	case LMS_IIC_SET_CONN:
		return iic_set_conn(argp);
	case LMS_IIC_READ_TYPE_INFO:
		return iic_read_type_info(argp);
	case LMS_IIC_SETUP:
		return iic_setup(argp);
	case LMS_IIC_SET:
		return iic_set(argp);
	default:
		return -ENOTTY;
	}
}

/* The four port states as text. */
static ssize_t iic_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	char text[24];
	int len;
	size_t n;

	len = scnprintf(text, sizeof(text), "%2u %2u %2u %2u\r", iic.port[0].state,
			iic.port[1].state, iic.port[2].state, iic.port[3].state);
	if (*ppos >= len)
		return 0;
	n = min_t(size_t, count, (size_t)(len - *ppos));
	if (copy_to_user(buf, text + *ppos, n))
		return -EFAULT;
	*ppos += n;
	return n;
}

/* LEGO's user space writes [port][bytes] here; the driver ignores it. */
static ssize_t iic_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	return count;
}

static int iic_mmap(struct file *file, struct vm_area_struct *vma)
{
	unsigned long len = vma->vm_end - vma->vm_start;

	if (vma->vm_pgoff || len > LMS_IIC_MAP_SIZE)
		return -EINVAL;
	if (remap_pfn_range(vma, vma->vm_start, virt_to_phys(iic.shm) >> PAGE_SHIFT, len,
			    vma->vm_page_prot))
		return -EAGAIN;
	return 0;
}

static const struct file_operations iic_fops = {
	.owner		= THIS_MODULE,
	.read		= iic_read,
	.write		= iic_write,
	.unlocked_ioctl	= iic_ioctl,
	.mmap		= iic_mmap,
};

static struct miscdevice iic_misc = {
	.minor	= MISC_DYNAMIC_MINOR,
	.name	= LMS_IIC_DEVICE_NAME,
	.fops	= &iic_fops,
};

/* ---- Module ---- */

static void iic_reserve_pages(bool reserve)
{
	unsigned long offset;

	for (offset = 0; offset < LMS_IIC_MAP_SIZE; offset += PAGE_SIZE) {
		struct page *page = virt_to_page((char *)iic.shm + offset);

		if (reserve)
			SetPageReserved(page);
		else
			ClearPageReserved(page);
	}
}

static void iic_unmap(void)
{
	if (iic.timer) {
		iounmap(iic.timer);
		release_mem_region(TIMER64P1_PHYS, TIMER64_SIZE);
	}
	if (iic.gpio)
		iounmap(iic.gpio);
	if (iic.syscfg0)
		iounmap(iic.syscfg0);
	iic.timer = iic.gpio = iic.syscfg0 = NULL;
}

static int iic_map(void)
{
	if (!request_mem_region(TIMER64P1_PHYS, TIMER64_SIZE, LMS_IIC_DEVICE_NAME))
		return -EBUSY;
	iic.timer = ioremap(TIMER64P1_PHYS, TIMER64_SIZE);
	if (!iic.timer) {
		release_mem_region(TIMER64P1_PHYS, TIMER64_SIZE);
		return -ENOMEM;
	}
	/* GPIO and SYSCFG0 are shared with every other driver: mapped, not claimed */
	iic.gpio = ioremap(GPIO_PHYS, GPIO_SIZE);
	iic.syscfg0 = ioremap(SYSCFG0_PHYS, SYSCFG0_SIZE);
	if (!iic.gpio || !iic.syscfg0) {
		iic_unmap();
		return -ENOMEM;
	}
	return 0;
}

static int __init d_iic_init(void)
{
	int ret;

	memset(&iic, 0, sizeof(iic));
	spin_lock_init(&iic.lock);
	if (!timer_clock_hz || timer_clock_hz % (NSEC_PER_SEC / BIT_PERIOD_NS) ||
	    timer_clock_hz / (NSEC_PER_SEC / BIT_PERIOD_NS) < 2) {
		pr_err("d_iic: timer_clock_hz %u does not give a 50 us period\n", timer_clock_hz);
		return -EINVAL;
	}
	iic.shm = kzalloc(LMS_IIC_MAP_SIZE, GFP_KERNEL);
	if (!iic.shm)
		return -ENOMEM;
	iic_reserve_pages(true);
	ret = iic_map();
	if (ret)
		goto free_shm;
	tick_setup();
	iic.irq = timer_irq;
	ret = request_irq(iic.irq, iic_tick_irq, 0, LMS_IIC_DEVICE_NAME, &iic);
	if (ret) {
		pr_err("d_iic: IRQ %d: %d\n", iic.irq, ret);
		goto unmap;
	}
	hrtimer_init(&iic.port_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	iic.port_timer.function = iic_port_timer;
	hrtimer_start(&iic.port_timer, ms_to_ktime(PORT_TICK_MS), HRTIMER_MODE_REL);
	ret = misc_register(&iic_misc);
	if (ret)
		goto stop_timer;
	return 0;

stop_timer:
	hrtimer_cancel(&iic.port_timer);
	free_irq(iic.irq, &iic);
unmap:
	iic_unmap();
free_shm:
	iic_reserve_pages(false);
	kfree(iic.shm);
	iic.shm = NULL;
	return ret;
}

static void __exit d_iic_exit(void)
{
	unsigned long flags;
	unsigned int i;

	misc_deregister(&iic_misc);
	hrtimer_cancel(&iic.port_timer);
	spin_lock_irqsave(&iic.lock, flags);
	for (i = 0; i < LMS_IIC_PORTS; i++) {
		if (iic.port[i].state != LMS_IIC_STATE_IDLE) {
			bus_abort(i);
			iic_port_disable(i);
		}
	}
	tick_stop();
	spin_unlock_irqrestore(&iic.lock, flags);
	free_irq(iic.irq, &iic);
	writel(0, iic.timer + TIMER64_INTCTLSTAT);
	iic_unmap();
	iic_reserve_pages(false);
	kfree(iic.shm);
	iic.shm = NULL;
}

module_init(d_iic_init);
module_exit(d_iic_exit);

MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("LEGO EV3 NXT I2C sensors (/dev/lms_iic)");
