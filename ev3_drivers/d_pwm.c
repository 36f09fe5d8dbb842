// SPDX-License-Identifier: GPL-2.0
/*
 * d_pwm.c — the EV3's four motor output ports (A..D), interface-compatible
 * with LEGO's lms2012 d_pwm driver.
 *
 * /dev/lms_pwm   write: LEGO's output command protocol (lms_pwm.h);
 *                read:  "R T " — the busy masks of limited commands.
 * /dev/lms_motor write: one byte ORed into both busy masks;
 *                mmap:  MOTORDATA[4] (tacho counts, speed, sensor counts).
 *
 * Hardware (AM1808, EV3 "EP2" board): duty cycles on eHRPWM1 (ports A, B)
 * and eCAP0/eCAP1 in APWM mode (ports C, D); the H-bridge inputs on two
 * GPIOs per port; a quadrature-like tacho (an interrupt pin counted on both
 * edges plus a direction pin); edge times stamped from TIMER64P3.
 *
 * What applications see behaves as LEGO's lms2012 d_pwm.c (mindboards/
 * ev3sources) does, measured on the same byte streams and simulated motors:
 *  - The speed regulator is LEGO's incremental PID in LEGO's integer
 *    arithmetic (its truncated integral stops adding power once the whole
 *    measured speed is the target: SPEED 100 runs at ~1 010 deg/s, SPEED 40
 *    anywhere in 403..413).  A limited command starts each of its phases
 *    (ramp up, constant, ramp down) with fresh integral and derivative
 *    terms, keeping its power for that tick, as LEGO's does.
 *  - A command re-issued while running (a control loop sending STEP_SYNC,
 *    SPEED, POWER, STEP_/TIME_SPEED every few ms) changes the target and
 *    nothing else: the regulator keeps its accumulated power, a ramp resumes
 *    where the port runs, the same sync pair runs on (its slave keeping its
 *    lag, even when the turn changes sign), so the motors run at the speed a
 *    single command gives.  A command naming one motor of a pair floats both.
 *    Deliberately unlike LEGO's, whose STEP_/TIME_SPEED without a ramp up
 *    clears the regulator's terms at every command (re-issued every 1-4 ms,
 *    speed 40 runs at 490-520 deg/s instead of 413) and whose re-issued
 *    TIME_SPEED with a ramp runs at 315..920 deg/s: a loop re-sending a
 *    command gets the speed it asks for.
 *  - A regulated command that brakes at its end closes in on it as LEGO's
 *    does: over its last speed/2 counts (speed/3 on a medium motor; speed
 *    ms for a time command) it asks for the counts (ms) left as its speed,
 *    or for 1 while more than 5 are left and the motor is faster, then holds
 *    the end (a 90-count step at speed 30 is busy ~590 ms, 360 at 50 ~1 s;
 *    a medium motor runs up to ~2 degrees past at speed 90, as LEGO's does);
 *    with a ramp down it ramps to speed 5 and brakes at the end.  A coasting
 *    step still slows down over its last counts (3/4 per unit of speed,
 *    15..60) to speed 3 and stops on its end, where LEGO's runs on at speed
 *    and coasts past it; a step pair (STEP_SYNC) slows down the same way.
 *  - MOTORDATA TachoCounts counts from the start of the current command: 0
 *    while unlimited, back to 0 when a limited command ends (its busy bits
 *    clear) and from the stop after OUTPUT_STOP; TachoSensor is cumulative
 *    (cleared by CLR_COUNT and SET_TYPE only).
 *  - A step command counts from where TachoCounts is 0: after a coast STOP
 *    that is the stop, not the command (a step of 90 issued 100 ms later,
 *    the motor having coasted on 45, turns 45 more; one issued after it
 *    coasted 115 to rest turns back 25); a step re-issued while the same
 *    step runs ends where the first would have.  OUTPUT_RESET makes a step
 *    count from where the motor is.
 *  - OUTPUT_STOP with brake holds the stop position with LEGO's proportional
 *    term: settled within 250 ms, a count or so back from the overshoot, and
 *    it stays put; only a load displacing the shaft by more than 3 counts
 *    starts an integral that brings it back.
 *  - MOTORDATA Speed is the measured speed, shown one 2 ms tick late as
 *    LEGO's is, averaged over a window that the newest edge interval
 *    chooses (4..64 edges), so a motor braking hard is followed within
 *    milliseconds.  OUTPUT_STOP clears the edge history: 0 until a full
 *    averaging window is in again (~40 ms coasting from speed 50, ~14 ms
 *    braked), then the coasting or settling motor's speed (+40 coasting,
 *    -16 braked 100 ms after a stop from speed 50).  A change of direction
 *    keeps the last speed until the new direction fills a window, and a
 *    longer window is waited for as the motor speeds up (SPEED +50 to -50:
 *    90 % of the speed the other way after 70..87 ms, LEGO's 76..88; +100
 *    to -100 after 127..135 ms, LEGO's 116..132, the new direction shown
 *    from ~60 ms on).  Deliberately unlike LEGO's, which keeps counting in
 *    the old direction while its measured speed is above 35: in some
 *    reversals from +100 (7 of 20) it notices the turn only at -300 deg/s,
 *    the window it then waits for grows with the speed faster than it
 *    fills, and MOTORDATA shows +15 for ~90 ms while the motor runs the
 *    other way at up to -950 deg/s (then -67 at 200 ms, where the others
 *    show -95).  ev3lx reads the direction pin whenever the port drives
 *    against the last direction.
 *
 * Concurrency: one spinlock guards all port state.  The tacho interrupt and
 * the 2 ms control hrtimer run with interrupts off and take it plainly;
 * write() takes it with interrupts saved, for a few dozen instructions.
 */
#include <linux/module.h>
#include <linux/kernel.h>
#include <linux/init.h>
#include <linux/types.h>
#include <linux/bits.h>
#include <linux/errno.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/uaccess.h>
#include <linux/io.h>
#include <linux/ioport.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/gpio.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/spinlock.h>
#include <linux/delay.h>
#include <linux/string.h>

#include "lms_pwm.h"

/* ---- AM1808 register map (physical addresses and offsets from the TRM) ---- */

#define GPIO_PHYS          0x01E26000
#define GPIO_SIZE          0xD8
#define GPIO_BANK_REGS(p)  (0x10 + ((p) / 32) * 0x28)  /* a bank pair's block */
#define GPIO_DIR           0x00    /* 1 = input (floating) */
#define GPIO_SET_DATA      0x08
#define GPIO_CLR_DATA      0x0C
#define GPIO_IN_DATA       0x10

#define SYSCFG0_PHYS       0x01C14000
#define SYSCFG0_SIZE       0x190
#define SYSCFG0_KICK0R     0x38
#define SYSCFG0_KICK1R     0x3C
#define SYSCFG0_KICK0_KEY  0x83E70B13
#define SYSCFG0_KICK1_KEY  0x95A4F1E0
#define SYSCFG0_PINMUX(n)  (0x120 + 4 * (n))
#define SYSCFG0_CFGCHIP1   0x180
#define CFGCHIP1_TBCLKSYNC BIT(12)

#define PSC1_PHYS          0x01E27000
#define PSC1_SIZE          0x1000
#define PSC_PTCMD          0x120
#define PSC_PTSTAT         0x128
#define PSC_MDCTL(n)       (0xA00 + 4 * (n))
#define PSC1_LPSC_EHRPWM   17
#define PSC1_LPSC_ECAP     20
#define PSC_STATE_ENABLE   3
#define PSC_GO_MASK        3       /* power domains 0 and 1 */
#define PSC_POLL_LIMIT     1000    /* 1 us each: a transition takes a few cycles */

#define EHRPWM1_PHYS       0x01F02000
#define EHRPWM_SIZE        0x80
#define EPWM_TBCTL         0x00
#define EPWM_TBPHS         0x06
#define EPWM_TBCNT         0x08
#define EPWM_TBPRD         0x0A
#define EPWM_CMPCTL        0x0E
#define EPWM_CMPA          0x12
#define EPWM_CMPB          0x14
#define EPWM_AQCTLA        0x16
#define EPWM_AQCTLB        0x18
#define EPWM_TBCTL_UP_FREE 0x0030  /* count up, no sync out, clock /1 /1 */
#define EPWM_CMPCTL_SHADOW_ZERO 0x0000  /* shadowed compares, loaded at zero */
#define EPWM_AQCTLA_LOW_ZERO_HIGH_CMPA 0x0021
#define EPWM_AQCTLB_LOW_ZERO_HIGH_CMPB 0x0201

#define ECAP0_PHYS         0x01F06000
#define ECAP1_PHYS         0x01F07000
#define ECAP_SIZE          0x60
#define ECAP_TSCTR         0x00
#define ECAP_CTRPHS        0x04
#define ECAP_CAP1          0x08    /* APWM period */
#define ECAP_CAP2          0x0C    /* APWM compare (duty) */
#define ECAP_ECCTL2        0x2A
#define ECAP_ECCTL2_APWM_LOW_FREE 0x0690

#define PWM_PERIOD         10000   /* counts per PWM period (TBPRD/CAP1 + 1) */

#define TIMER64P3_PHYS     0x01F0D000
#define TIMER64_SIZE       0x80
#define TIMER64_TIM34      0x14
#define TIMER64_PRD34      0x1C
#define TIMER64_TCR        0x20
#define TIMER64_TGCR       0x24
#define TIMER64_TGCR_DUAL_UNCHAINED_DIV4 0x3304
#define TIMER64_TGCR_TIM34RS BIT(1)
#define TIMER64_TCR_TIM34_CONTINUOUS 0x00800000
#define STAMP_SHIFT        8       /* a stamp is TIM34 >> 8 ... */
#define STAMP_MASK         0xFFFFFF /* ... 24 bits, about 7.76 us per tick */

/* ---- Control constants (LEGO's regulation, see the facts sheet) ---- */

#define CONTROL_PERIOD_MS  2
#define STAMP_RING         128
#define SPEED_MAX          100
#define POWER_MAX          10000   /* internal power: user power x 100 */
#define FAST_SPEED         35      /* above this the tacho DIR pin is not trusted */
#define BRAKE_HOLD_GAIN    400     /* hold power per count of displacement */
#define HOLD_LOAD_COUNTS   4       /* a hold this far off is under load: the integral works */
#define HOLD_I_GAIN        10      /* hold power per accumulated count-tick */
#define HOLD_I_MAX         (POWER_MAX / HOLD_I_GAIN)
#define HOLD_STILL_TICKS   25      /* the integral only grows once no edge came for 50 ms */
#define PROGRAM_STOP_BRAKE_MS 100
#define RAMP_UP_FLOOR_SPEED 6      /* a ramp never asks for less, or a step ramp would stall: */
#define RAMP_FLOOR_SPEED   5       /* LEGO's ramps start at 6 and end at 5 */
#define RAMP_FLOOR_POWER   10
#define APPROACH_COUNTS_MIN 15     /* a step slows down over its last counts: 3/4 per unit */
#define APPROACH_COUNTS_MAX 60     /* of speed (30 at speed 40), at least 15, at most 60, */
#define APPROACH_SPEED     3       /* and arrives at this speed, slow enough not to overshoot */
#define APPROACH_MS        100     /* a braking time command slows down over its last 100 ms */
#define SYNC_POSITION_GAIN 2       /* slave speed per count it is off its share */
#define SYNC_LAG_FREE      2       /* counts a slave may lag before the master waits */
#define SYNC_LAG_SLOWDOWN  4       /* master speed given up per count of lag beyond that */

/* ---- Board wiring (EP2 tables) ---- */

enum pwm_channel { PWM_EPWM1B, PWM_EPWM1A, PWM_APWM0, PWM_APWM1 };

struct pwm_port_pins {
	u16 dir0, dir1;      /* H-bridge inputs */
	u16 tacho_int;       /* counted on both edges */
	u16 tacho_dir;
	enum pwm_channel channel;
};

#define GP(bank, bit) ((bank) * 16 + (bit))

static const struct pwm_port_pins port_pins[LMS_PWM_PORTS] = {
	{ GP(3, 15), GP(3, 6),  GP(5, 11), GP(0, 4),  PWM_EPWM1B },
	{ GP(2, 1),  GP(0, 3),  GP(5, 8),  GP(2, 9),  PWM_EPWM1A },
	{ GP(6, 8),  GP(5, 9),  GP(5, 13), GP(3, 14), PWM_APWM0 },
	{ GP(5, 3),  GP(5, 10), GP(6, 9),  GP(2, 8),  PWM_APWM1 },
};

/* Pinmux fields (register, shift, function) routing the PWM outputs to the pins. */
struct pinmux_field {
	u8 reg, shift, function;
};

static const struct pinmux_field pwm_pinmux[] = {
	{ 5, 0, 2 },     /* EPWM1B */
	{ 5, 4, 2 },     /* EPWM1A */
	{ 2, 28, 2 },    /* ECAP0_APWM0 */
	{ 1, 28, 4 },    /* ECAP1_APWM1 */
};

/* ---- Port state ---- */

enum pwm_drive { DRIVE_COAST, DRIVE_FORWARD, DRIVE_REVERSE, DRIVE_BRAKE };

/* What began the current run of edges in one direction (see tacho_speed). */
enum pwm_run {
	RUN_CLEARED,         /* OUTPUT_STOP or SET_TYPE forgot the edges before */
	RUN_SILENCE,         /* the motor stood still; the last edge before is old */
	RUN_TURN,            /* the motor turned; the last edge before went the other way */
};

enum pwm_state {
	STATE_IDLE,          /* coasting */
	STATE_UNREG,         /* unlimited, fixed power */
	STATE_REG,           /* unlimited, regulated speed */
	STATE_LIMITED,       /* a STEP_/TIME_ command: ramp up, constant, ramp down */
	STATE_SYNC_MASTER,   /* a STEP_/TIME_SYNC pair, leading */
	STATE_SYNC_SLAVE,    /* following its master at a ratio */
	STATE_BRAKED,        /* holding hold_pos */
	STATE_BRAKE_TIMED,   /* PROGRAM_STOP: short-brake until brake_until, then coast */
};

enum pwm_phase { PHASE_UP, PHASE_FLAT, PHASE_DOWN };

struct pwm_profile {          /* a limited command */
	bool by_time;
	bool brake;
	bool regulated;
	s8 peak;              /* target of the constant phase, polarity applied */
	u32 ramp_in;          /* how far into its ramp up the command started (counts or ms) */
	u32 up, flat, down;   /* phase lengths in counts or ms; all 0 = forever */
	s32 origin;           /* position at the start */
	ktime_t start;
	bool closing;         /* braking at its end: closing in on it (latched) */
	enum pwm_phase phase; /* the phase the regulator last started */
};

struct pwm_port {
	const struct pwm_port_pins *pins;
	u8 __iomem *int_bank, *dir_bank;
	u32 int_mask, dir_mask;
	int irq;

	u8 type;
	bool tacho;           /* type 7 or 8 */
	bool medium;          /* type 8 */
	s8 polarity;          /* +1 or -1, applied when commands are taken */

	enum pwm_state state;
	bool start_regulated; /* what OUTPUT_START enters */
	s8 target;            /* power or speed of the unlimited states, polarity applied */
	struct pwm_profile profile;
	int partner;          /* the other port of a sync pair, or -1 */
	s32 sync_factor;      /* slave: its counts per 100 master counts, signed */
	s32 sync_carry;       /* slave: hundredths of a count it owes from earlier commands */
	s32 setpoint;         /* speed (or user power) the control loop last asked for */

	s32 hold_pos;         /* BRAKED: position to hold */
	s32 hold_i;           /* BRAKED: integral of the displacement, once a load showed */
	s32 hold_seen;        /* BRAKED: the position at the last tick ... */
	u16 hold_still;       /* ... and for how many ticks it has not changed */
	ktime_t brake_until;  /* BRAKE_TIMED */

	s32 power;            /* applied power, -POWER_MAX..POWER_MAX */
	s32 pid_power;        /* the regulator's power, -POWER_MAX..POWER_MAX */
	s32 pid_i;            /* its decaying integral, in power */
	s32 pid_last_err;

	/* tacho: written by the edge interrupt */
	s32 position;         /* counts since load, never reset: the reference of everything */
	s8 last_dir;
	u32 stamps[STAMP_RING];
	u8 stamp_head;        /* next slot */
	u8 stamp_valid;       /* consecutive stamps in the same direction, up to STAMP_RING */
	enum pwm_run run;     /* what began those stamps */

	/* derived in the control tick */
	s8 speed;
	s32 command_origin;   /* TachoCounts reference */
	s32 sensor_origin;    /* TachoSensor reference */

	/* output cache: hardware is written only on change */
	enum pwm_drive drive;
	u16 duty;
};

static DEFINE_SPINLOCK(pwm_lock);
static struct pwm_port ports[LMS_PWM_PORTS];
static u8 ready_status, test_status;   /* busy masks */

/* Register blocks, as byte pointers so that offsets add without extensions. */
static u8 __iomem *gpio_base;
static u8 __iomem *syscfg0_base;
static u8 __iomem *psc1_base;
static u8 __iomem *ehrpwm1_base;
static u8 __iomem *ecap_base[2];
static u8 __iomem *timer64_base;

static void *motor_alloc;               /* kmalloc'd, holds the page below */
static struct lms_motor_data *motor_data; /* page-aligned, mapped by user space */
static struct hrtimer control_timer;

static char *HwId = "03";
module_param(HwId, charp, 0);
MODULE_PARM_DESC(HwId, "LEGO hardware id (accepted for lms2012 compatibility; EP2 wiring is used)");

/* ---- Low-level hardware ---- */

/* Drives a GPIO pin to a level: output value first, then the direction. */
static void gpio_drive(unsigned int pin, bool high)
{
	u8 __iomem *bank = gpio_base + GPIO_BANK_REGS(pin);
	u32 mask = BIT(pin % 32);

	writel(mask, bank + (high ? GPIO_SET_DATA : GPIO_CLR_DATA));
	writel(readl(bank + GPIO_DIR) & ~mask, bank + GPIO_DIR);
}

/* Releases a GPIO pin (input, no drive). */
static void gpio_float(unsigned int pin)
{
	u8 __iomem *bank = gpio_base + GPIO_BANK_REGS(pin);

	writel(readl(bank + GPIO_DIR) | BIT(pin % 32), bank + GPIO_DIR);
}

/* Writes the duty (0..PWM_PERIOD counts active) of a port's PWM channel. */
static void pwm_write_duty(enum pwm_channel ch, u16 duty)
{
	switch (ch) {
	case PWM_EPWM1B:
		writew(duty, ehrpwm1_base + EPWM_CMPB);
		break;
	case PWM_EPWM1A:
		writew(duty, ehrpwm1_base + EPWM_CMPA);
		break;
	case PWM_APWM0:
		writel(duty, ecap_base[0] + ECAP_CAP2);
		break;
	case PWM_APWM1:
		writel(duty, ecap_base[1] + ECAP_CAP2);
		break;
	}
}

/* Applies an H-bridge mode and duty to a port, touching only what changed. */
static void port_output(struct pwm_port *p, enum pwm_drive drive, u16 duty)
{
	const struct pwm_port_pins *pins = p->pins;

	if (drive != p->drive) {
		/* Lower the duty first so a direction change never sees full drive. */
		pwm_write_duty(pins->channel, 0);
		switch (drive) {
		case DRIVE_COAST:
			gpio_drive(pins->dir0, false);
			gpio_drive(pins->dir1, false);
			break;
		case DRIVE_FORWARD:
			gpio_float(pins->dir1);
			gpio_drive(pins->dir0, true);
			break;
		case DRIVE_REVERSE:
			gpio_float(pins->dir0);
			gpio_drive(pins->dir1, true);
			break;
		case DRIVE_BRAKE:
			gpio_drive(pins->dir0, true);
			gpio_drive(pins->dir1, true);
			break;
		}
		p->drive = drive;
		p->duty = 0;
	}
	if (duty != p->duty) {
		pwm_write_duty(pins->channel, duty);
		p->duty = duty;
	}
}

/* Reads the 24-bit edge time stamp from TIMER64P3. */
static u32 stamp_now(void)
{
	return (readl(timer64_base + TIMER64_TIM34) >> STAMP_SHIFT) & STAMP_MASK;
}

/* ---- Tacho ---- */

/* Stamp ticks x speed units per count (LEGO's CountsPerPulse) of a port's motor. */
static u32 counts_per_pulse(const struct pwm_port *p)
{
	return p->medium ? 8100 : 12800;
}

/* Counts one tacho edge: +-1 by the INT/DIR rule, and stamps it for the speed. */
static irqreturn_t tacho_isr(int irq, void *dev_id)
{
	struct pwm_port *p = dev_id;
	bool int_high = readl(p->int_bank + GPIO_IN_DATA) & p->int_mask;
	bool dir_high = readl(p->dir_bank + GPIO_IN_DATA) & p->dir_mask;
	u32 stamp = stamp_now();
	s8 dir;

	spin_lock(&pwm_lock);
	/*
	 * Above speed 35 the DIR pin may have moved on by the time it is read, so
	 * the last direction is kept - but only while the port drives that way
	 * (braking or reversing, the shaft may turn back right after an edge and
	 * cross it again quickly) and this edge came quickly too: the averaged
	 * speed lags a fast reversal, the edge interval does not.
	 */
	if (p->last_dir && p->power * p->last_dir > 0 && abs(p->speed) > FAST_SPEED &&
	    p->stamp_valid &&
	    ((stamp - p->stamps[(p->stamp_head + STAMP_RING - 1) % STAMP_RING]) & STAMP_MASK) *
	    FAST_SPEED < counts_per_pulse(p))
		dir = p->last_dir;
	else
		dir = (int_high != dir_high) ? 1 : -1;
	if (dir != p->last_dir) {
		p->stamp_valid = 0;
		p->run = RUN_TURN;
	}
	p->last_dir = dir;
	p->position += dir;
	p->stamps[p->stamp_head] = stamp;
	p->stamp_head = (p->stamp_head + 1) % STAMP_RING;
	if (p->stamp_valid < STAMP_RING)
		p->stamp_valid++;
	spin_unlock(&pwm_lock);
	return IRQ_HANDLED;
}

/*
 * Measures a port's speed (-100..100) from its edge stamps; 0 after a
 * silence.  The window is as many edges as the newest edge interval's speed
 * asks for (more when faster), so a motor slowing down hard is followed
 * within a few ms.  The speed is only measured again over a full window of
 * edges in one direction: after OUTPUT_STOP (speed set to 0), a silence or a
 * change of direction cleared the stamps, and whenever the motor got fast
 * enough to ask for a longer window, it keeps its last value until that
 * window is full, as LEGO's driver shows it (0 for about 40 ms of a large
 * motor coasting from speed 50; through a reversal the old direction's speed
 * at first, then the new one in steps, so the regulator keeps pushing).
 */
static s8 tacho_speed(struct pwm_port *p, u32 now)
{
	u32 cpp = counts_per_pulse(p);
	static const u8 samples_large[] = { 4, 16, 32, 64 };
	static const u8 samples_medium[] = { 2, 4, 8, 16 };
	const u8 *table = p->medium ? samples_medium : samples_large;
	u32 n, mag, newest, oldest, ticks, speed;

	if (p->stamp_valid == 0)
		return 0;
	newest = p->stamps[(p->stamp_head + STAMP_RING - 1) % STAMP_RING];
	if (((now - newest) & STAMP_MASK) > cpp) {
		p->stamp_valid = 0;
		p->run = RUN_SILENCE;
		return 0;
	}
	if (p->stamp_valid < 2)
		return p->speed;
	ticks = (newest - p->stamps[(p->stamp_head + STAMP_RING - 2) % STAMP_RING]) & STAMP_MASK;
	mag = ticks ? min_t(u32, cpp / ticks, SPEED_MAX) : SPEED_MAX;
	n = table[(mag > 40) + (mag > 60) + (mag > 80)];
	/*
	 * LEGO's window may reach back to the edge before the run: after a
	 * silence that edge is old and the speed low; after OUTPUT_STOP its
	 * time stamp is cleared and the speed reads 0 for that tick (on the
	 * brick, where the free-running timer is far from 0); after a turn the
	 * window waits for an edge more.
	 */
	if (p->stamp_valid < n || (p->stamp_valid == n && p->run == RUN_TURN))
		return p->speed;
	if (p->stamp_valid == n && p->run == RUN_CLEARED)
		return 0;
	oldest = p->stamps[(p->stamp_head + STAMP_RING - 1 - n) % STAMP_RING];
	ticks = (newest - oldest) & STAMP_MASK;
	if (ticks == 0)
		return p->last_dir * SPEED_MAX;
	speed = n * cpp / ticks;
	if (speed > SPEED_MAX)
		speed = SPEED_MAX;
	return p->last_dir * (s8)speed;
}

/* ---- Control ---- */

/* Duty counts for a power, by motor type and regulation (LEGO's calibration). */
static u16 power_to_duty(const struct pwm_port *p, s32 power, bool regulated)
{
	u32 mag = abs(power);

	if (mag == 0)
		return 0;
	if (regulated)
		mag = p->medium ? mag * 9 / 10 + 1000 : mag;
	else if (p->tacho)
		mag = p->medium ? mag * 8 / 10 + 2000 : mag * 95 / 100 + 500;
	return mag > PWM_PERIOD ? PWM_PERIOD : mag;
}

/*
 * Drives a port with a signed power.  The bridge shorts the windings in the
 * off phase of each PWM period, so a small power mostly brakes; a regulated
 * zero therefore brakes too (a regulator slowing down must not let go), an
 * unregulated zero coasts.
 */
static void port_drive_power(struct pwm_port *p, s32 power, bool regulated)
{
	p->power = power;
	if (power == 0)
		port_output(p, regulated ? DRIVE_BRAKE : DRIVE_COAST, regulated ? PWM_PERIOD : 0);
	else
		port_output(p, power > 0 ? DRIVE_FORWARD : DRIVE_REVERSE,
			    power_to_duty(p, power, regulated));
}

/* Forgets the PID history, keeping the applied power as the starting point. */
static void pid_reset(struct pwm_port *p)
{
	p->pid_power = p->power;
	p->pid_i = 0;
	p->pid_last_err = 0;
}

/*
 * One incremental PID step towards a target speed; returns the new power.
 * The arithmetic is LEGO's (lms2012 d_pwm.c, dRegulateSpeed): whole units of
 * power, the integral decaying by 9/10 and growing by err/4 (err/3 on a
 * medium motor), both truncated.  The truncation is what stops the power
 * rising once the measured speed is within a few units of the target, or
 * at the top of the scale, where the measurement saturates: a large motor
 * asked for speed 100 runs at ~1 010 deg/s as LEGO's does, not at full
 * duty (~1 040), and the 90 % point of a reversal from +100 is where LEGO's is.
 */
static s32 pid_step(struct pwm_port *p, s32 target)
{
	s32 err = target - p->speed;
	s32 pterm, dterm;

	if (target == 0) {
		pid_reset(p);
		p->pid_power = 0;
		return 0;
	}
	if (p->medium) {
		pterm = 4 * err;
		p->pid_i = p->pid_i * 9 / 10 + err / 3;
	} else {
		pterm = 2 * err;
		p->pid_i = p->pid_i * 9 / 10 + err / 4;
	}
	dterm = 80 * (err - p->pid_last_err);
	p->pid_last_err = err;
	p->pid_power += pterm + dterm + p->pid_i;
	p->pid_power = clamp(p->pid_power, -POWER_MAX, POWER_MAX);
	/* Never drive against the requested direction: let the motor slow down instead. */
	if ((target > 0 && p->pid_power < 0) || (target < 0 && p->pid_power > 0))
		p->pid_power = 0;
	return p->pid_power;
}

/*
 * Holds hold_pos with LEGO's proportional term (the windings shorted when the
 * shaft is on it).  A free shaft settles within a count or two of the point,
 * so an integral only starts when a load keeps the shaft further off (and
 * still); from then on it integrates the whole displacement, bringing the
 * loaded shaft back to the point and unwinding when the load lets go.
 * Without a load nothing integrates and the shaft stays where the
 * proportional term left it.
 */
static void brake_hold(struct pwm_port *p)
{
	s32 err = p->position - p->hold_pos;
	s32 power;

	if (p->position != p->hold_seen) {
		p->hold_seen = p->position;
		p->hold_still = 0;
	} else if (p->hold_still < HOLD_STILL_TICKS) {
		p->hold_still++;
	}
	/* Still means no edge for a while (the measured speed reads 0 at every turn-around too). */
	if (p->hold_still >= HOLD_STILL_TICKS && (p->hold_i || abs(err) > HOLD_LOAD_COUNTS))
		p->hold_i = clamp(p->hold_i + err, -HOLD_I_MAX, HOLD_I_MAX);
	power = clamp(-BRAKE_HOLD_GAIN * err - HOLD_I_GAIN * p->hold_i, -POWER_MAX, POWER_MAX);
	p->power = 0;
	if (power == 0)
		port_output(p, DRIVE_BRAKE, PWM_PERIOD);
	else
		port_drive_power(p, power, true);
}

/* mag * num / den for num <= den, in 32 bits whatever the magnitudes. */
static u32 scale_fraction(u32 mag, u32 num, u32 den)
{
	while (den > 0xFFFF) {
		den >>= 1;
		num >>= 1;
	}
	return den ? mag * num / den : mag;
}

/* Progress of a limited command along its direction: counts or ms. */
static u32 profile_progress(const struct pwm_profile *pr, const struct pwm_port *p, ktime_t now)
{
	s32 moved;
	s64 us;

	if (pr->by_time) {
		us = ktime_to_us(ktime_sub(now, pr->start));
		return us >= 0xFFFFFFFFLL ? 0xFFFFFFFFU / 1000 : (u32)us / 1000;
	}
	moved = p->position - pr->origin;
	if (pr->peak < 0)
		moved = -moved;
	return moved > 0 ? moved : 0;
}

/*
 * Counts (or ms, for a braking time command) before its end over which a
 * regulated limited command slows down, so that it arrives slowly enough to
 * stop on its end instead of overshooting it; 0 for none.
 */
static u32 approach_span(const struct pwm_profile *pr)
{
	if (!pr->regulated)
		return 0;
	if (pr->by_time)
		return pr->brake ? APPROACH_MS : 0;
	return clamp_t(u32, abs(pr->peak) * 3 / 4, APPROACH_COUNTS_MIN, APPROACH_COUNTS_MAX);
}

/*
 * Target (signed) of a limited command at a progress, or false when it is
 * done: the ramp up from the speed (power) the command found, the constant
 * phase, the ramp down, and the approach to the end (*approaching set):
 * the speed falls in proportion to what is left, to APPROACH_SPEED.
 */
static bool profile_target(const struct pwm_profile *pr, u32 progress, bool approach, s32 *target,
			   bool *approaching)
{
	u32 peak = abs(pr->peak), mag = peak;
	u32 total = pr->up + pr->flat + pr->down;
	u32 floor = min_t(u32, mag, pr->regulated ? RAMP_FLOOR_SPEED : RAMP_FLOOR_POWER);
	u32 up_floor = min_t(u32, mag, pr->regulated ? RAMP_UP_FLOOR_SPEED : RAMP_FLOOR_POWER);
	u32 near = approach ? approach_span(pr) : 0, left;

	*approaching = false;
	if (total == 0) {
		*target = pr->peak;
		return true;
	}
	if (progress >= total)
		return false;
	left = total - progress;
	if (progress < pr->up)
		mag = max(scale_fraction(mag, min(progress + pr->ramp_in, pr->up), pr->up), up_floor);
	else if (progress >= pr->up + pr->flat)
		mag = max(scale_fraction(mag, left, pr->down), floor);
	*approaching = left < near && mag > APPROACH_SPEED;
	if (*approaching)
		mag = min_t(u32, mag, max_t(u32, scale_fraction(peak, left, near), APPROACH_SPEED));
	*target = pr->peak < 0 ? -(s32)mag : (s32)mag;
	return true;
}

/*
 * Approaching the end, each step down of the target cuts the regulator's
 * power in proportion at once (the power a speed needs is about proportional
 * to it): the incremental PID alone would take tens of ms to let go, and
 * the motor would run past the end.
 */
static void approach_cut(struct pwm_port *p, s32 target)
{
	s32 was = abs(p->setpoint);

	if (target * p->setpoint > 0 && abs(target) < was)
		p->pid_power = p->pid_power * abs(target) / was;
}

/* Ends a port's command: hold at hold_pos or coast, and clear its busy bits. */
static void port_finish(struct pwm_port *p, int port, bool brake, s32 hold_pos)
{
	p->partner = -1;
	p->setpoint = 0;
	p->command_origin = p->position;    /* TachoCounts counts from here */
	if (brake) {
		p->state = STATE_BRAKED;
		p->hold_pos = hold_pos;
		p->hold_i = 0;
		p->hold_still = 0;
		brake_hold(p);
	} else {
		p->state = STATE_IDLE;
		p->power = 0;
		port_output(p, DRIVE_COAST, 0);
	}
	ready_status &= ~BIT(port);
	test_status &= ~BIT(port);
}

/* True if the port's limited command is regulated and brakes at its end: it ends as LEGO's does. */
static bool brakes_at_end(const struct pwm_port *p)
{
	return p->tacho && p->profile.regulated && p->profile.brake;
}

/* True if it also has no ramp down and a length: it closes in on its end (closing_target). */
static bool closes_at_end(const struct pwm_port *p)
{
	const struct pwm_profile *pr = &p->profile;

	return brakes_at_end(p) && !pr->down && pr->up + pr->flat != 0;
}

/*
 * Closing in on the end of a regulated command that brakes there with no
 * ramp down, as LEGO's driver does: once what is left (counts, or ms) is no
 * more than the speed's half (a large motor's counts; a third for a medium
 * motor; the whole speed in ms), the target speed is what is left, or 1
 * while more than 5 are left and the motor is still faster than that.
 * False while not closing in yet.
 */
static bool closing_target(struct pwm_port *p, u32 progress, s32 *target)
{
	struct pwm_profile *pr = &p->profile;
	u32 total = pr->up + pr->flat + pr->down, left, speed = abs(p->speed), near;

	if (!closes_at_end(p) || progress >= total)
		return false;
	left = total - progress;
	near = pr->by_time ? speed : p->medium ? speed / 3 : speed / 2;
	if (!pr->closing && (progress < pr->up || left > near))
		return false;
	pr->closing = true;
	if (left > 5 && left < speed)
		left = 1;
	left = min_t(u32, left, abs(pr->peak));
	*target = pr->peak < 0 ? -(s32)left : (s32)left;
	return true;
}

/* The phase of a limited command at a progress (the last one past its end). */
static enum pwm_phase profile_phase(const struct pwm_profile *pr, u32 progress)
{
	if (progress < pr->up)
		return PHASE_UP;
	return progress < pr->up + pr->flat ? PHASE_FLAT : PHASE_DOWN;
}

/* Runs one limited command tick; finishes the command when its profile ends. */
static void limited_tick(struct pwm_port *p, int port, ktime_t now)
{
	struct pwm_profile *pr = &p->profile;
	u32 progress = profile_progress(pr, p, now);
	enum pwm_phase phase = profile_phase(pr, progress);
	s32 target, end;
	bool approaching;

	/*
	 * A regulated command starts each phase with a fresh integral and
	 * derivative, keeping its power for the tick it changes phase, as
	 * LEGO's does (lms2012 d_pwm.c clears its PID terms entering the
	 * constant and the ramp-down phase, and regulates from the next tick):
	 * the first regulated tick of a phase answers the whole speed error at
	 * once, which is what lifts a ramped step onto its constant speed in
	 * LEGO's time.  A command re-issued while it runs starts in the phase
	 * it is in, and keeps its terms: LEGO's clears them at every command
	 * without a ramp up, and a loop re-issuing STEP_SPEED 40 every 1-4 ms
	 * runs at 490-520 deg/s there instead of 413.
	 */
	if (pr->regulated && phase != pr->phase && progress < pr->up + pr->flat + pr->down) {
		pr->phase = phase;
		pid_reset(p);
		return;
	}
	if (closing_target(p, progress, &target)) {
		p->setpoint = target;
		port_drive_power(p, pid_step(p, target), true);
		return;
	}
	/* Braking at the end, LEGO's driver has no approach of its own: a ramp down brakes at speed 5. */
	if (!profile_target(pr, progress, !brakes_at_end(p), &target, &approaching)) {
		end = pr->origin + (pr->peak < 0 ? -(s32)(pr->up + pr->flat + pr->down)
						 : (s32)(pr->up + pr->flat + pr->down));
		/* A step command holds exactly its end position, not where momentum took it. */
		port_finish(p, port, pr->brake, pr->by_time ? p->position : end);
		return;
	}
	if (approaching)
		approach_cut(p, target);
	p->setpoint = target;
	if (pr->regulated && p->tacho)
		port_drive_power(p, pid_step(p, target), true);
	else
		port_drive_power(p, target * (POWER_MAX / 100), false);
}

/*
 * Hundredths of a count a sync master's slave is behind the share of the
 * master's travel it should have made (kept in hundredths so that a pair
 * re-issued every millisecond loses nothing to rounding).
 */
static s32 sync_slave_lag100(const struct pwm_port *m)
{
	const struct pwm_port *s = &ports[m->partner];

	return (s->profile.origin - s->position) * 100 + s->sync_carry +
	       (m->position - m->profile.origin) * s->sync_factor;
}

/* Runs one tick of a sync pair from its master: both motors, the ratio, the end. */
static void sync_tick(struct pwm_port *m, int port, ktime_t now)
{
	struct pwm_port *s = &ports[m->partner];
	struct pwm_profile *pr = &m->profile;
	s32 target, end, err, lag, slave_target, master_target;
	bool brake = pr->brake, approaching;

	if (!profile_target(pr, profile_progress(pr, m, now), true, &target, &approaching)) {
		/* A step pair holds its end positions, a timed one where time ran out. */
		if (pr->by_time) {
			port_finish(s, m->partner, brake, s->position);
			port_finish(m, port, brake, m->position);
			return;
		}
		end = pr->peak < 0 ? -(s32)pr->flat : (s32)pr->flat;
		port_finish(s, m->partner, brake, s->profile.origin +
			    (s->sync_carry + end * s->sync_factor) / 100);
		port_finish(m, port, brake, pr->origin + end);
		return;
	}
	/* The slave keeps its position at factor/100 of the master's travel. */
	err = sync_slave_lag100(m) / 100;
	slave_target = clamp(target * s->sync_factor / 100 + err * SYNC_POSITION_GAIN,
			     -SPEED_MAX, SPEED_MAX);
	/* A lagging slave slows the master down so the pair keeps its shape. */
	lag = target * s->sync_factor < 0 ? -err : err;
	master_target = target;
	if (s->sync_factor != 0 && lag > SYNC_LAG_FREE) {
		s32 slow = (lag - SYNC_LAG_FREE) * SYNC_LAG_SLOWDOWN;

		master_target = target > 0 ? max(target - slow, 0) : min(target + slow, 0);
	}
	if (approaching) {
		approach_cut(m, master_target);
		approach_cut(s, slave_target);
	}
	port_drive_power(m, pid_step(m, master_target), true);
	m->setpoint = master_target;
	if (s->sync_factor == 0) {
		s->hold_pos = s->profile.origin + s->sync_carry / 100;
		brake_hold(s);
		s->setpoint = 0;
	} else {
		port_drive_power(s, pid_step(s, slave_target), true);
		s->setpoint = slave_target;
	}
}

/*
 * Publishes a port's counters into the shared MOTORDATA: TachoCounts from the
 * start of the current command (0 while unlimited), Speed as measured (after
 * a STOP too, while the motor coasts or the brake settles) - the measurement
 * of the tick before, shown as LEGO's driver shows it, one tick late;
 * TachoSensor cumulative.
 */
static void publish(struct pwm_port *p, struct lms_motor_data *md, s8 speed)
{
	bool unlimited = p->state == STATE_UNREG || p->state == STATE_REG;

	WRITE_ONCE(md->tacho_counts, unlimited ? 0 : p->position - p->command_origin);
	WRITE_ONCE(md->speed, speed);
	WRITE_ONCE(md->tacho_sensor, p->position - p->sensor_origin);
}

/* The 2 ms control loop: speeds, regulation, ramps, sync pairs, brakes, MOTORDATA. */
static enum hrtimer_restart control_tick(struct hrtimer *timer)
{
	ktime_t now = ktime_get();
	u32 stamp;
	int i;

	hrtimer_forward_now(timer, ms_to_ktime(CONTROL_PERIOD_MS));
	spin_lock(&pwm_lock);
	/* Read under the lock: an edge stamped after it would look like a silence. */
	stamp = stamp_now();
	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];
		s8 shown = p->speed;

		p->speed = tacho_speed(p, stamp);
		switch (p->state) {
		case STATE_IDLE:
			break;
		case STATE_UNREG:
			p->setpoint = p->target;
			port_drive_power(p, p->target * (POWER_MAX / 100), false);
			break;
		case STATE_REG:
			p->setpoint = p->target;
			if (p->tacho)
				port_drive_power(p, pid_step(p, p->target), true);
			else
				port_drive_power(p, p->target * (POWER_MAX / 100), false);
			break;
		case STATE_LIMITED:
			limited_tick(p, i, now);
			break;
		case STATE_SYNC_MASTER:
			sync_tick(p, i, now);
			break;
		case STATE_SYNC_SLAVE:
			break;      /* driven by its master */
		case STATE_BRAKED:
			brake_hold(p);
			break;
		case STATE_BRAKE_TIMED:
			if (ktime_compare(now, p->brake_until) >= 0) {
				p->state = STATE_IDLE;
				port_output(p, DRIVE_COAST, 0);
			}
			break;
		}
		publish(p, &motor_data[i], shown);
	}
	spin_unlock(&pwm_lock);
	return HRTIMER_RESTART;
}

/* ---- Commands ---- */

/*
 * Each opcode has a handler that checks its fields, takes pwm_lock for the
 * few stores it makes and returns 0 or -EINVAL.  Port loops visit only the
 * ports in the mask.  The helpers below run with pwm_lock held.
 */

/* True if nos names at least one port and nothing else. */
static bool valid_nos(u8 nos)
{
	return nos != 0 && !(nos & ~LMS_PWM_PORT_MASK);
}

/* True while the speed regulator drives the port (its PID state is live). */
static bool regulating(const struct pwm_port *p)
{
	return p->state == STATE_REG || p->state == STATE_SYNC_MASTER ||
	       (p->state == STATE_SYNC_SLAVE && p->sync_factor != 0) ||
	       (p->state == STATE_LIMITED && p->profile.regulated);
}

/*
 * Where a new limited command enters its ramp up: as far in as the port
 * already runs, so that a command re-issued while running carries on
 * instead of starting again from rest.  The same ramp re-issued resumes
 * exactly; otherwise the ramp is entered at the magnitude (speed, or user
 * power) the port runs at in its direction, rounded up.
 */
static u32 ramp_entry(const struct pwm_port *p, const struct pwm_profile *next, ktime_t now)
{
	const struct pwm_profile *prev = &p->profile;
	s32 peak = next->peak, v;

	if (next->up == 0 || peak == 0)
		return 0;
	if (p->state == STATE_LIMITED && prev->by_time == next->by_time &&
	    prev->regulated == next->regulated && prev->peak == peak && prev->up == next->up)
		return min(prev->ramp_in + profile_progress(prev, p, now), next->up);
	v = next->regulated ? max_t(s32, p->speed * peak, p->setpoint * peak)
			    : p->power / (POWER_MAX / SPEED_MAX) * peak;
	v = clamp_t(s32, v / abs(peak), 0, abs(peak));
	if (next->up > U32_MAX / SPEED_MAX)
		return scale_fraction(next->up, v, abs(peak));
	return DIV_ROUND_UP(next->up * v, abs(peak));
}

/* Coasts a port and drops whatever it was doing, including its busy bits. */
static void port_float(struct pwm_port *p, int port)
{
	port_finish(p, port, false, 0);
}

/* Dissolves the sync pair a port is in: the partner floats. */
static void sync_dissolve(struct pwm_port *p)
{
	int other = p->partner;

	if (other < 0)
		return;
	p->partner = -1;
	port_float(&ports[other], other);
	if (p->state == STATE_SYNC_MASTER || p->state == STATE_SYNC_SLAVE)
		port_float(p, p - ports);
}

/* OUTPUT_POWER / OUTPUT_SPEED: new target; applies at once to a running unlimited port. */
static int cmd_target(const u8 *b, bool regulated)
{
	u8 nos = b[1];
	s8 value = (s8)b[2];
	unsigned long flags;
	struct pwm_port *p;

	if (!valid_nos(nos) || value < -SPEED_MAX || value > SPEED_MAX)
		return -EINVAL;
	spin_lock_irqsave(&pwm_lock, flags);
	for (p = ports; nos; nos >>= 1, p++) {
		if (!(nos & 1))
			continue;
		if (unlikely(p->partner >= 0))
			sync_dissolve(p);
		p->target = value * p->polarity;
		p->start_regulated = regulated;
		if (p->state == STATE_UNREG || p->state == STATE_REG) {
			if (regulated && p->state != STATE_REG)
				pid_reset(p);
			p->state = regulated ? STATE_REG : STATE_UNREG;
		}
	}
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* OUTPUT_SPEED. */
static int cmd_speed(const u8 *b)
{
	return cmd_target(b, true);
}

/* OUTPUT_POWER. */
static int cmd_power(const u8 *b)
{
	return cmd_target(b, false);
}

/* OUTPUT_START: an idle or braked port enters its unlimited target state. */
static int cmd_start(const u8 *b)
{
	u8 nos = b[1];
	unsigned long flags;
	struct pwm_port *p;

	if (!valid_nos(nos))
		return -EINVAL;
	spin_lock_irqsave(&pwm_lock, flags);
	for (p = ports; nos; nos >>= 1, p++) {
		if (!(nos & 1) || (p->state != STATE_IDLE && p->state != STATE_BRAKED &&
				   p->state != STATE_BRAKE_TIMED))
			continue;
		p->power = 0;
		pid_reset(p);
		p->state = p->start_regulated ? STATE_REG : STATE_UNREG;
	}
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* OUTPUT_STOP: hold position (brake) or coast; ends limited commands and pairs. */
static int cmd_stop(const u8 *b)
{
	u8 nos = b[1], brake = b[2];
	unsigned long flags;
	int i;

	if (!valid_nos(nos) || brake > 1)
		return -EINVAL;
	spin_lock_irqsave(&pwm_lock, flags);
	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];

		if (!(nos & BIT(i)))
			continue;
		sync_dissolve(p);
		port_finish(p, i, brake, p->position);
		/* Speed starts again from a cleared history, as LEGO's driver clears its samples. */
		p->stamp_valid = 0;
		p->run = RUN_CLEARED;
		p->speed = 0;
	}
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* OUTPUT_POLARITY: set (-1, 1) or toggle (0); running targets flip at once. */
static int cmd_polarity(const u8 *b)
{
	u8 nos = b[1];
	s8 polarity = (s8)b[2];
	unsigned long flags;
	int i;

	if (!valid_nos(nos) || polarity < -1 || polarity > 1)
		return -EINVAL;
	spin_lock_irqsave(&pwm_lock, flags);
	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];
		s8 want = polarity ? polarity : -p->polarity;

		if (!(nos & BIT(i)) || want == p->polarity)
			continue;
		p->polarity = want;
		p->target = -p->target;
		p->profile.peak = -p->profile.peak;
		if (p->state == STATE_REG)
			pid_reset(p);
	}
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* OUTPUT_RESET: ends sync; zeroes the command counters (not the sensor count). */
static int cmd_reset(const u8 *b)
{
	u8 nos = b[1];
	ktime_t now = ktime_get();
	unsigned long flags;
	int i;

	if (!valid_nos(nos))
		return -EINVAL;
	spin_lock_irqsave(&pwm_lock, flags);
	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];

		if (!(nos & BIT(i)))
			continue;
		sync_dissolve(p);
		p->command_origin = p->position;
		p->profile.origin = p->position;
		p->profile.start = now;
		p->hold_pos = p->position;
		p->hold_i = 0;
	}
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* OUTPUT_CLR_COUNT: zeroes the cumulative sensor count. */
static int cmd_clr_count(const u8 *b)
{
	u8 nos = b[1];
	unsigned long flags;
	int i;

	if (!valid_nos(nos))
		return -EINVAL;
	spin_lock_irqsave(&pwm_lock, flags);
	for (i = 0; i < LMS_PWM_PORTS; i++)
		if (nos & BIT(i))
			ports[i].sensor_origin = ports[i].position;
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* OUTPUT_SET_TYPE: a port whose type changed becomes idle with zeroed counters. */
static int cmd_set_type(const u8 *b)
{
	const u8 *types = b + 1;
	unsigned long flags;
	int i;

	spin_lock_irqsave(&pwm_lock, flags);
	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];

		if (types[i] == p->type)
			continue;
		sync_dissolve(p);
		port_float(p, i);
		p->type = types[i];
		p->tacho = types[i] == LMS_PWM_TYPE_TACHO || types[i] == LMS_PWM_TYPE_MINITACHO;
		p->medium = types[i] == LMS_PWM_TYPE_MINITACHO;
		p->command_origin = p->position;
		p->sensor_origin = p->position;
		p->hold_pos = p->position;
		p->hold_i = 0;
		p->stamp_valid = 0;
		p->run = RUN_CLEARED;
	}
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* PROGRAM_STOP's first half: everything stops; braked ports brake 100 ms, then coast. */
static void program_stop(void)
{
	ktime_t until = ktime_add(ktime_get(), ms_to_ktime(PROGRAM_STOP_BRAKE_MS));
	int i;

	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];
		bool braked = p->state == STATE_BRAKED;

		p->partner = -1;
		p->target = 0;
		port_float(p, i);
		if (braked) {
			p->state = STATE_BRAKE_TIMED;
			p->brake_until = until;
			port_output(p, DRIVE_BRAKE, PWM_PERIOD);
		}
	}
}

/* PROGRAM_START (and PROGRAM_STOP's second half): polarity +1, sync pairs dissolved. */
static void program_start(void)
{
	int i;

	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];

		p->partner = -1;
		if (p->state == STATE_SYNC_MASTER || p->state == STATE_SYNC_SLAVE)
			port_float(p, i);
		p->polarity = 1;
	}
}

/* PROGRAM_STOP, which falls through into PROGRAM_START as LEGO's does. */
static int cmd_program_stop(const u8 *b)
{
	unsigned long flags;

	spin_lock_irqsave(&pwm_lock, flags);
	program_stop();
	program_start();
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* PROGRAM_START. */
static int cmd_program_start(const u8 *b)
{
	unsigned long flags;

	spin_lock_irqsave(&pwm_lock, flags);
	program_start();
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* Opcodes the protocol defines but this driver has nothing to do for. */
static int cmd_ignored(const u8 *b)
{
	return 0;
}

/* Reads a little-endian s32 from a command buffer. */
static s32 get_s32(const u8 *b)
{
	return (s32)((u32)b[0] | (u32)b[1] << 8 | (u32)b[2] << 16 | (u32)b[3] << 24);
}

/*
 * Where a step command on a port counts from: where MOTORDATA TachoCounts is
 * 0.  That is the command's own start while the port runs unlimited, timed
 * or in a pair (their count restarts all the time or with the command), but
 * the stop after OUTPUT_STOP (counting on while coasting) or the start of a
 * step still running (a step re-issued ends where the first would have).
 */
static s32 step_origin(const struct pwm_port *p)
{
	if (p->state == STATE_IDLE || p->state == STATE_BRAKED ||
	    (p->state == STATE_LIMITED && !p->profile.by_time))
		return p->command_origin;
	return p->position;
}

/* STEP_/TIME_POWER and STEP_/TIME_SPEED: start a ramp profile on each port of nos. */
static int cmd_profile(const u8 *b, bool by_time, bool regulated)
{
	s8 value = (s8)b[LMS_PWM_STEP_OFF_VALUE];
	s32 step[3] = { get_s32(b + LMS_PWM_STEP_OFF_STEP1), get_s32(b + LMS_PWM_STEP_OFF_STEP2),
			get_s32(b + LMS_PWM_STEP_OFF_STEP3) };
	u8 nos = b[LMS_PWM_STEP_OFF_NOS];
	u8 brake = b[LMS_PWM_STEP_OFF_BRAKE];
	struct pwm_profile next;
	unsigned long flags;
	ktime_t now;
	s32 origin;
	int i;

	if (!valid_nos(nos) || value < -SPEED_MAX || value > SPEED_MAX || brake > 1)
		return -EINVAL;
	for (i = 0; i < 3; i++) {
		/* Steps carry the direction of the power: their sign is redundant.  Times may not be negative. */
		if (step[i] < 0 && (by_time || step[i] == S32_MIN))
			return -EINVAL;
		step[i] = abs(step[i]);
	}
	if ((u32)step[0] + (u32)step[1] + (u32)step[2] > S32_MAX)
		return -EINVAL;
	now = ktime_get();
	spin_lock_irqsave(&pwm_lock, flags);
	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];
		struct pwm_profile *pr = &p->profile;

		if (!(nos & BIT(i)))
			continue;
		origin = by_time ? p->position : step_origin(p);
		sync_dissolve(p);
		next = (struct pwm_profile){
			.by_time = by_time, .brake = brake, .regulated = regulated,
			.peak = value * p->polarity, .up = step[0], .flat = step[1], .down = step[2],
		};
		/* A new command changes the target; the regulator keeps what it has learnt. */
		if (!regulated || !regulating(p))
			pid_reset(p);
		next.ramp_in = ramp_entry(p, &next, now);
		*pr = next;
		pr->origin = origin;
		pr->start = now;
		/* A command re-issued into a later phase is in it already: no new phase. */
		pr->phase = profile_phase(pr, profile_progress(pr, p, now));
		p->command_origin = origin;
		/* A step command with no power would never arrive: it is done at once. */
		if (!by_time && value == 0 && step[0] + step[1] + step[2] != 0) {
			port_finish(p, i, brake, p->position);
			continue;
		}
		p->state = STATE_LIMITED;
		ready_status |= BIT(i);
		test_status |= BIT(i);
	}
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* True if the mask names exactly two ports. */
static bool two_ports(u8 nos)
{
	u8 rest = nos & (nos - 1);      /* drops the lowest set bit */

	return nos && rest && !(rest & (rest - 1));
}

/* STEP_SYNC / TIME_SYNC: two ports, the master at speed, the slave at the turn ratio. */
static int cmd_sync(const u8 *b, bool by_time)
{
	u8 nos = b[LMS_PWM_SYNC_OFF_NOS];
	s8 speed = (s8)b[LMS_PWM_SYNC_OFF_SPEED];
	s16 turn = (s16)(b[LMS_PWM_SYNC_OFF_TURN] | b[LMS_PWM_SYNC_OFF_TURN + 1] << 8);
	s32 step = get_s32(b + LMS_PWM_SYNC_OFF_STEP);
	u8 brake = b[LMS_PWM_SYNC_OFF_BRAKE];
	int first, second, mi, si, ratio;
	s32 lag;
	struct pwm_port *m, *s;
	unsigned long flags;
	ktime_t now;

	if (!valid_nos(nos) || !two_ports(nos) || speed < -SPEED_MAX || speed > SPEED_MAX ||
	    turn < -200 || turn > 200 || brake > 1 || step == S32_MIN || (by_time && step < 0))
		return -EINVAL;
	step = abs(step);     /* a step count carries the direction of the speed */
	for (first = 0; !(nos & BIT(first)); first++)
		;
	for (second = first + 1; !(nos & BIT(second)); second++)
		;
	mi = turn >= 0 ? first : second;
	si = turn >= 0 ? second : first;
	ratio = abs(turn) < 100 ? 100 - abs(turn) : -(abs(turn) - 100);
	now = ktime_get();

	spin_lock_irqsave(&pwm_lock, flags);
	m = &ports[mi];
	s = &ports[si];
	/*
	 * The same pair again (a steering loop re-issues it all the time) runs
	 * on: the regulators keep their state and, if the master stays master,
	 * the slave the lag it has.  Any other pair is dissolved first.
	 */
	if (m->partner == si) {
		lag = m->state == STATE_SYNC_MASTER ? sync_slave_lag100(m) : 0;
	} else {
		sync_dissolve(m);
		sync_dissolve(s);
		lag = 0;
		m->hold_i = 0;
		s->hold_i = 0;
		s->hold_still = 0;
	}
	if (!regulating(m))
		pid_reset(m);
	if (!regulating(s))
		pid_reset(s);
	m->profile = (struct pwm_profile){
		.by_time = by_time, .brake = brake, .regulated = true,
		.peak = speed * m->polarity, .flat = step, .origin = m->position, .start = now,
	};
	s->profile = m->profile;
	s->profile.origin = s->position;
	s->sync_carry = lag;
	/* Ratio in the motors' own frames: polarities enter through the factor. */
	s->sync_factor = ratio * s->polarity * m->polarity;
	m->partner = si;
	s->partner = mi;
	m->command_origin = m->position;
	s->command_origin = s->position;
	m->state = STATE_SYNC_MASTER;
	s->state = STATE_SYNC_SLAVE;
	ready_status |= nos;
	test_status |= nos;
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 0;
}

/* The four STEP_/TIME_ commands and the two SYNC commands. */
static int cmd_step_power(const u8 *b)
{
	return cmd_profile(b, false, false);
}

static int cmd_time_power(const u8 *b)
{
	return cmd_profile(b, true, false);
}

static int cmd_step_speed(const u8 *b)
{
	return cmd_profile(b, false, true);
}

static int cmd_time_speed(const u8 *b)
{
	return cmd_profile(b, true, true);
}

static int cmd_step_sync(const u8 *b)
{
	return cmd_sync(b, false);
}

static int cmd_time_sync(const u8 *b)
{
	return cmd_sync(b, true);
}

struct pwm_opcode {
	u8 min, max;                    /* accepted command lengths */
	int (*run)(const u8 *b);
};

#define OPCODE_FIRST LMS_PWM_OUTPUT_GET_TYPE
#define OPCODE(op, lo, hi, fn) [(op) - OPCODE_FIRST] = { (lo), (hi), (fn) }

/* The output opcodes 0xA0..0xB4, indexed from OPCODE_FIRST. */
static const struct pwm_opcode output_opcodes[] = {
	OPCODE(LMS_PWM_OUTPUT_GET_TYPE, 1, LMS_PWM_CMD_MAX, cmd_ignored),
	OPCODE(LMS_PWM_OUTPUT_SET_TYPE, 1 + LMS_PWM_PORTS, 1 + LMS_PWM_PORTS, cmd_set_type),
	OPCODE(LMS_PWM_OUTPUT_RESET, 2, 2, cmd_reset),
	OPCODE(LMS_PWM_OUTPUT_STOP, 3, 3, cmd_stop),
	OPCODE(LMS_PWM_OUTPUT_POWER, 3, 3, cmd_power),
	OPCODE(LMS_PWM_OUTPUT_SPEED, 3, 3, cmd_speed),
	OPCODE(LMS_PWM_OUTPUT_START, 2, 2, cmd_start),
	OPCODE(LMS_PWM_OUTPUT_POLARITY, 3, 3, cmd_polarity),
	OPCODE(LMS_PWM_OUTPUT_READ, 1, LMS_PWM_CMD_MAX, cmd_ignored),
	OPCODE(LMS_PWM_OUTPUT_TEST, 1, LMS_PWM_CMD_MAX, cmd_ignored),
	OPCODE(LMS_PWM_OUTPUT_READY, 1, LMS_PWM_CMD_MAX, cmd_ignored),
	OPCODE(LMS_PWM_OUTPUT_POSITION, 1, LMS_PWM_CMD_MAX, cmd_ignored),
	OPCODE(LMS_PWM_OUTPUT_STEP_POWER, LMS_PWM_STEP_LEN_MIN, LMS_PWM_STEP_LEN, cmd_step_power),
	OPCODE(LMS_PWM_OUTPUT_TIME_POWER, LMS_PWM_STEP_LEN_MIN, LMS_PWM_STEP_LEN, cmd_time_power),
	OPCODE(LMS_PWM_OUTPUT_STEP_SPEED, LMS_PWM_STEP_LEN_MIN, LMS_PWM_STEP_LEN, cmd_step_speed),
	OPCODE(LMS_PWM_OUTPUT_TIME_SPEED, LMS_PWM_STEP_LEN_MIN, LMS_PWM_STEP_LEN, cmd_time_speed),
	OPCODE(LMS_PWM_OUTPUT_STEP_SYNC, LMS_PWM_SYNC_LEN_MIN, LMS_PWM_SYNC_LEN, cmd_step_sync),
	OPCODE(LMS_PWM_OUTPUT_TIME_SYNC, LMS_PWM_SYNC_LEN_MIN, LMS_PWM_SYNC_LEN, cmd_time_sync),
	OPCODE(LMS_PWM_OUTPUT_CLR_COUNT, 2, 2, cmd_clr_count),
	OPCODE(LMS_PWM_OUTPUT_PRG_STOP, 1, LMS_PWM_CMD_MAX, cmd_ignored),
	OPCODE(LMS_PWM_OUTPUT_GET_COUNT, 1, LMS_PWM_CMD_MAX, cmd_ignored),
};

static const struct pwm_opcode program_stop_opcode = { 1, 1, cmd_program_stop };
static const struct pwm_opcode program_start_opcode = { 1, 1, cmd_program_start };

/* The table entry of an opcode, or NULL if the protocol has no such opcode. */
static const struct pwm_opcode *opcode_of(u8 op)
{
	unsigned int index = op - OPCODE_FIRST;

	if (likely(index < ARRAY_SIZE(output_opcodes)))
		return &output_opcodes[index];
	if (op == LMS_PWM_PROGRAM_STOP)
		return &program_stop_opcode;
	if (op == LMS_PWM_PROGRAM_START)
		return &program_start_opcode;
	return NULL;
}

/* ---- File operations ---- */

/* /dev/lms_pwm write: one command of the protocol; returns count or -EINVAL/-EFAULT. */
static ssize_t pwm_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	u8 cmd[LMS_PWM_CMD_MAX];
	const struct pwm_opcode *oc;
	int ret;

	if (count - 1 >= LMS_PWM_CMD_MAX)        /* 0 or more than the longest command */
		return -EINVAL;
	if (copy_from_user(cmd, buf, count))
		return -EFAULT;
	oc = opcode_of(cmd[0]);
	if (!oc || count < oc->min || count > oc->max)
		return -EINVAL;
	ret = oc->run(cmd);
	return ret ? ret : (ssize_t)count;
}

/* /dev/lms_pwm read: "R T ", the ReadyStatus and TestStatus masks as hex digits. */
static ssize_t pwm_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	static const char hex[] = "0123456789ABCDEF";
	char status[LMS_PWM_STATUS_LEN];
	unsigned long flags;
	size_t n = min_t(size_t, count, LMS_PWM_STATUS_LEN);

	spin_lock_irqsave(&pwm_lock, flags);
	status[0] = hex[ready_status & 0xF];
	status[2] = hex[test_status & 0xF];
	spin_unlock_irqrestore(&pwm_lock, flags);
	status[1] = ' ';
	status[3] = ' ';
	if (copy_to_user(buf, status, n))
		return -EFAULT;
	return n;
}

/* /dev/lms_motor write: one byte ORed into both busy masks. */
static ssize_t motor_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	unsigned long flags;
	u8 mask;

	if (count != 1)
		return -EINVAL;
	if (copy_from_user(&mask, buf, 1))
		return -EFAULT;
	if (mask & ~LMS_PWM_PORT_MASK)
		return -EINVAL;
	spin_lock_irqsave(&pwm_lock, flags);
	ready_status |= mask;
	test_status |= mask;
	spin_unlock_irqrestore(&pwm_lock, flags);
	return 1;
}

/* /dev/lms_motor read: nothing to read (as LEGO's). */
static ssize_t motor_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	return 0;
}

/* /dev/lms_motor mmap: the MOTORDATA page, from offset 0, at most one page. */
static int motor_mmap(struct file *file, struct vm_area_struct *vma)
{
	unsigned long size = vma->vm_end - vma->vm_start;

	if (vma->vm_pgoff != 0 || size == 0 || size > PAGE_SIZE)
		return -EINVAL;
	if (remap_pfn_range(vma, vma->vm_start, virt_to_phys(motor_data) >> PAGE_SHIFT,
			    size, vma->vm_page_prot))
		return -EAGAIN;
	return 0;
}

static const struct file_operations pwm_fops = {
	.owner = THIS_MODULE,
	.read = pwm_read,
	.write = pwm_write,
};

static const struct file_operations motor_fops = {
	.owner = THIS_MODULE,
	.read = motor_read,
	.write = motor_write,
	.mmap = motor_mmap,
};

static struct miscdevice pwm_misc = {
	.minor = MISC_DYNAMIC_MINOR,
	.name = LMS_PWM_DEVICE_NAME,
	.fops = &pwm_fops,
};

static struct miscdevice motor_misc = {
	.minor = MISC_DYNAMIC_MINOR,
	.name = LMS_MOTOR_DEVICE_NAME,
	.fops = &motor_fops,
};

/* ---- Hardware bring-up ---- */

/* Powers eHRPWM1 and the eCAPs through PSC1; -ETIMEDOUT if the transition hangs. */
static int psc_power_on(void)
{
	int i;

	writel(PSC_STATE_ENABLE, psc1_base + PSC_MDCTL(PSC1_LPSC_EHRPWM));
	writel(readl(psc1_base + PSC_MDCTL(PSC1_LPSC_ECAP)) | PSC_STATE_ENABLE,
	       psc1_base + PSC_MDCTL(PSC1_LPSC_ECAP));
	writel(readl(psc1_base + PSC_PTCMD) | PSC_GO_MASK, psc1_base + PSC_PTCMD);
	for (i = 0; i < PSC_POLL_LIMIT; i++) {
		if (!(readl(psc1_base + PSC_PTSTAT) & PSC_GO_MASK))
			return 0;
		udelay(1);
	}
	return -ETIMEDOUT;
}

/* Unlocks SYSCFG0, routes the PWM pins, starts the eHRPWM time base clock, locks again. */
static void syscfg_setup(bool tbclk_on)
{
	unsigned int i;
	u32 v;

	writel(SYSCFG0_KICK0_KEY, syscfg0_base + SYSCFG0_KICK0R);
	writel(SYSCFG0_KICK1_KEY, syscfg0_base + SYSCFG0_KICK1R);
	for (i = 0; tbclk_on && i < ARRAY_SIZE(pwm_pinmux); i++) {
		u8 __iomem *reg = syscfg0_base + SYSCFG0_PINMUX(pwm_pinmux[i].reg);

		v = readl(reg) & ~(0xFU << pwm_pinmux[i].shift);
		writel(v | (u32)pwm_pinmux[i].function << pwm_pinmux[i].shift, reg);
	}
	v = readl(syscfg0_base + SYSCFG0_CFGCHIP1);
	v = tbclk_on ? v | CFGCHIP1_TBCLKSYNC : v & ~CFGCHIP1_TBCLKSYNC;
	writel(v, syscfg0_base + SYSCFG0_CFGCHIP1);
	writel(0, syscfg0_base + SYSCFG0_KICK0R);
	writel(0, syscfg0_base + SYSCFG0_KICK1R);
}

/* Sets up eHRPWM1 (ports A, B) and eCAP0/1 in APWM mode (ports C, D), all at 0 duty. */
static void pwm_hw_setup(void)
{
	int i;

	writew(EPWM_TBCTL_UP_FREE, ehrpwm1_base + EPWM_TBCTL);
	writew(0, ehrpwm1_base + EPWM_TBPHS);
	writew(0, ehrpwm1_base + EPWM_TBCNT);
	writew(PWM_PERIOD - 1, ehrpwm1_base + EPWM_TBPRD);
	writew(EPWM_CMPCTL_SHADOW_ZERO, ehrpwm1_base + EPWM_CMPCTL);
	writew(EPWM_AQCTLA_LOW_ZERO_HIGH_CMPA, ehrpwm1_base + EPWM_AQCTLA);
	writew(EPWM_AQCTLB_LOW_ZERO_HIGH_CMPB, ehrpwm1_base + EPWM_AQCTLB);
	writew(0, ehrpwm1_base + EPWM_CMPA);
	writew(0, ehrpwm1_base + EPWM_CMPB);
	for (i = 0; i < 2; i++) {
		writew(ECAP_ECCTL2_APWM_LOW_FREE, ecap_base[i] + ECAP_ECCTL2);
		writel(0, ecap_base[i] + ECAP_TSCTR);
		writel(0, ecap_base[i] + ECAP_CTRPHS);
		writel(PWM_PERIOD - 1, ecap_base[i] + ECAP_CAP1);
		writel(0, ecap_base[i] + ECAP_CAP2);
	}
}

/* Starts TIMER64P3's TIM34 as the free-running edge time base. */
static void timer64_setup(void)
{
	writel(TIMER64_TGCR_DUAL_UNCHAINED_DIV4, timer64_base + TIMER64_TGCR);
	writel(TIMER64_TGCR_DUAL_UNCHAINED_DIV4 | TIMER64_TGCR_TIM34RS, timer64_base + TIMER64_TGCR);
	writel(0xFFFFFFFF, timer64_base + TIMER64_PRD34);
	writel(TIMER64_TCR_TIM34_CONTINUOUS, timer64_base + TIMER64_TCR);
}

/* Puts every port in its power-up state: coasting, tacho pins as inputs, nothing busy. */
static void ports_init(void)
{
	int i;

	ready_status = 0;
	test_status = 0;
	for (i = 0; i < LMS_PWM_PORTS; i++) {
		struct pwm_port *p = &ports[i];
		const struct pwm_port_pins *pins = &port_pins[i];

		memset(p, 0, sizeof(*p));
		p->pins = pins;
		p->int_bank = gpio_base + GPIO_BANK_REGS(pins->tacho_int);
		p->dir_bank = gpio_base + GPIO_BANK_REGS(pins->tacho_dir);
		p->int_mask = BIT(pins->tacho_int % 32);
		p->dir_mask = BIT(pins->tacho_dir % 32);
		p->irq = -1;
		p->type = LMS_PWM_TYPE_TACHO;
		p->tacho = true;
		p->polarity = 1;
		p->partner = -1;
		p->state = STATE_IDLE;
		gpio_float(pins->tacho_int);
		gpio_float(pins->tacho_dir);
		p->drive = DRIVE_BRAKE;     /* forces the first port_output to write the pins */
		port_output(p, DRIVE_COAST, 0);
	}
}

/* Coasts every port and zeroes every duty (module exit and init failure). */
static void ports_shutdown(void)
{
	int i;

	for (i = 0; i < LMS_PWM_PORTS; i++)
		port_output(&ports[i], DRIVE_COAST, 0);
}

/* Unmaps whatever registers are mapped and releases the exclusive regions. */
static void regs_unmap(void)
{
	if (timer64_base) {
		iounmap(timer64_base);
		release_mem_region(TIMER64P3_PHYS, TIMER64_SIZE);
	}
	if (ecap_base[1]) {
		iounmap(ecap_base[1]);
		release_mem_region(ECAP1_PHYS, ECAP_SIZE);
	}
	if (ecap_base[0]) {
		iounmap(ecap_base[0]);
		release_mem_region(ECAP0_PHYS, ECAP_SIZE);
	}
	if (ehrpwm1_base) {
		iounmap(ehrpwm1_base);
		release_mem_region(EHRPWM1_PHYS, EHRPWM_SIZE);
	}
	if (psc1_base)
		iounmap(psc1_base);
	if (syscfg0_base)
		iounmap(syscfg0_base);
	if (gpio_base)
		iounmap(gpio_base);
	timer64_base = NULL;
	ecap_base[0] = ecap_base[1] = NULL;
	ehrpwm1_base = NULL;
	psc1_base = syscfg0_base = gpio_base = NULL;
}

/* Claims (exclusive ones only) and maps one register block. */
static u8 __iomem *map_block(resource_size_t phys, resource_size_t size, bool exclusive)
{
	u8 __iomem *base;

	if (exclusive && !request_mem_region(phys, size, LMS_PWM_DEVICE_NAME))
		return NULL;
	base = ioremap(phys, size);
	if (!base && exclusive)
		release_mem_region(phys, size);
	return base;
}

/* Maps the register blocks; GPIO, SYSCFG0 and PSC1 are shared with other drivers. */
static int regs_map(void)
{
	gpio_base = map_block(GPIO_PHYS, GPIO_SIZE, false);
	syscfg0_base = map_block(SYSCFG0_PHYS, SYSCFG0_SIZE, false);
	psc1_base = map_block(PSC1_PHYS, PSC1_SIZE, false);
	ehrpwm1_base = map_block(EHRPWM1_PHYS, EHRPWM_SIZE, true);
	ecap_base[0] = map_block(ECAP0_PHYS, ECAP_SIZE, true);
	ecap_base[1] = map_block(ECAP1_PHYS, ECAP_SIZE, true);
	timer64_base = map_block(TIMER64P3_PHYS, TIMER64_SIZE, true);
	if (!gpio_base || !syscfg0_base || !psc1_base || !ehrpwm1_base ||
	    !ecap_base[0] || !ecap_base[1] || !timer64_base) {
		regs_unmap();
		return -EBUSY;
	}
	return 0;
}

/* Releases the tacho interrupts that were requested. */
static void tacho_irqs_free(void)
{
	int i;

	for (i = 0; i < LMS_PWM_PORTS; i++) {
		if (ports[i].irq >= 0)
			free_irq(ports[i].irq, &ports[i]);
		ports[i].irq = -1;
	}
}

/* Requests each port's tacho interrupt on both edges. */
static int tacho_irqs_request(void)
{
	int i, irq, ret;

	for (i = 0; i < LMS_PWM_PORTS; i++) {
		irq = gpio_to_irq(port_pins[i].tacho_int);
		if (irq < 0) {
			ret = irq;
			goto fail;
		}
		ret = request_irq(irq, tacho_isr, 0, LMS_PWM_DEVICE_NAME, &ports[i]);
		if (ret)
			goto fail;
		ports[i].irq = irq;
		ret = irq_set_irq_type(irq, IRQ_TYPE_EDGE_BOTH);
		if (ret)
			goto fail;
	}
	return 0;
fail:
	tacho_irqs_free();
	return ret;
}

/* Module load: memory, registers, hardware, interrupts, devices, then the control loop. */
static int __init d_pwm_init(void)
{
	int ret;

	/* Two pages so that one whole page-aligned page can be mapped to user space. */
	motor_alloc = kzalloc(2 * PAGE_SIZE, GFP_KERNEL);
	if (!motor_alloc)
		return -ENOMEM;
	motor_data = (struct lms_motor_data *)PAGE_ALIGN((unsigned long)motor_alloc);
	SetPageReserved(virt_to_page(motor_data));

	ret = regs_map();
	if (ret)
		goto fail_free;
	ret = psc_power_on();
	if (ret) {
		pr_err("lms_pwm: PSC1 did not power eHRPWM1/eCAP\n");
		goto fail_unmap;
	}
	syscfg_setup(false);
	pwm_hw_setup();
	syscfg_setup(true);
	timer64_setup();
	ports_init();

	ret = tacho_irqs_request();
	if (ret)
		goto fail_outputs;
	ret = misc_register(&pwm_misc);
	if (ret)
		goto fail_irqs;
	ret = misc_register(&motor_misc);
	if (ret)
		goto fail_pwm_misc;

	hrtimer_init(&control_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	control_timer.function = control_tick;
	hrtimer_start(&control_timer, ms_to_ktime(CONTROL_PERIOD_MS), HRTIMER_MODE_REL);
	return 0;

fail_pwm_misc:
	misc_deregister(&pwm_misc);
fail_irqs:
	tacho_irqs_free();
fail_outputs:
	ports_shutdown();
fail_unmap:
	regs_unmap();
fail_free:
	ClearPageReserved(virt_to_page(motor_data));
	kfree(motor_alloc);
	motor_alloc = NULL;
	motor_data = NULL;
	return ret;
}

/* Module unload: stops the loop, removes devices and interrupts, coasts, releases. */
static void __exit d_pwm_exit(void)
{
	hrtimer_cancel(&control_timer);
	misc_deregister(&motor_misc);
	misc_deregister(&pwm_misc);
	tacho_irqs_free();
	ports_shutdown();
	syscfg_setup(false);
	regs_unmap();
	ClearPageReserved(virt_to_page(motor_data));
	kfree(motor_alloc);
	motor_alloc = NULL;
	motor_data = NULL;
}

module_init(d_pwm_init);
module_exit(d_pwm_exit);

MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("LEGO Mindstorms EV3 motor outputs (lms2012 d_pwm interface)");
