/*
 * i2c.c — the AM1808's I2C0 and I2C1 as bus masters, one model
 * instantiated twice (host_sim/devices/i2c.h states the behaviour): each
 * transfer a sequence of events in virtual time — START and the address,
 * each byte, STOP — answered by the slaves connected to the bus.
 */
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/devices/i2c.h"

enum {
	ICOAR = 0x00, ICIMR = 0x04, ICSTR = 0x08, ICCLKL = 0x0C, ICCLKH = 0x10, ICCNT = 0x14,
	ICDRR = 0x18, ICSAR = 0x1C, ICDXR = 0x20, ICMDR = 0x24, ICIVR = 0x28, ICEMDR = 0x2C,
	ICPSC = 0x30, REVID1 = 0x34, REVID2 = 0x38, ICPFUNC = 0x48,
};

/* ICSTR */
#define STR_AL		(1U << 0)
#define STR_NACK	(1U << 1)
#define STR_ARDY	(1U << 2)
#define STR_RRDY	(1U << 3)
#define STR_XRDY	(1U << 4)
#define STR_SCD		(1U << 5)
#define STR_XSMT	(1U << 10)
#define STR_BB		(1U << 12)
#define STR_W1C		0x303FU     /* AL..SCD, BB, NACKSNT */
#define STR_RESET	(STR_XSMT | STR_XRDY)
#define INT_FLAGS	0x7FU       /* the flags ICIMR enables: AL..SCD, AAS */
/* ICMDR */
#define MDR_RM		(1U << 7)
#define MDR_IRS		(1U << 5)
#define MDR_TRX		(1U << 9)
#define MDR_MST		(1U << 10)
#define MDR_STP		(1U << 11)
#define MDR_STT		(1U << 13)

struct i2c_instance {
	const char *name;
	uint32_t phys;
	unsigned power;
	unsigned intno;
	uint32_t clock_hz;
};

static const struct i2c_instance i2c_instances[HS_I2C_BUSES] = {
	{ "I2C0", HS_I2C0_BASE, HS_NO_PSC, HS_I2C0_INTNO, HS_OSCIN_HZ },
	{ "I2C1", HS_I2C1_BASE, HS_PSC1_MODULE(HS_LPSC1_I2C1), HS_I2C1_INTNO, HS_PLL1_SYSCLK2_HZ },
};

struct slave {
	uint8_t addr;
	const struct hs_i2c_slave_ops *ops;
	void *ctx;
};

enum phase {
	PH_IDLE,        /* bus free (or another master's) */
	PH_ADDRESS,     /* START and the address byte on the wire */
	PH_WAIT_TX,     /* holding SCL low until ICDXR is written */
	PH_TX,          /* a byte going out */
	PH_RX,          /* a byte coming in */
	PH_WAIT_RX,     /* a byte received, held until ICDRR is read */
	PH_HOLD,        /* count done without STP: ARDY, bus held for a repeated START */
	PH_NACKED,      /* the slave NACKed: waiting for STP */
	PH_STOPPING,    /* STOP on the wire */
};

struct i2c_module {
	const struct i2c_instance *inst;
	struct hs_region *r;
	uint32_t *str, *imr, *mdr, *cnt, *sar, *drr, *clkl, *clkh, *psc, *dxr;
	enum phase phase;
	hs_event_t ev;
	bool dxr_full;              /* a byte waits in ICDXR */
	uint8_t shift;              /* the byte going out */
	uint8_t rx_pending;         /* received, not yet in ICDRR */
	uint32_t remaining;         /* bytes left of ICCNT's */
	bool repeat;                /* RM: no count */
	bool read;
	const struct slave *cur;    /* the addressed slave */
	unsigned lose;              /* address phases still to lose (hs_i2c_lose_arbitration) */
	struct hs_i2c_stats stats;
};

static struct i2c_module *modules[HS_I2C_BUSES];
static struct slave slaves[HS_I2C_BUSES][HS_I2C_MAX_SLAVES];
static unsigned pending_losses[HS_I2C_BUSES];

/* ---- slaves ---- */

ER hs_i2c_attach(unsigned bus, uint8_t addr, const struct hs_i2c_slave_ops *ops, void *ctx)
{
	unsigned i;

	if (bus >= HS_I2C_BUSES)
		return E_ID;
	if (addr == 0 || addr > 0x7F || !ops || !ops->start || !ops->write || !ops->read)
		return E_PAR;
	for (i = 0; i < HS_I2C_MAX_SLAVES; i++)
		if (slaves[bus][i].ops && slaves[bus][i].addr == addr)
			return E_OBJ;
	for (i = 0; i < HS_I2C_MAX_SLAVES; i++)
		if (!slaves[bus][i].ops) {
			slaves[bus][i] = (struct slave){ addr, ops, ctx };
			return E_OK;
		}
	return E_NOMEM;
}

void hs_i2c_detach(unsigned bus, uint8_t addr)
{
	unsigned i;

	for (i = 0; bus < HS_I2C_BUSES && i < HS_I2C_MAX_SLAVES; i++)
		if (slaves[bus][i].ops && slaves[bus][i].addr == addr) {
			if (modules[bus] && modules[bus]->cur == &slaves[bus][i])
				modules[bus]->cur = NULL;
			slaves[bus][i] = (struct slave){ 0 };
		}
}

static const struct slave *find_slave(unsigned bus, uint8_t addr)
{
	unsigned i;

	for (i = 0; i < HS_I2C_MAX_SLAVES; i++)
		if (slaves[bus][i].ops && slaves[bus][i].addr == addr)
			return &slaves[bus][i];
	return NULL;
}

static bool regfile_start(void *ctx, bool read)
{
	struct hs_i2c_regfile *f = ctx;

	f->pointer_next = !read;
	return true;
}

static bool regfile_write(void *ctx, uint8_t byte)
{
	struct hs_i2c_regfile *f = ctx;

	if (f->pointer_next) {
		f->pointer = byte;
		f->pointer_next = false;
	} else {
		f->regs[f->pointer++] = byte;
	}
	return true;
}

static uint8_t regfile_read(void *ctx)
{
	struct hs_i2c_regfile *f = ctx;

	return f->regs[f->pointer++];
}

const struct hs_i2c_slave_ops hs_i2c_regfile_ops = {
	.start = regfile_start, .write = regfile_write, .read = regfile_read,
};

void hs_i2c_lose_arbitration(unsigned bus, unsigned count)
{
	if (bus >= HS_I2C_BUSES)
		return;
	pending_losses[bus] = count;
	if (modules[bus])
		modules[bus]->lose = count;
}

struct hs_i2c_stats hs_i2c_get_stats(unsigned bus)
{
	return bus < HS_I2C_BUSES && modules[bus] ? modules[bus]->stats : (struct hs_i2c_stats){ 0 };
}

/* ---- the controller ---- */

static unsigned bus_of(const struct i2c_module *m)
{
	return (unsigned)(m->inst - i2c_instances);
}

/* Drives the interrupt line from ICSTR and ICIMR. */
static void irq_update(struct i2c_module *m)
{
	hs_intc_set_level(m->inst->intno, (*m->str & *m->imr & INT_FLAGS) != 0);
}

static void flag(struct i2c_module *m, uint32_t set, uint32_t clear)
{
	*m->str = (*m->str & ~clear) | set;
	irq_update(m);
}

/* One SCL period of the current clock settings (TRM: d = 7, 6, 5 for IPSC 0, 1, more). */
static uint64_t period_ns(struct i2c_module *m)
{
	uint32_t psc = *m->psc & 0xFFU;
	uint32_t d = psc == 0 ? 7U : psc == 1 ? 6U : 5U;
	uint64_t cycles = ((uint64_t)(*m->clkl & 0xFFFFU) + d + (*m->clkh & 0xFFFFU) + d) * (psc + 1U);
	uint64_t ns = cycles * 1000000000ULL / m->inst->clock_hz;

	m->stats.scl_period_ns = (uint32_t)ns;
	return ns;
}

static void after_periods(struct i2c_module *m, unsigned periods, rtos_host_event_fn fn)
{
	m->ev = hs_event_after(periods * period_ns(m), fn, m);
}

static void stop_done(void *arg)
{
	struct i2c_module *m = arg;

	m->ev = 0;
	*m->mdr &= ~(MDR_MST | MDR_STP);
	m->phase = PH_IDLE;
	m->stats.stops++;
	if (m->cur && m->cur->ops->stop)
		m->cur->ops->stop(m->cur->ctx);
	m->cur = NULL;
	flag(m, STR_SCD, STR_BB);
}

static void send_stop(struct i2c_module *m)
{
	m->phase = PH_STOPPING;
	after_periods(m, 1, stop_done);
}

/* The count is done: STOP if STP is set, else ARDY with the bus held. */
static void count_done(struct i2c_module *m)
{
	if (*m->mdr & MDR_STP) {
		send_stop(m);
	} else {
		m->phase = PH_HOLD;
		flag(m, STR_ARDY, 0);
	}
}

static void tx_done(void *arg);
static void rx_done(void *arg);

/* The next byte of the transfer, or the end of its count. */
static void next_byte(struct i2c_module *m)
{
	if (!m->repeat && m->remaining == 0) {
		count_done(m);
		return;
	}
	if (m->read) {
		m->phase = PH_RX;
		after_periods(m, 9, rx_done);
	} else if (m->dxr_full) {
		m->shift = (uint8_t)*m->dxr;
		m->dxr_full = false;
		m->phase = PH_TX;
		flag(m, STR_XRDY | STR_XSMT, 0);
		after_periods(m, 9, tx_done);
	} else {
		m->phase = PH_WAIT_TX;
		flag(m, STR_XRDY, STR_XSMT);     /* transmit underflow: SCL held low */
	}
}

static void tx_done(void *arg)
{
	struct i2c_module *m = arg;

	m->ev = 0;
	m->stats.bytes_written++;
	if (!m->cur || !m->cur->ops->write(m->cur->ctx, m->shift)) {
		m->stats.data_nacks++;
		m->phase = PH_NACKED;
		flag(m, STR_NACK, 0);
		if (*m->mdr & MDR_STP)
			send_stop(m);
		return;
	}
	if (!m->repeat)
		m->remaining--;
	next_byte(m);
}

/* Puts the received byte in ICDRR, or holds it while ICDRR is full. */
static void rx_deliver(struct i2c_module *m)
{
	if (*m->str & STR_RRDY) {
		m->phase = PH_WAIT_RX;
		return;
	}
	*m->drr = m->rx_pending;
	flag(m, STR_RRDY, 0);
	if (!m->repeat)
		m->remaining--;
	next_byte(m);
}

static void rx_done(void *arg)
{
	struct i2c_module *m = arg;

	m->ev = 0;
	m->rx_pending = m->cur ? m->cur->ops->read(m->cur->ctx) : 0xFF;
	m->stats.bytes_read++;
	rx_deliver(m);
}

static void address_done(void *arg)
{
	struct i2c_module *m = arg;
	const struct slave *s;

	m->ev = 0;
	if (m->lose > 0) {
		m->lose--;
		m->stats.arbitration_lost++;
		m->phase = PH_IDLE;
		m->cur = NULL;
		*m->mdr &= ~(MDR_MST | MDR_STP);
		flag(m, STR_AL, STR_BB);
		return;
	}
	s = find_slave(bus_of(m), (uint8_t)(*m->sar & 0x7FU));
	if (!s || !s->ops->start(s->ctx, m->read)) {
		m->stats.address_nacks++;
		m->cur = NULL;
		m->phase = PH_NACKED;
		flag(m, STR_NACK, 0);
		if (*m->mdr & MDR_STP)
			send_stop(m);
		return;
	}
	m->cur = s;
	next_byte(m);
}

/* STT: START (or a repeated START from ARDY), then the address. */
static void start_transfer(struct i2c_module *m)
{
	if (m->phase != PH_IDLE && m->phase != PH_HOLD) {
		rtos_host_trace(m->inst->name, "ICMDR.STT during a transfer: ignored");
		return;
	}
	if (m->phase == PH_HOLD)
		m->stats.repeated_starts++;
	else
		m->stats.starts++;
	*m->mdr &= ~MDR_STT;
	m->read = !(*m->mdr & MDR_TRX);
	m->repeat = (*m->mdr & MDR_RM) != 0;
	m->remaining = *m->cnt & 0xFFFFU;
	if (!m->repeat && m->remaining == 0)
		m->remaining = 65536;                /* TRM: ICCNT 0 means 65536 */
	m->phase = PH_ADDRESS;
	flag(m, STR_BB, STR_ARDY | STR_NACK | STR_SCD);
	after_periods(m, 10, address_done);     /* START, then the address byte with its ACK */
}

/* IRS = 0: the module in reset, the bus let go. */
static void module_reset(struct i2c_module *m)
{
	hs_event_cancel(&m->ev);
	m->phase = PH_IDLE;
	m->dxr_full = false;
	m->cur = NULL;
	*m->str = STR_RESET;
	irq_update(m);
}

static void write_mdr(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct i2c_module *m = ctx;

	if (!(nv & MDR_IRS)) {
		module_reset(m);
		return;
	}
	if ((nv & MDR_STT) && (nv & MDR_MST)) {
		start_transfer(m);
		return;
	}
	if ((nv & MDR_STP) && (m->phase == PH_HOLD || m->phase == PH_NACKED))
		send_stop(m);
}

static void write_dxr(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct i2c_module *m = ctx;

	m->dxr_full = true;
	flag(m, 0, STR_XRDY);
	if (m->phase == PH_WAIT_TX)
		next_byte(m);
}

/* The held byte moves into ICDRR just after the read that emptied it. */
static void rx_release(void *arg)
{
	struct i2c_module *m = arg;

	m->ev = 0;
	if (m->phase == PH_WAIT_RX)
		rx_deliver(m);
}

static void read_drr(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct i2c_module *m = ctx;

	flag(m, 0, STR_RRDY);
	if (m->phase == PH_WAIT_RX && !m->ev)
		m->ev = hs_event_after(1, rx_release, m);
}

/* ICIVR: the highest-priority enabled flag's code, cleared by the read
 * (ICRRDY and ICXRDY excepted). */
static void read_ivr(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct i2c_module *m = ctx;
	uint32_t pending = *m->str & *m->imr & INT_FLAGS;
	unsigned code;

	*value = 0;
	for (code = 1; code <= 7; code++) {
		uint32_t bit = 1U << (code - 1);

		if (pending & bit) {
			*value = code;
			if (bit != STR_RRDY && bit != STR_XRDY)
				flag(m, 0, bit);
			return;
		}
	}
}

static void write_str_or_imr(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	irq_update(ctx);
}

static const struct hs_reg i2c_regs[] = {
	{ .name = "ICOAR", .offset = ICOAR, .kind = HS_RW, .mask = 0x3FF },
	{ .name = "ICIMR", .offset = ICIMR, .kind = HS_RW, .mask = INT_FLAGS, .after_write = write_str_or_imr },
	{ .name = "ICSTR", .offset = ICSTR, .kind = HS_W1C, .mask = STR_W1C, .reset = STR_RESET,
	  .after_write = write_str_or_imr },
	{ .name = "ICCLKL", .offset = ICCLKL, .kind = HS_RW, .mask = 0xFFFF },
	{ .name = "ICCLKH", .offset = ICCLKH, .kind = HS_RW, .mask = 0xFFFF },
	{ .name = "ICCNT", .offset = ICCNT, .kind = HS_RW, .mask = 0xFFFF },
	{ .name = "ICDRR", .offset = ICDRR, .kind = HS_RO, .before_read = read_drr },
	{ .name = "ICSAR", .offset = ICSAR, .kind = HS_RW, .mask = 0x3FF, .reset = 0x3FF },
	{ .name = "ICDXR", .offset = ICDXR, .kind = HS_RW, .mask = 0xFF, .after_write = write_dxr },
	{ .name = "ICMDR", .offset = ICMDR, .kind = HS_RW, .mask = 0xFFFF, .after_write = write_mdr },
	{ .name = "ICIVR", .offset = ICIVR, .kind = HS_RO, .before_read = read_ivr },
	{ .name = "ICEMDR", .offset = ICEMDR, .kind = HS_RW, .mask = 0x3, .reset = 0x1 },
	{ .name = "ICPSC", .offset = ICPSC, .kind = HS_RW, .mask = 0xFF },
	{ .name = "REVID1", .offset = REVID1, .kind = HS_RO },   /* revision values not modelled: 0 */
	{ .name = "REVID2", .offset = REVID2, .kind = HS_RO },
	{ .name = "ICPFUNC", .offset = ICPFUNC, .kind = HS_RW, .count = 6, .stride = 4, .mask = 0x3 },
};

static ER i2c_create(unsigned bus, const struct hs_board_cfg *cfg, void **ctx)
{
	const struct i2c_instance *inst = &i2c_instances[bus];
	struct i2c_module *m = calloc(1, sizeof(*m));

	if (!m)
		return E_NOMEM;
	m->inst = inst;
	m->r = hs_region_add(&(struct hs_region_cfg){ .name = inst->name, .phys = inst->phys, .size = 0x1000,
		.regs = i2c_regs, .nregs = HS_ARRAY_SIZE(i2c_regs), .power = inst->power, .ctx = m });
	if (!m->r) {
		free(m);
		return E_PAR;
	}
	m->str = hs_reg_value_ptr(m->r, ICSTR);
	m->imr = hs_reg_value_ptr(m->r, ICIMR);
	m->mdr = hs_reg_value_ptr(m->r, ICMDR);
	m->cnt = hs_reg_value_ptr(m->r, ICCNT);
	m->sar = hs_reg_value_ptr(m->r, ICSAR);
	m->drr = hs_reg_value_ptr(m->r, ICDRR);
	m->dxr = hs_reg_value_ptr(m->r, ICDXR);
	m->clkl = hs_reg_value_ptr(m->r, ICCLKL);
	m->clkh = hs_reg_value_ptr(m->r, ICCLKH);
	m->psc = hs_reg_value_ptr(m->r, ICPSC);
	m->lose = pending_losses[bus];
	modules[bus] = m;
	*ctx = m;
	return E_OK;
}

static ER i2c0_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return i2c_create(0, cfg, ctx);
}

static ER i2c1_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return i2c_create(1, cfg, ctx);
}

/* Frees a controller and forgets its bus's slaves (they belong to the board that goes). */
static void i2c_destroy(void *ctx)
{
	struct i2c_module *m = ctx;
	unsigned bus = bus_of(m);

	hs_event_cancel(&m->ev);
	memset(slaves[bus], 0, sizeof(slaves[bus]));
	pending_losses[bus] = 0;
	modules[bus] = NULL;
	free(m);
}

const struct hs_device hs_i2c0_device = { "I2C0", i2c0_create, NULL, i2c_destroy };
const struct hs_device hs_i2c1_device = { "I2C1", i2c1_create, NULL, i2c_destroy };
