/*
 * spi.c — the AM1808's SPI0 and SPI1 masters, one model instantiated twice
 * (spi.h for the behaviour modelled): transfers in virtual time, answered
 * by whatever the board connects as each bus's slave (hs_spi_connect; on the
 * EV3 the converter on SPI0, ev3/adc.c, and the display controller on SPI1,
 * ev3/st7586.c).
 *
 * A frame nothing but its own registers can observe the end of (no interrupt
 * enabled, no word waiting behind it, no slave hook at its end: the ADC's
 * polled frames) is not an event: it is a deferred event (rtos_host.h),
 * completed when the CPU next looks at SPIBUF/SPIFLG/SPIEMU, writes a
 * register whose effect depends on it, the statistics are read or the
 * kernel checks for idle — with the same values, at the same virtual times,
 * as if its end had been an event.  (Only the model-side backdoor,
 * hs_reg_get on SPIFLG/SPIBUF, does not settle it; nothing reads SPI0's
 * registers that way.)
 */
#include <stdlib.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/devices/spi.h"

enum {
	SPIGCR0 = 0x00, SPIGCR1 = 0x04, SPIINT0 = 0x08, SPILVL = 0x0C, SPIFLG = 0x10,
	SPIPC0 = 0x14, SPIPC1 = 0x18, SPIPC2 = 0x1C, SPIPC3 = 0x20, SPIPC4 = 0x24, SPIPC5 = 0x28,
	SPIDAT0 = 0x38, SPIDAT1 = 0x3C, SPIBUF = 0x40, SPIEMU = 0x44, SPIDELAY = 0x48,
	SPIDEF = 0x4C, SPIFMT0 = 0x50, INTVEC0 = 0x60, INTVEC1 = 0x64,
};

#define BUF_RXEMPTY    (1U << 31)
#define BUF_RXOVR      (1U << 30)
#define BUF_TXFULL     (1U << 29)
#define FLG_OVRN       (1U << 6)
#define FLG_RXINT      (1U << 8)
#define FLG_TXINT      (1U << 9)
#define INT0_RXINTENA  (1U << 8)
#define INT0_OVRNINTENA (1U << 6)
#define FLG_WRITABLE   0x0000015FU  /* SPIFLG's write-1-to-clear bits */
#define DAT0_MASK      0x0000FFFFU  /* SPIDAT0's data bits */

/* What differs between SPI0 and SPI1 (AM1808 TRM, memory map, PSC and AINTC chapters). */
struct spi_instance {
	const char *name;
	uint32_t phys;
	unsigned power;             /* HS_PSC0_MODULE / HS_PSC1_MODULE */
	unsigned intno;
	uint32_t clock_hz;          /* module clock: PLL0_SYSCLK2 (SPI0), ASYNC3 (SPI1) */
};

static const struct spi_instance spi_instances[HS_SPI_BUSES] = {
	{ "SPI0", HS_SPI0_BASE, HS_PSC0_MODULE(HS_LPSC0_SPI0), EV3_SPI0_INTNO, HS_PLL0_SYSCLK2_HZ },
	{ "SPI1", HS_SPI1_BASE, HS_PSC1_MODULE(HS_LPSC1_SPI1), HS_SPI1_INTNO, HS_PLL1_SYSCLK2_HZ },
};

struct spi_module {
	const struct spi_instance *inst;
	struct hs_spi_peer slave;   /* what answers the frames (none: the line reads 0) */
	uint16_t word;              /* the word in flight, for the slave's frame_done */
	struct hs_region *r;
	/* stored values of the registers every frame consults (hs_reg_value_ptr) */
	uint32_t *gcr0, *gcr1, *int0, *flg, *dat1, *delay, *fmt[4];
	/* the frame timing of the last format and delay seen (frame_ns depends on nothing else) */
	bool timing_known;
	uint32_t timing_fmt, timing_delay;
	uint64_t timing_ns;
	uint16_t timing_mask;       /* the data bits of a word of that format */
	/* A word written now starts a frame with a deferred end, timed as
	 * timing_ns/timing_mask: the module is out of reset, enabled and
	 * master, no interrupt is enabled, the slave has no hook at frame ends,
	 * ends are deferred, and the timing is that of the selected format and
	 * delay (polled_update redoes it whenever one of these may change). */
	bool polled;
	bool busy, tx_full;
	uint16_t tx_buf;            /* word waiting in the TX buffer */
	unsigned tx_buf_fmt;
	uint16_t shift_out;         /* what the slave shifts back in this frame, cut to its length */
	uint64_t frame_end;
	hs_event_t frame_ev;
	struct rtos_host_deferred frame_deferred;   /* armed: the frame's end is deferred */
	uint32_t rx;                /* SPIBUF data and flags */
	bool irq;
	struct ev3_spi_stats stats;
};

static struct spi_module *spis[HS_SPI_BUSES];
/* Slaves connected before their master exists (board models may be created in any order). */
static struct hs_spi_peer pending[HS_SPI_BUSES];

/* Whether private frame ends are deferred (hs_spi_defer_private_ends). */
static bool defer_private_ends = true;

static void frame_settle(struct spi_module *s);
static void frame_settle_or_queue(struct spi_module *s);
static void polled_update(struct spi_module *s);

void hs_spi_connect(unsigned bus, const struct hs_spi_peer *peer)
{
	if (bus >= HS_SPI_BUSES)
		return;
	pending[bus] = peer != NULL ? *peer : (struct hs_spi_peer){ 0 };
	if (spis[bus]) {
		frame_settle(spis[bus]);            /* a frame that ended did so with the old slave */
		spis[bus]->slave = pending[bus];
		frame_settle_or_queue(spis[bus]);   /* the new slave may act at the frame's end */
		polled_update(spis[bus]);
	}
}

uint32_t hs_spi_format(unsigned bus)
{
	struct spi_module *s = bus < HS_SPI_BUSES ? spis[bus] : NULL;

	return s ? *s->fmt[(*s->dat1 >> 24) & 3U] : 0;
}

/* Drives the module's interrupt line from SPIFLG and SPIINT0. */
static inline void spi_irq_update(struct spi_module *s)
{
	uint32_t flg, ena = *s->int0;
	bool level;

	if (!s->irq && !(ena & (INT0_RXINTENA | INT0_OVRNINTENA)))
		return;                 /* low and nothing enabled that could raise it: polled use */
	flg = *s->flg;
	level = ((flg & FLG_RXINT) && (ena & INT0_RXINTENA)) || ((flg & FLG_OVRN) && (ena & INT0_OVRNINTENA));
	if (level != s->irq) {
		s->irq = level;
		hs_intc_set_level(s->inst->intno, level);
	}
}

/* Frame length in ns for a data format, and the data bits of its words in *mask. */
static uint64_t frame_ns(struct spi_module *s, unsigned fmt, uint16_t *mask)
{
	uint32_t f = *s->fmt[fmt];
	uint32_t delay = *s->delay;
	unsigned charlen = f & 0x1FU, prescale = (f >> 8) & 0xFFU;
	uint64_t cs_cycles;

	if (s->timing_known && f == s->timing_fmt && delay == s->timing_delay) {
		*mask = s->timing_mask;
		return s->timing_ns;
	}
	/* chip-select setup (C2TDELAY) and hold (T2CDELAY) in module clocks */
	cs_cycles = ((delay >> 24) & 0xFFU) + ((delay >> 16) & 0xFFU) + 2U;
	if (charlen < 2)
		charlen = 16;
	s->timing_known = true;
	s->timing_fmt = f;
	s->timing_delay = delay;
	s->timing_mask = charlen >= 16 ? 0xFFFFU : (uint16_t)((1U << charlen) - 1U);
	s->timing_ns = hs_cycles_to_ns((uint64_t)charlen * (prescale + 1U) + cs_cycles, s->inst->clock_hz);
	*mask = s->timing_mask;
	return s->timing_ns;
}

/* Sets and clears SPIFLG bits (hs_reg_update on the stored value; SPIFLG is 32 bits wide). */
static void flg_update(struct spi_module *s, uint32_t clear, uint32_t set)
{
	*s->flg = (*s->flg & ~clear) | set;
}

static void frame_start(struct spi_module *s, uint16_t word, unsigned fmt);

/* The answer of the frame ending now goes to SPIBUF (an overrun if the last
 * one was not read) and SPIFLG. */
static inline void frame_shift_in(struct spi_module *s)
{
	if (!(s->rx & BUF_RXEMPTY)) {
		s->rx |= BUF_RXOVR;
		s->stats.rx_overruns++;
		flg_update(s, 0, FLG_OVRN);
	}
	s->rx = (s->rx & BUF_RXOVR) | s->shift_out;
	flg_update(s, 0, FLG_RXINT | FLG_TXINT);
}

/* Event: a frame ends; SPIBUF gets the answer. */
static void frame_done(void *arg)
{
	struct spi_module *s = arg;

	s->frame_ev = 0;
	rtos_host_deferred_disarm(&s->frame_deferred);
	s->busy = false;
	s->stats.transfers++;
	if (s->slave.frame_done != NULL)
		s->slave.frame_done(s->slave.ctx, s->word);
	frame_shift_in(s);
	if (s->tx_full) {
		s->tx_full = false;
		frame_start(s, s->tx_buf, s->tx_buf_fmt);
		polled_update(s);       /* the waiting word's format may not be the selected one */
	}
	spi_irq_update(s);
}

/* True if a frame's end is seen by nothing but the module's registers when
 * no word waits behind it: no interrupt it could raise is enabled, the slave
 * has nothing to do at its end. */
static bool ends_unseen(const struct spi_module *s)
{
	return !(*s->int0 & (INT0_RXINTENA | INT0_OVRNINTENA)) && s->slave.frame_done == NULL;
}

/* True if the end of the frame in flight can change nothing but the module's
 * own registers and statistics (ends_unseen, and no word waits to start after it). */
static bool frame_end_private(const struct spi_module *s)
{
	return ends_unseen(s) && !s->tx_full;
}

/* True if the module may transfer: out of reset, enabled, master (SPIGCR0/1). */
static bool module_ready(const struct spi_module *s)
{
	uint32_t gcr1 = *s->gcr1;

	return (*s->gcr0 & 1U) && (gcr1 & (1U << 24)) && (gcr1 & 3U) == 3U;
}

/* Redoes s->polled (see struct spi_module) and the timing it relies on. */
static void polled_update(struct spi_module *s)
{
	uint16_t mask;

	s->polled = defer_private_ends && module_ready(s) && ends_unseen(s);
	if (s->polled)
		frame_ns(s, (*s->dat1 >> 24) & 3U, &mask);
}

/* frame_done for a deferred frame: its end stayed private since it started
 * (whatever could change that queues it), so there is no word waiting, no
 * slave hook, no event handle, and the interrupt line stays low (no
 * interrupt enabled: the last SPIINT0 write left it low). */
static inline void frame_done_private(struct spi_module *s)
{
	rtos_host_deferred_disarm(&s->frame_deferred);
	s->busy = false;
	s->stats.transfers++;
	frame_shift_in(s);
}

/* Completes a deferred frame whose end has passed (its event would have run). */
static inline void frame_settle(struct spi_module *s)
{
	if (s->frame_deferred.armed && rtos_host_deferred_due(&s->frame_deferred))
		frame_done_private(s);
}

/* Settles a deferred frame, then queues it as an event if it is still in
 * flight and its end is no longer private (it must happen at its time). */
static void frame_settle_or_queue(struct spi_module *s)
{
	frame_settle(s);
	if (s->frame_deferred.armed && !frame_end_private(s))
		s->frame_ev = rtos_host_deferred_queue(&s->frame_deferred);
}

/* The kernel's settle callback (its idle check): complete or queue. */
static void frame_settle_for_kernel(void *arg)
{
	struct spi_module *s = arg;

	frame_settle(s);
	if (s->frame_deferred.armed)
		s->frame_ev = rtos_host_deferred_queue(&s->frame_deferred);
}

/* Starts a frame now with the slave answering (mask: the word's data bits);
 * its end (frame_end) is left to the caller. */
static inline void frame_begin(struct spi_module *s, uint16_t word, uint16_t mask)
{
	uint16_t out;

	s->busy = true;
	s->word = word;
	out = s->slave.frame != NULL ? s->slave.frame(s->slave.ctx, word) : 0;
	s->shift_out = out & mask;
}

/* Defers the end of the frame just begun (it is private) to ns from now;
 * frame_deferred is bound to frame_done once (spi_create). */
static inline void frame_defer_end(struct spi_module *s, uint64_t ns)
{
	s->stats.deferred_ends++;
	s->frame_end = rtos_host_deferred_arm_in(&s->frame_deferred, ns);
}

/* Starts a frame now with the slave answering; its end is an event, or
 * deferred when private. */
static void frame_start(struct spi_module *s, uint16_t word, unsigned fmt)
{
	uint16_t mask;
	uint64_t ns = frame_ns(s, fmt, &mask);

	frame_begin(s, word, mask);
	if (defer_private_ends && frame_end_private(s)) {
		frame_defer_end(s, ns);
	} else {
		s->frame_end = hs_now() + ns;
		s->frame_ev = hs_event_at(s->frame_end, frame_done, s);
	}
}

/* A word written to SPIDAT0/1: transfer now, or park it in the TX buffer. */
static void spi_send(struct spi_module *s, uint16_t word)
{
	uint32_t gcr1 = *s->gcr1;
	unsigned fmt = (*s->dat1 >> 24) & 3U;

	if (!module_ready(s)) {
		rtos_host_bug("host_sim", "%s: word 0x%04x written with the module %s: no transfer",
			      s->inst->name, word, !(hs_reg_get(s->r, SPIGCR0) & 1U) ? "in reset (SPIGCR0.RESET=0)" :
			      !(gcr1 & (1U << 24)) ? "disabled (SPIGCR1.ENABLE=0)" :
			      "not master (SPIGCR1.MASTER/CLKMOD)");
		return;
	}
	if (s->busy)                /* an armed frame is busy */
		frame_settle(s);
	flg_update(s, FLG_TXINT, 0);
	if (!s->busy) {
		frame_start(s, word, fmt);
	} else if (!s->tx_full) {
		s->tx_full = true;
		s->tx_buf = word;
		s->tx_buf_fmt = fmt;
		frame_settle_or_queue(s);   /* the waiting word starts at the frame's end */
	} else {
		rtos_host_trace(s->inst->name, "word 0x%04x overwrites the full TX buffer", word);
		s->tx_buf = word;
	}
}

/* A word written to SPIDAT0 starts a transfer; when polled and idle
 * (d_analog's every frame) without spi_send's checks, which polled_update
 * made beforehand.  Inline in both of SPIDAT0's write paths. */
static inline __attribute__((always_inline)) void dat0_send(struct spi_module *s, uint16_t word)
{
	/* SPIDAT0 and SPIDAT1 share the data half (SPIDAT1 is 32 bits wide) */
	*s->dat1 = (*s->dat1 & ~0xFFFFU) | word;
	if (s->polled && !s->busy) {
		flg_update(s, FLG_TXINT, 0);
		frame_begin(s, word, s->timing_mask);
		frame_defer_end(s, s->timing_ns);
		return;
	}
	spi_send(s, word);
}

/* SPIDAT0 writes: dat0_send. */
static void write_dat0(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	dat0_send(ctx, (uint16_t)(nv & DAT0_MASK));
}

/* write_dat0 as SPIDAT0's direct write (regs.h): the store of the data half, then dat0_send. */
static void write_dat0_direct(const struct rtos_host_mmio_route *rt, uint32_t data)
{
	const struct hs_direct *d = hs_direct_of(rt);

	*d->value = (*d->value & ~DAT0_MASK) | (data & DAT0_MASK);
	dat0_send(d->ctx, (uint16_t)data);
}

/* SPIDAT1 writes (its format select may change) start a transfer. */
static void write_dat1(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct spi_module *s = ctx;

	polled_update(s);
	if (a->width == 1)
		return;                 /* a byte write to the control half does not start a transfer */
	/* Before SPIGCR1.ENABLE is set a write only latches the fields (CSHOLD,
	 * WDEL, DFSEL, CSNR): the AM1808 TRM's SPI initialization procedure
	 * configures SPIDAT1 and sets ENABLE last, and with ENABLE=0 the SPI "is
	 * not activated for transfers" (SPIGCR1 field description).  LEGO's
	 * d_analog selects its data format that way. */
	if ((*s->gcr0 & 1U) && !(*s->gcr1 & (1U << 24))) {
		rtos_host_trace(s->inst->name, "SPIDAT1 = 0x%08x with SPIGCR1.ENABLE=0: fields latched, no transfer",
				(unsigned)nv);
		return;
	}
	spi_send(s, (uint16_t)(nv & 0xFFFFU));
}

/* SPIGCR1, SPIFMTn and SPIDELAY writes: polled_update. */
static void write_setup(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	polled_update(ctx);
}

/* SPIBUF contents with the TXFULL flag. */
static uint32_t buf_value(const struct spi_module *s)
{
	return s->rx | (s->tx_full ? BUF_TXFULL : 0U);
}

/* The interrupt line after SPIBUF was read with the module not polled; v,
 * the value read, back (out of line: buf_take then keeps nothing across a call). */
static __attribute__((noinline)) uint32_t buf_taken_unpolled(struct spi_module *s, uint32_t v)
{
	spi_irq_update(s);
	return v;
}

/* SPIBUF read of the frame's answer: the value with TXFULL, then consumed;
 * the value read, also left in *value. */
static inline uint32_t buf_take(struct spi_module *s, uint32_t *value)
{
	uint32_t rx = s->rx;        /* read once: *value may alias it as far as the compiler knows */
	uint32_t v = rx | (s->tx_full ? BUF_TXFULL : 0U);

	*value = v;
	s->rx = (rx | BUF_RXEMPTY) & ~BUF_RXOVR;
	flg_update(s, FLG_RXINT, 0);
	if (!s->polled)             /* polled: no interrupt enabled, the line stays low */
		return buf_taken_unpolled(s, v);
	return v;
}

/* frame_done_private then buf_take, for a read of SPIBUF, empty, as the
 * deferred frame ends: the answer is shifted in and taken at once (no
 * overrun; no word waits behind a deferred frame), so SPIFLG keeps TXINT
 * but not RXINT.  One update of SPIBUF and of SPIFLG instead of two each.
 * The value read, also left in *value. */
static inline uint32_t frame_done_private_taken(struct spi_module *s, uint32_t *value)
{
	uint32_t in = s->shift_out;

	rtos_host_deferred_disarm(&s->frame_deferred);
	s->busy = false;
	s->stats.transfers++;
	*value = in;
	s->rx = BUF_RXEMPTY | in;
	flg_update(s, FLG_RXINT, FLG_TXINT);
	if (!s->polled)
		return buf_taken_unpolled(s, in);
	return in;
}

/* read_buf while a frame is busy: settle it, stall until its end if the poll
 * would see "not yet", then consume; the value read, also left in *value.
 * Out of line: the idle read, one of d_analog's two per frame, then needs no
 * registers saved. */
static __attribute__((noinline)) uint32_t read_buf_busy(struct spi_module *s, uint32_t *value)
{
	frame_settle(s);
	/* a poll that would see "not yet": the CPU spins until the frame ends */
	if (s->busy && ((s->rx & BUF_RXEMPTY) || s->tx_full)) {
		s->stats.stalls++;
		if (!s->frame_deferred.armed) {
			hs_access_stall_until(s->frame_end);
		} else {
			rtos_host_deferred_wait(&s->frame_deferred);   /* hs_access_stall_until, inline */
			/* d_analog's every frame: still deferred (nothing looked meanwhile), and due */
			if (s->frame_deferred.armed && (s->rx & BUF_RXEMPTY) &&
			    rtos_host_deferred_due(&s->frame_deferred))
				return frame_done_private_taken(s, value);
		}
		frame_settle(s);
	}
	return buf_take(s, value);
}

/* SPIBUF read: stall while in flight, then consume. */
static void read_buf(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct spi_module *s = ctx;

	if (s->busy)                /* an armed frame is busy */
		read_buf_busy(s, value);
	else
		buf_take(s, value);
}

/* read_buf as SPIBUF's direct read (regs.h): d_analog's two polls per frame. */
static uint32_t read_buf_direct(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);
	struct spi_module *s = d->ctx;

	if (s->busy)
		return read_buf_busy(s, d->value);
	return buf_take(s, d->value);
}

/* SPIEMU read: SPIBUF without side effects. */
static void read_emu(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct spi_module *s = ctx;

	frame_settle(s);
	*value = buf_value(s) & 0xFFFFU;
}

/* SPIFLG read: TXINTFLG from the TX buffer. */
static void read_flg(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct spi_module *s = ctx;

	frame_settle(s);
	*value = (*value & ~FLG_TXINT) | (s->tx_full ? 0U : FLG_TXINT);
}

/* SPIFLG write-1-to-clear: re-evaluates the interrupt.  A deferred frame
 * that ended before the write sets its flags now, so they are cleared again
 * as the write would have cleared them. */
static void write_flg(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct spi_module *s = ctx;

	if (s->frame_deferred.armed && rtos_host_deferred_due(&s->frame_deferred)) {
		frame_done_private(s);
		flg_update(s, written & FLG_WRITABLE, 0);
	}
	spi_irq_update(s);
}

/* SPIGCR0: RESET = 0 resets the module. */
static void write_gcr0(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct spi_module *s = ctx;

	if (!(nv & 1U)) {           /* reset: abort, registers to reset values */
		frame_settle(s);
		rtos_host_deferred_disarm(&s->frame_deferred);
		hs_event_cancel(&s->frame_ev);
		s->busy = s->tx_full = false;
		s->rx = BUF_RXEMPTY;
		hs_region_reset(s->r);
		spi_irq_update(s);
	}
	polled_update(s);
}

/* SPIINT0 write: re-evaluates the interrupt; a frame in flight whose end
 * may now raise it becomes an event. */
static void write_int0(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct spi_module *s = ctx;

	frame_settle_or_queue(s);
	spi_irq_update(s);
	polled_update(s);
}

static const struct hs_reg spi_regs[] = {
	{ .name = "SPIGCR0", .offset = SPIGCR0, .kind = HS_RW, .mask = 0x1, .after_write = write_gcr0 },
	{ .name = "SPIGCR1", .offset = SPIGCR1, .kind = HS_RW, .mask = 0x01010303, .after_write = write_setup },
	{ .name = "SPIINT0", .offset = SPIINT0, .kind = HS_RW, .mask = 0x0101035F, .after_write = write_int0 },
	{ .name = "SPILVL", .offset = SPILVL, .kind = HS_RW, .mask = 0x0000035F },
	{ .name = "SPIFLG", .offset = SPIFLG, .kind = HS_W1C, .mask = FLG_WRITABLE,
	  .before_read = read_flg, .after_write = write_flg },
	{ .name = "SPIPC", .offset = SPIPC0, .kind = HS_RW, .count = 6, .stride = 4, .mask = 0x01010F3F },
	{ .name = "SPIDAT0", .offset = SPIDAT0, .widths = HS_W16 | HS_W32, .kind = HS_RW, .mask = DAT0_MASK,
	  .after_write = write_dat0, .write_direct = write_dat0_direct },
	{ .name = "SPIDAT1", .offset = SPIDAT1, .widths = HS_W8 | HS_W16 | HS_W32, .kind = HS_RW,
	  .mask = 0x17FFFFFF, .after_write = write_dat1 },
	{ .name = "SPIBUF", .offset = SPIBUF, .widths = HS_W16 | HS_W32, .kind = HS_RO,
	  .reset = BUF_RXEMPTY, .before_read = read_buf, .read_direct = read_buf_direct },
	{ .name = "SPIEMU", .offset = SPIEMU, .kind = HS_RO, .before_read = read_emu },
	{ .name = "SPIDELAY", .offset = SPIDELAY, .kind = HS_RW, .after_write = write_setup },
	{ .name = "SPIDEF", .offset = SPIDEF, .kind = HS_RW, .mask = 0xFF, .reset = 0xFF },
	{ .name = "SPIFMT", .offset = SPIFMT0, .kind = HS_RW, .count = 4, .stride = 4, .mask = 0x3F7FFF1F,
	  .after_write = write_setup },
	{ .name = "INTVEC0", .offset = INTVEC0, .kind = HS_RO },
	{ .name = "INTVEC1", .offset = INTVEC1, .kind = HS_RO },
};

/* Creates one SPI module's region. */
static ER spi_create(unsigned bus, const struct hs_board_cfg *cfg, void **ctx)
{
	const struct spi_instance *inst = &spi_instances[bus];
	struct spi_module *s = calloc(1, sizeof(*s));

	if (!s)
		return E_NOMEM;
	s->inst = inst;
	s->r = hs_region_add(&(struct hs_region_cfg){ .name = inst->name, .phys = inst->phys, .size = 0x1000,
		.regs = spi_regs, .nregs = HS_ARRAY_SIZE(spi_regs), .power = inst->power, .ctx = s });
	if (!s->r) {
		free(s);
		return E_PAR;
	}
	s->gcr0 = hs_reg_value_ptr(s->r, SPIGCR0);
	s->gcr1 = hs_reg_value_ptr(s->r, SPIGCR1);
	s->int0 = hs_reg_value_ptr(s->r, SPIINT0);
	s->flg = hs_reg_value_ptr(s->r, SPIFLG);
	s->dat1 = hs_reg_value_ptr(s->r, SPIDAT1);
	s->delay = hs_reg_value_ptr(s->r, SPIDELAY);
	for (unsigned i = 0; i < 4U; i++)
		s->fmt[i] = hs_reg_value_ptr(s->r, SPIFMT0 + 4U * i);
	s->rx = BUF_RXEMPTY;
	rtos_host_deferred_bind(&s->frame_deferred, frame_done, frame_settle_for_kernel, s);
	/* Linux's SPI master leaves the module out of reset (EV3RT's driver had to take SPI0 out itself) */
	if (!cfg || !cfg->cold_reset)
		hs_reg_set(s->r, SPIGCR0, 1);
	s->slave = pending[bus];
	polled_update(s);
	spis[bus] = s;
	*ctx = s;
	return E_OK;
}

static ER spi0_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return spi_create(0, cfg, ctx);
}

static ER spi1_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return spi_create(1, cfg, ctx);
}

/* Frees a module. */
static void spi_destroy(void *ctx)
{
	struct spi_module *s = ctx;

	rtos_host_deferred_disarm(&s->frame_deferred);
	hs_event_cancel(&s->frame_ev);
	for (unsigned bus = 0; bus < HS_SPI_BUSES; bus++)
		if (spis[bus] == s)
			spis[bus] = NULL;
	free(s);
}

const struct hs_device hs_spi0_device = { "SPI0", spi0_create, NULL, spi_destroy };
const struct hs_device hs_spi1_device = { "SPI1", spi1_create, NULL, spi_destroy };

const struct ev3_spi_stats *hs_spi_stats(unsigned bus)
{
	static const struct ev3_spi_stats none;
	struct spi_module *s = bus < HS_SPI_BUSES ? spis[bus] : NULL;

	if (s)
		frame_settle(s);
	return s ? &s->stats : &none;
}

void hs_spi_defer_private_ends(bool on)
{
	defer_private_ends = on;
	for (unsigned bus = 0; bus < HS_SPI_BUSES; bus++)
		if (spis[bus])
			polled_update(spis[bus]);
}

const struct ev3_spi_stats *ev3_spi_get_stats(void)
{
	return hs_spi_stats(0);
}
