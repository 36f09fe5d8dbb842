/*
 * gpio.c — the DaVinci GPIO controller (9 banks in 5 bank-pair blocks) and
 * the pins behind it.  Host only.
 *
 * A pin's level is resolved from the SoC side (DIR bit 0 and muxed to GPIO:
 * OUT_DATA wins) and the external side a model sets (driven, pulled or
 * floating, which reads 0).  Every level change runs the edge detectors:
 * an edge enabled in SET_RIS_TRIG/SET_FAL_TRIG sets INTSTAT and, with the
 * bank enabled in BINTEN, pulses the bank's system interrupt (42 + bank).
 *
 * Pin multiplexing: where this file knows which PINMUX field selects a pin
 * (banks 1..6: pins 8..15 in PINMUX(2b+1), pins 0..7 in PINMUX(2b+2), one
 * 4-bit field per pin from bit 28 down, GPIO = function 8), a pin whose field
 * selects another function is not driven by the SoC, and a driver writing
 * OUT_DATA for such an output pin is reported.  Banks 0, 7 and 8 are assumed
 * muxed.  The state Linux leaves has the EV3's pins muxed to GPIO.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/gpio.h"
#include "host_sim/intc.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/syscfg.h"
#include "host_sim/trace.h"
#include "soc_parts.h"

#define GPIO_PAIRS        5U
#define GPIO_BINTEN       0x08U
#define PAIR_BASE(n)      (0x10U + 0x28U * (n))
#define R_DIR             0x00U
#define R_OUT_DATA        0x04U
#define R_SET_RIS_TRIG    0x14U
#define R_SET_FAL_TRIG    0x1CU
#define R_IN_DATA         0x10U
#define R_INTSTAT         0x24U
#define PAIR_REG_SLOTS    (R_INTSTAT / 4U + 1U)
#define GPIO_MUX_FUNC     8U
#define MAX_WATCHES       256U

struct pin {
	uint8_t ext;                /* enum hs_pin_ext */
	bool level;
	bool soc_drives;
	bool muxed;
	bool contention;
	bool mux_reported;
	uint8_t mux_shift;          /* pin_muxed reads the field at mux_shift of *mux_reg */
	const uint32_t *mux_reg;
	int16_t first_watch;        /* index into watches, -1 for none */
	struct hs_signal *sig;      /* declared on first activity */
};

static struct {
	struct hs_region *region;
	uint32_t *pair_val[GPIO_PAIRS][PAIR_REG_SLOTS];   /* stored values pair_reg reads */
	uint32_t *binten;
	struct pin pins[HS_GPIO_NPINS];
	uint32_t in_data[GPIO_PAIRS];
	const uint32_t *in_data_val;    /* IN_DATA[0]'s stored value; IN_DATA[n]'s follows at n */
	bool pinmux_check;
	int syscfg_watch;
	struct {
		hs_pin_watch_fn fn;
		void *ctx;
		uint16_t pin;
		int16_t next;
	} watches[MAX_WATCHES];
} g;

const char *hs_gpio_name(unsigned pin, char *buf)
{
	snprintf(buf, 8, "GP%u_%u", (pin / 16U) % 100U, pin % 16U);
	return buf;
}

int hs_gpio_parse(const char *name)
{
	unsigned bank, bit;
	char tail;

	if (!name || sscanf(name, "GP%u_%u%c", &bank, &bit, &tail) != 2 || bank >= HS_GPIO_BANKS || bit >= 16U)
		return -1;
	return (int)HS_GPIO(bank, bit);
}

/* The PINMUX register and shift selecting pin, or false if not known here. */
static bool pin_mux_field(unsigned pin, unsigned *reg, unsigned *shift)
{
	unsigned bank = pin / 16U, bit = pin % 16U;

	/* Bank 1 bits 8..15 do not follow the pattern: PINMUX3 holds SPI0, UART0 and eHRPWM0
	 * pins (EPWM0B at [7:4], UART0_TXD/GP8_3 at [23:20], LEGO's d_sound and d_iic), so
	 * their fields are not known here. */
	if (bank < 1U || bank > 6U || (bank == 1U && bit >= 8U))
		return false;
	if (bit >= 8U) {
		*reg = 2U * bank + 1U;
		*shift = 28U - 4U * (bit - 8U);
	} else {
		*reg = 2U * bank + 2U;
		*shift = 28U - 4U * bit;
	}
	return true;
}

/* Muxes pin to GPIO in SYSCFG0, as board code does before a driver loads. */
void hs_gpio_mux_as_gpio(unsigned pin)
{
	struct hs_region *syscfg0 = hs_region_by_name("SYSCFG0");
	unsigned reg, shift;

	if (syscfg0 && pin_mux_field(pin, &reg, &shift))
		hs_reg_update(syscfg0, 0x120U + 4U * reg, 0xFU << shift, GPIO_MUX_FUNC << shift);
}

/* PINMUX words pin_muxed reads for a pin whose field it does not consult: one
 * selecting GPIO at bits 3:0 (the mux is not known here, or not checked), one
 * selecting nothing (no SYSCFG0 to read it from). */
static const uint32_t mux_word_gpio = GPIO_MUX_FUNC;
static const uint32_t mux_word_none;

/* true if pin is muxed to GPIO (or its mux is not known here, or not checked);
 * every resolve asks, so pin_mux_locate finds once what to read: one field,
 * no branch. */
static inline bool pin_muxed(unsigned pin)
{
	const struct pin *p = &g.pins[pin];

	return ((*p->mux_reg >> p->mux_shift) & 0xFU) == GPIO_MUX_FUNC;
}

/* Finds where pin's PINMUX field is stored, for pin_muxed (g.pinmux_check set). */
static void pin_mux_locate(unsigned pin)
{
	struct pin *p = &g.pins[pin];
	unsigned reg, shift;

	p->mux_reg = &mux_word_gpio;
	p->mux_shift = 0;
	if (g.pinmux_check && pin_mux_field(pin, &reg, &shift)) {
		const uint32_t *word = hs_syscfg_pinmux_ptr(reg);

		p->mux_reg = word != NULL ? word : &mux_word_none;
		p->mux_shift = (uint8_t)shift;
	}
}

/* Stored value of a bank-pair register (DIR, OUT_DATA, the triggers or INTSTAT). */
static uint32_t pair_reg(unsigned pair, uint32_t r)
{
	return *g.pair_val[pair][r / 4U];
}

/* pin_trace_declare's first activity: out of line, so that the resolve, which
 * asks on every change, keeps no name buffer. */
static __attribute__((noinline)) void pin_trace_declare_first(unsigned pin)
{
	char name[8];

	g.pins[pin].sig = hs_trace_signal("gpio", hs_gpio_name(pin, name), 1);
}

/* Makes the pin visible in traces. */
static inline void pin_trace_declare(unsigned pin)
{
	if (!g.pins[pin].sig)
		pin_trace_declare_first(pin);
}

/* Records the pin's level (or 'z' when nothing drives it) in its trace signal. */
static inline void pin_trace(const struct pin *p)
{
	if (!p->sig)
		return;
	if (!p->soc_drives && p->ext == HS_EXT_FLOAT)
		hs_trace_set_z(p->sig);
	else
		hs_trace_set(p->sig, p->level);
}

static void pin_state_of(unsigned pin, struct hs_pin_state *st)
{
	const struct pin *p = &g.pins[pin];
	unsigned pair = pin / 32U, bit = pin % 32U;

	st->soc_drives = p->soc_drives;
	st->soc_level = g.region ? (pair_reg(pair, R_OUT_DATA) >> bit) & 1U : 0U;
	st->muxed_gpio = p->muxed;
	st->ext = (enum hs_pin_ext)p->ext;
	st->level = p->level;
	st->contention = p->contention;
}

/* Reports a pin starting to be driven against the SoC's out level (out of
 * line, as pin_notify). */
static __attribute__((noinline)) void contention_report(unsigned pin, bool out)
{
	char name[8];

	rtos_host_trace("host_sim", "gpio %s: contention, SoC drives %d against an external %s",
			hs_gpio_name(pin, name), out, out ? "low" : "high");
}

/* Tells the pin's watchers its state: out of line, so that the resolve of
 * an unwatched pin (a tacho edge) keeps no state on its stack. */
static __attribute__((noinline)) void pin_notify(unsigned pin)
{
	struct hs_pin_state st;

	pin_state_of(pin, &st);
	for (int16_t w = g.pins[pin].first_watch; w >= 0; w = g.watches[w].next)
		g.watches[w].fn(g.watches[w].ctx, pin, &st);
}

/* pin_resolve; input: the caller saw the pin's DIR bit set (the SoC does not
 * drive it), which lets a constant true fold the SoC side away (a motor's tacho
 * edges, thousands per second, resolve input pins). */
static inline __attribute__((always_inline)) void pin_resolve_as(unsigned pin, bool notify, bool input)
{
	struct pin *p = &g.pins[pin];
	unsigned pair = pin / 32U, bit = pin % 32U;
	uint32_t m = 1U << bit;
	bool out, drives, level, changed;
	bool old_drives = p->soc_drives, old_level = p->level, old_cont = p->contention;

	if (!input && !g.region)    /* input: the caller saw the region's DIR */
		return;
	p->muxed = pin_muxed(pin);
	drives = !input && p->muxed && !(pair_reg(pair, R_DIR) & m);
	out = drives && (pair_reg(pair, R_OUT_DATA) & m) != 0;
	if (drives)
		level = out;
	else
		level = p->ext == HS_EXT_HIGH || p->ext == HS_EXT_PULL_UP;
	p->soc_drives = drives;
	p->level = level;
	p->contention = drives && ((p->ext == HS_EXT_LOW && out) || (p->ext == HS_EXT_HIGH && !out));
	if (p->contention && !old_cont)
		contention_report(pin, out);
	if (drives)
		pin_trace_declare(pin);
	changed = level != old_level;
	if (changed) {
		uint32_t trig;

		g.in_data[pair] ^= m;
		trig = pair_reg(pair, level ? R_SET_RIS_TRIG : R_SET_FAL_TRIG);
		if (trig & m) {
			unsigned bank = pin / 16U;

			*g.pair_val[pair][R_INTSTAT / 4U] |= m;
			if (*g.binten & (1U << bank))
				hs_intc_raise(HS_GPIO_BANK_INTNO(bank));
		}
	}
	pin_trace(p);
	if (p->first_watch >= 0 && (notify || changed || drives != old_drives || p->contention != old_cont))
		pin_notify(pin);
}

/* Recomputes pin from both sides; handles edges, interrupts, trace, watchers. */
static void pin_resolve(unsigned pin, bool notify)
{
	pin_resolve_as(pin, notify, false);
}

/* DIR/OUT_DATA/SET_DATA/CLR_DATA written: resolve the pins whose bits changed. */
static void soc_side_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	unsigned pair = a->index;
	uint32_t diff = old ^ now;
	bool data_reg = a->reg->name[0] != 'D';

	(void)ctx;
	if (data_reg && g.pinmux_check) {
		/* A driver driving a pin that is not muxed to GPIO: it will not move. */
		uint32_t touched = (a->reg->name[0] == 'O' ? diff : written) & ~pair_reg(pair, R_DIR);

		for (unsigned b = 0; touched && b < 32U; b++) {
			unsigned pin = 32U * pair + b;
			unsigned reg = 0, shift = 0;

			if (!(touched & (1U << b)) || pin >= HS_GPIO_NPINS || pin_muxed(pin) || g.pins[pin].mux_reported)
				continue;
			pin_mux_field(pin, &reg, &shift);
			g.pins[pin].mux_reported = true;
			{
				char name[8];

				rtos_host_bug("host_sim", "GPIO.%s[%u] drives %s, an output pin whose PINMUX%u[%u:%u] is %u, "
					      "not GPIO (%u): the pin does not move", a->reg->name, pair,
					      hs_gpio_name(pin, name), reg, shift + 3U, shift,
					      hs_syscfg_pinmux_field(reg, shift), GPIO_MUX_FUNC);
			}
		}
	}
	for (unsigned b = 0; diff && b < 32U; b++) {
		unsigned pin = 32U * pair + b;

		if ((diff & (1U << b)) && pin < HS_GPIO_NPINS)
			pin_resolve(pin, true);
	}
}

/* IN_DATA: the resolved levels. */
static void in_data_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx;
	*value = g.in_data[a->index];
}

/* in_data_read as IN_DATA's direct read (regs.h): the pair is where the
 * element's stored value lies in the array (checked by hs_gpio_create). */
static uint32_t in_data_read_direct(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);

	return *d->value = g.in_data[d->value - g.in_data_val];
}

/* INTSTAT's direct write (regs.h): write 1 to clear, all 32 bits, no hook. */
static void intstat_write_direct(const struct rtos_host_mmio_route *rt, uint32_t data)
{
	*hs_direct_of(rt)->value &= ~data;
}

/* A PINMUX change can connect or disconnect pins from the GPIO controller. */
static void pinmux_changed(void *ctx, uint32_t offset, uint32_t old, uint32_t now)
{
	(void)ctx;
	if (offset < 0x120U || offset > 0x16CU)
		return;
	for (unsigned pin = 16; pin < 7U * 16U; pin++) {
		unsigned reg, shift;

		if (pin_mux_field(pin, &reg, &shift) && 0x120U + 4U * reg == offset &&
		    (((old ^ now) >> shift) & 0xFU))
			pin_resolve(pin, true);
	}
}

#define PAIR_REG(nm, off, k, ...) \
	{ .name = nm, .offset = 0x10 + (off), .count = GPIO_PAIRS, .stride = 0x28, .kind = k, __VA_ARGS__ }

static const struct hs_reg gpio_regs[] = {
	{ .name = "REVID",  .offset = 0x00, .kind = HS_RO, .reset = 0x44830105 },
	{ .name = "BINTEN", .offset = GPIO_BINTEN, .kind = HS_RW, .mask = 0x1FF },
	PAIR_REG("DIR",          0x00, HS_RW,  .reset = 0xFFFFFFFF, .after_write = soc_side_written),
	PAIR_REG("OUT_DATA",     0x04, HS_RW,  .after_write = soc_side_written),
	PAIR_REG("SET_DATA",     0x08, HS_W1S, .alias = "OUT_DATA", .after_write = soc_side_written),
	PAIR_REG("CLR_DATA",     0x0C, HS_W1C, .alias = "OUT_DATA", .after_write = soc_side_written),
	PAIR_REG("IN_DATA",      0x10, HS_RO,  .before_read = in_data_read, .read_direct = in_data_read_direct),
	PAIR_REG("SET_RIS_TRIG", 0x14, HS_W1S),
	PAIR_REG("CLR_RIS_TRIG", 0x18, HS_W1C, .alias = "SET_RIS_TRIG"),
	PAIR_REG("SET_FAL_TRIG", 0x1C, HS_W1S),
	PAIR_REG("CLR_FAL_TRIG", 0x20, HS_W1C, .alias = "SET_FAL_TRIG"),
	PAIR_REG("INTSTAT",      0x24, HS_W1C, .write_direct = intstat_write_direct),
};

/* EV3 pins Linux muxes to GPIO at boot (the port pin tables of LEGO's d_pwm.c/d_analog.c). */
static const uint8_t ev3_gpio_pins[] = {
	HS_GPIO(1, 14), HS_GPIO(1, 15), HS_GPIO(2, 1), HS_GPIO(2, 2), HS_GPIO(2, 5), HS_GPIO(2, 8),
	HS_GPIO(2, 9), HS_GPIO(3, 6), HS_GPIO(3, 8), HS_GPIO(3, 14), HS_GPIO(3, 15), HS_GPIO(5, 3),
	HS_GPIO(5, 4), HS_GPIO(5, 8), HS_GPIO(5, 9), HS_GPIO(5, 10), HS_GPIO(5, 11), HS_GPIO(5, 13),
	HS_GPIO(5, 15), HS_GPIO(6, 4), HS_GPIO(6, 8), HS_GPIO(6, 9),
};

ER hs_gpio_create(bool cold, bool pinmux_check)
{
	struct hs_region *sys0;

	memset(&g, 0, sizeof(g));
	g.pinmux_check = pinmux_check;
	for (unsigned i = 0; i < HS_GPIO_NPINS; i++) {
		g.pins[i].first_watch = -1;
		pin_mux_locate(i);
	}
	g.region = hs_region_add(&(struct hs_region_cfg){
		.name = "GPIO", .phys = HS_GPIO_BASE, .size = 0x1000,
		.regs = gpio_regs, .nregs = HS_ARRAY_SIZE(gpio_regs),
		.power = HS_PSC1_MODULE(HS_LPSC1_GPIO), .ctx = NULL });
	if (!g.region)
		return E_SYS;
	for (unsigned pair = 0; pair < GPIO_PAIRS; pair++) {
		static const uint32_t used[] = { R_DIR, R_OUT_DATA, R_SET_RIS_TRIG, R_SET_FAL_TRIG, R_INTSTAT };

		for (unsigned i = 0; i < HS_ARRAY_SIZE(used); i++)
			g.pair_val[pair][used[i] / 4U] = hs_reg_value_ptr(g.region, PAIR_BASE(pair) + used[i]);
	}
	g.in_data_val = hs_reg_value_ptr(g.region, PAIR_BASE(0) + R_IN_DATA);
	for (unsigned pair = 1; pair < GPIO_PAIRS; pair++) {
		if (hs_reg_value_ptr(g.region, PAIR_BASE(pair) + R_IN_DATA) != g.in_data_val + pair) {
			rtos_host_bug("host_sim", "GPIO.IN_DATA[%u]'s stored value does not follow IN_DATA[0]'s", pair);
			return E_SYS;
		}
	}
	g.binten = hs_reg_value_ptr(g.region, GPIO_BINTEN);
	sys0 = hs_region_by_name("SYSCFG0");
	if (!cold && sys0) {
		for (unsigned i = 0; i < HS_ARRAY_SIZE(ev3_gpio_pins); i++) {
			unsigned reg, shift;

			if (pin_mux_field(ev3_gpio_pins[i], &reg, &shift))
				hs_reg_update(sys0, 0x120U + 4U * reg, 0xFU << shift, GPIO_MUX_FUNC << shift);
		}
	}
	g.syscfg_watch = hs_syscfg_watch(pinmux_changed, NULL);
	for (unsigned pin = 0; pin < HS_GPIO_NPINS; pin++)
		g.pins[pin].muxed = pin_muxed(pin);
	return E_OK;
}

void hs_gpio_destroy(void)
{
	hs_syscfg_unwatch(g.syscfg_watch);
	memset(&g, 0, sizeof(g));
}

/* true if pin exists, else reports the caller's bug. */
static bool pin_ok(unsigned pin, const char *what)
{
	if (pin < HS_GPIO_NPINS && g.region)
		return true;
	if (!g.region)
		rtos_host_bug("host_sim", "%s(%u): no board", what, pin);
	else
		rtos_host_bug("host_sim", "%s(%u): no such GPIO pin (0..%u)", what, pin, HS_GPIO_NPINS - 1U);
	return false;
}

void hs_gpio_drive(unsigned pin, enum hs_pin_ext ext)
{
	struct pin *p;

	if (!pin_ok(pin, "hs_gpio_drive"))
		return;
	if ((unsigned)ext > HS_EXT_PULL_UP) {
		rtos_host_bug("host_sim", "hs_gpio_drive(%u, %d): bad drive", pin, (int)ext);
		return;
	}
	p = &g.pins[pin];
	if (p->ext == (uint8_t)ext)
		return;
	p->ext = (uint8_t)ext;
	pin_trace_declare(pin);
	if ((pair_reg(pin / 32U, R_DIR) & (1U << (pin % 32U))))
		pin_resolve_as(pin, true, true);
	else
		pin_resolve(pin, true);
}

void hs_gpio_set_input(unsigned pin, int level)
{
	hs_gpio_drive(pin, level ? HS_EXT_HIGH : HS_EXT_LOW);
}

bool hs_gpio_level(unsigned pin)
{
	return pin_ok(pin, "hs_gpio_level") && g.pins[pin].level;
}

void hs_gpio_state(unsigned pin, struct hs_pin_state *st)
{
	memset(st, 0, sizeof(*st));
	if (pin_ok(pin, "hs_gpio_state"))
		pin_state_of(pin, st);
}

bool hs_gpio_soc_output(unsigned pin, bool *level)
{
	/* the two fields of hs_gpio_state, without the rest (the ADC asks on every frame) */
	bool known = pin_ok(pin, "hs_gpio_soc_output");

	if (level)
		*level = known && ((pair_reg(pin / 32U, R_OUT_DATA) >> (pin % 32U)) & 1U);
	return known && g.pins[pin].soc_drives;
}

bool hs_gpio_soc_output_or_level(unsigned pin, bool *level)
{
	const struct pin *p;

	if (!pin_ok(pin, "hs_gpio_soc_output_or_level")) {
		*level = false;
		return false;
	}
	p = &g.pins[pin];
	if (!p->soc_drives) {
		*level = p->level;
		return false;
	}
	*level = (pair_reg(pin / 32U, R_OUT_DATA) >> (pin % 32U)) & 1U;
	return true;
}

int hs_gpio_watch(unsigned pin, hs_pin_watch_fn fn, void *ctx)
{
	if (!pin_ok(pin, "hs_gpio_watch") || !fn)
		return 0;
	for (unsigned i = 0; i < MAX_WATCHES; i++) {
		if (!g.watches[i].fn) {
			g.watches[i].fn = fn;
			g.watches[i].ctx = ctx;
			g.watches[i].pin = (uint16_t)pin;
			g.watches[i].next = g.pins[pin].first_watch;
			g.pins[pin].first_watch = (int16_t)i;
			pin_trace_declare(pin);
			pin_trace(&g.pins[pin]);
			return (int)i + 1;
		}
	}
	return 0;
}

void hs_gpio_unwatch(int handle)
{
	int16_t i = (int16_t)(handle - 1);
	int16_t *link;

	if (handle <= 0 || (unsigned)handle > MAX_WATCHES || !g.watches[i].fn)
		return;
	for (link = &g.pins[g.watches[i].pin].first_watch; *link >= 0; link = &g.watches[*link].next) {
		if (*link == i) {
			*link = g.watches[i].next;
			break;
		}
	}
	g.watches[i].fn = NULL;
}
