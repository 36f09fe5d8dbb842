/*
 * uart16550.c — AM1808 UART (TRM "Universal Asynchronous Receiver/
 * Transmitter"), 16550-compatible.  Bytes are events on the virtual clock;
 * everything else is computed when read.
 */
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/trace.h"
#include "host_sim/devices/uart16550.h"

enum {
	RBR = 0x00, IER = 0x04, IIR = 0x08, LCR = 0x0C, MCR = 0x10, LSR = 0x14, MSR = 0x18,
	SCR = 0x1C, DLL = 0x20, DLH = 0x24, REVID1 = 0x28, REVID2 = 0x2C, PWREMU = 0x30, MDR = 0x34,
};

#define IER_ERBI   0x01U
#define IER_ETBEI  0x02U
#define IER_ELSI   0x04U
#define LCR_BC     0x40U
#define LCR_DLAB   0x80U
#define MCR_LOOP   0x10U
#define LSR_DR     0x01U
#define LSR_OE     0x02U
#define LSR_PE     0x04U
#define LSR_FE     0x08U
#define LSR_BI     0x10U
#define LSR_THRE   0x20U
#define LSR_TEMT   0x40U
#define LSR_RXFIFOE 0x80U
#define PWREMU_URRST (1U << 13)
#define PWREMU_UTRST (1U << 14)
#define FIFO_SIZE  16U

struct hs_uart {
	const struct hs_uart_cfg *cfg;
	struct hs_region *r;
	uint8_t fcr;                /* FCR is write-only: its state lives here */
	/* copies of the registers the byte path consults, kept by the write hooks */
	uint32_t lcr, mcr, ier, dll, dlh, mdr, pwremu;
	/* derived from lcr, dll, dlh, mdr by timing_update: the byte path reads them per byte */
	uint32_t baud, baud_lo, baud_hi;    /* baud, and the +-4 % a received byte may differ by */
	uint64_t char_ns, timeout_ns;       /* one character, and the 4-character timeout */
	uint64_t last_rx_activity;  /* for the character timeout */
	uint8_t rx[FIFO_SIZE], rx_err[FIFO_SIZE];
	unsigned rx_head, rx_count;
	unsigned rx_errs;           /* FIFO entries whose error bits LSR has not reported */
	uint8_t tx[FIFO_SIZE];
	unsigned tx_head, tx_count;
	bool tsr_busy;
	uint8_t tsr;
	hs_event_t tx_ev, timeout_ev, break_ev;
	bool thre_int;              /* THRE interrupt source pending */
	bool timeout_int;           /* character timeout pending */
	bool timeout_deferred;      /* timeout due since the last RX activity but not armed (timeout_defer) */
	bool overrun;               /* OE until LSR is read */
	bool line_high;
	bool break_sent;
	bool irq;
	unsigned iir;               /* iir_id() as of the last irq_update */
	bool irq_stale;             /* a source changed without irq_update (THRE from a divisor write) */
	struct hs_uart_peer peer;
	struct hs_uart_stats stats;
};


/* ---- helpers ---- */

static bool fifo_mode(const struct hs_uart *u)
{
	return u->fcr & 1U;
}

/* RX FIFO depth in the current mode. */
static unsigned rx_capacity(const struct hs_uart *u)
{
	return fifo_mode(u) ? FIFO_SIZE : 1U;
}

/* RX trigger level. */
static unsigned rx_trigger(const struct hs_uart *u)
{
	static const unsigned levels[4] = { 1, 4, 8, 14 };

	return fifo_mode(u) ? levels[(u->fcr >> 6) & 3U] : 1U;
}

/* Baud divisor (DLH:DLL). */
static uint32_t divisor(const struct hs_uart *u)
{
	return u->dll | (u->dlh << 8);
}

/* 16x or 13x per MDR. */
static unsigned oversampling(const struct hs_uart *u)
{
	return (u->mdr & 1U) ? 13U : 16U;
}

/*
 * Half bit times per character: start, data, parity, stop.  LCR.STB asks for
 * 2 stop bits, 1.5 with 5-bit words (AM1808 TRM, UART Line Control Register,
 * STB: "WLS = 0: 1.5 STOP bits; WLS = 1h-3h: 2 STOP bits"), hence halves.
 */
static unsigned char_half_bits(const struct hs_uart *u)
{
	uint32_t lcr = u->lcr;
	unsigned data = 5U + (lcr & 3U);
	unsigned stop_halves = !(lcr & 0x04U) ? 2U : data == 5U ? 3U : 4U;

	return 2U * (1U + data + ((lcr & 0x08U) ? 1U : 0U)) + stop_halves;
}

/* Nanoseconds of n half bit times at the current divisor (0 if no clock). */
static uint64_t half_bits_ns(const struct hs_uart *u, unsigned n)
{
	uint32_t div = divisor(u);

	return div ? hs_cycles_to_ns((uint64_t)n * oversampling(u) * div, 2U * (uint64_t)u->cfg->clock_hz) : 0;
}

/* Current baud. */
uint32_t hs_uart_baud(const struct hs_uart *u)
{
	return u->baud;
}

/* Recomputes what the byte path derives from LCR, DLL, DLH and MDR; called whenever one changes. */
static void timing_update(struct hs_uart *u)
{
	uint32_t div = divisor(u);

	u->baud = div ? (uint32_t)((u->cfg->clock_hz + (uint64_t)oversampling(u) * div / 2U) /
				   ((uint64_t)oversampling(u) * div)) : 0U;
	u->baud_lo = u->baud - u->baud / 25U;
	u->baud_hi = u->baud + u->baud / 25U;
	u->char_ns = half_bits_ns(u, char_half_bits(u));
	u->timeout_ns = half_bits_ns(u, 4U * char_half_bits(u));
}

/* Receiver out of reset. */
static bool rx_enabled(const struct hs_uart *u)
{
	return u->pwremu & PWREMU_URRST;
}

/* Transmitter out of reset. */
static bool tx_enabled(const struct hs_uart *u)
{
	return u->pwremu & PWREMU_UTRST;
}

/* The interrupt identification now (IIR bits 3:0). */
static unsigned iir_id(const struct hs_uart *u)
{
	uint32_t ier = u->ier;
	bool rx_error = u->overrun || (u->rx_count && u->rx_err[u->rx_head]);

	if ((ier & IER_ELSI) && rx_error)
		return HS_UART_IIR_LINE_STATUS;
	if ((ier & IER_ERBI) && u->rx_count >= rx_trigger(u))
		return HS_UART_IIR_RX_DATA;
	if ((ier & IER_ERBI) && u->timeout_int && u->rx_count)
		return HS_UART_IIR_RX_TIMEOUT;
	if ((ier & IER_ETBEI) && u->thre_int)
		return HS_UART_IIR_THR_EMPTY;
	return HS_UART_IIR_NONE;
}

/* Drives the interrupt request line from the current sources. */
static void irq_update(struct hs_uart *u)
{
	bool level;

	u->iir = iir_id(u);
	level = u->iir != HS_UART_IIR_NONE;
	u->irq_stale = false;
	if (level != u->irq) {
		u->irq = level;
		hs_intc_set_level(u->cfg->intno, level);
	}
}

/* ---- receiver ---- */

/* Event: the character timeout may be due; activity since it was armed
 * moves it instead of cancelling and re-scheduling on every byte. */
static void timeout_due(void *arg)
{
	struct hs_uart *u = arg;
	uint64_t due = u->last_rx_activity + u->timeout_ns;

	u->timeout_ev = 0;
	if (!fifo_mode(u) || !u->rx_count || !(u->ier & IER_ERBI))
		return;
	if (hs_now() < due) {
		u->timeout_ev = hs_event_at(due, timeout_due, u);
		return;
	}
	u->timeout_int = true;
	irq_update(u);
}

/* Notes RX activity (a byte in or out of the FIFO) for the character timeout.
 * While the FIFO holds the trigger level the data interrupt outranks the
 * timeout and only reading (activity again, which restarts the timeout)
 * brings the FIFO below it, so the timer is not armed then: with the
 * drivers' trigger level of 1 that is every byte.  Only a change of the
 * trigger level or the character time could expose it; those settle it
 * first (timeout_settle). */
static void rx_activity(struct hs_uart *u)
{
	u->last_rx_activity = hs_now();
	u->timeout_int = false;
	u->timeout_deferred = false;
	if (u->timeout_ev || !fifo_mode(u) || !u->rx_count || !(u->ier & IER_ERBI))
		return;
	if (u->rx_count >= rx_trigger(u))
		u->timeout_deferred = true;
	else
		u->timeout_ev = hs_event_at(u->last_rx_activity + u->timeout_ns, timeout_due, u);
}

/* Before FCR or the character time changes: a deferred timeout becomes what
 * the armed timer would have made of it by now (set, or still to come). */
static void timeout_settle(struct hs_uart *u)
{
	uint64_t due = u->last_rx_activity + u->timeout_ns;

	if (!u->timeout_deferred)
		return;
	u->timeout_deferred = false;
	if (hs_now() > due)
		u->timeout_int = true;
	else
		u->timeout_ev = hs_event_at(due, timeout_due, u);
}

/* A received character enters the FIFO, or overruns. */
static void rx_push(struct hs_uart *u, uint8_t byte, uint8_t err)
{
	if (!rx_enabled(u)) {
		u->stats.rx_in_reset++;
		return;
	}
	if (u->rx_count >= rx_capacity(u)) {
		u->overrun = true;
		u->stats.overruns++;
		rtos_host_trace(u->cfg->name, "overrun: byte 0x%02x lost (RX FIFO full)", byte);
	} else {
		unsigned i = (u->rx_head + u->rx_count) % FIFO_SIZE;

		u->rx[i] = byte;
		u->rx_err[i] = err;
		u->rx_errs += err != 0;
		u->rx_count++;
		u->stats.rx_bytes++;
	}
	rx_activity(u);
	irq_update(u);
}

/* A byte from the line at the sender's baud. */
void hs_uart_rx_byte(struct hs_uart *u, uint8_t byte, uint32_t baud)
{
	uint32_t mine;

	if (!u || (u->mcr & MCR_LOOP))
		return;
	mine = u->baud;
	if (!mine || baud < u->baud_lo || baud > u->baud_hi) {
		/* sampled at the wrong rate: the receiver assembles other bits and misses the stop bit */
		u->stats.framing_errors++;
		rx_push(u, (uint8_t)(baud > mine ? (byte | 0x80U) ^ 0x55U : 0x00U), LSR_FE);
		return;
	}
	rx_push(u, byte, 0);
}

/* Event: the line has been low a character time. */
static void break_due(void *arg)
{
	struct hs_uart *u = arg;

	u->break_ev = 0;
	u->stats.breaks++;
	rx_push(u, 0x00, LSR_BI | LSR_FE);
}

/* RX line level: low for a whole character is one break character. */
void hs_uart_rx_line(struct hs_uart *u, bool high)
{
	if (!u || high == u->line_high)
		return;
	u->line_high = high;
	hs_event_cancel(&u->break_ev);
	if (!high && divisor(u))
		u->break_ev = hs_event_after(u->char_ns, break_due, u);
}

/* ---- transmitter ---- */

static void tx_start(struct hs_uart *u);

/* Event: the shift register is empty; the byte reaches the far end. */
static void tx_done(void *arg)
{
	struct hs_uart *u = arg;
	uint8_t b = u->tsr;
	uint32_t baud = u->baud;

	u->tx_ev = 0;
	u->tsr_busy = false;
	u->stats.tx_bytes++;
	if (u->mcr & MCR_LOOP)
		rx_push(u, b, 0);
	else if (!(u->lcr & LCR_BC) && u->peer.tx_byte)
		u->peer.tx_byte(u->peer.ctx, b, baud);
	tx_start(u);
	irq_update(u);
}

/* Moves the next FIFO byte into the shift register if it is free. */
static void tx_start(struct hs_uart *u)
{
	uint64_t ns;

	if (u->tsr_busy || !u->tx_count || !tx_enabled(u))
		return;
	ns = u->char_ns;
	if (!ns)
		return;     /* no baud clock: the byte waits */
	u->tsr = u->tx[u->tx_head];
	u->tx_head = (u->tx_head + 1U) % FIFO_SIZE;
	u->tx_count--;
	u->tsr_busy = true;
	if (!u->tx_count) {
		u->thre_int = true;
		u->irq_stale = true;
	}
	u->tx_ev = hs_event_after(ns, tx_done, u);
}

/* ---- register hooks ---- */

/* RBR read (DLL with DLAB): the FIFO's head byte, taken; 0 when empty.
 * The value read, also left in *value. */
static inline uint32_t rbr_take(struct hs_uart *u, uint32_t *value)
{
	uint32_t v;

	if (u->lcr & LCR_DLAB)
		return *value = u->dll;
	if (!u->rx_count)
		return *value = 0;
	*value = v = u->rx[u->rx_head];
	u->rx_errs -= u->rx_err[u->rx_head] != 0;
	u->rx_head = (u->rx_head + 1U) % FIFO_SIZE;
	u->rx_count--;
	rx_activity(u);
	irq_update(u);
	return v;
}

static void read_rbr(void *ctx, const struct hs_access *a, uint32_t *value)
{
	rbr_take(ctx, value);
}

/* read_rbr as RBR's direct read (regs.h). */
static uint32_t read_rbr_direct(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);

	return rbr_take(d->ctx, d->value);
}

/* THR write: queue a byte (DLL with DLAB). */
static void write_thr(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_uart *u = ctx;

	if (u->lcr & LCR_DLAB) {
		timeout_settle(u);
		hs_reg_set(u->r, DLL, written & 0xFFU);
		u->dll = written & 0xFFU;
		timing_update(u);
		tx_start(u);
		return;
	}
	if (!tx_enabled(u)) {
		rtos_host_trace(u->cfg->name, "THR write 0x%02x ignored: transmitter in reset (PWREMU_MGMT.UTRST=0)",
				(unsigned)(written & 0xFFU));
		return;
	}
	if (u->tx_count >= (fifo_mode(u) ? FIFO_SIZE : 1U)) {
		rtos_host_trace(u->cfg->name, "THR write 0x%02x lost: TX FIFO full", (unsigned)(written & 0xFFU));
		return;
	}
	u->tx[(u->tx_head + u->tx_count) % FIFO_SIZE] = (uint8_t)written;
	u->tx_count++;
	u->thre_int = false;
	tx_start(u);
	irq_update(u);
}

/* IER read (DLH with DLAB). */
static void read_ier(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct hs_uart *u = ctx;

	if (u->lcr & LCR_DLAB)
		*value = u->dlh;
}

/* IER write (DLH with DLAB). */
static void write_ier(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_uart *u = ctx;

	if (u->lcr & LCR_DLAB) {
		timeout_settle(u);
		hs_reg_set(u->r, IER, old);
		hs_reg_set(u->r, DLH, written & 0xFFU);
		u->dlh = written & 0xFFU;
		timing_update(u);
		tx_start(u);
		return;
	}
	u->ier = nv;
	/* enabling ETBEI while the holding register is empty raises THRE at once */
	if ((nv & IER_ETBEI) && !(old & IER_ETBEI) && !u->tx_count)
		u->thre_int = true;
	rx_activity(u);
	irq_update(u);
}

/* The interrupt line after an IIR read reported THRE, which the read
 * clears; v, the value read, back (out of line: iir_take then keeps nothing
 * across a call). */
static __attribute__((noinline)) uint32_t iir_taken_thre(struct hs_uart *u, uint32_t v)
{
	u->thre_int = false;
	irq_update(u);
	return v;
}

/* IIR read: the identification; clears a THRE interrupt it reports.  The
 * value read, also left in *value. */
static inline uint32_t iir_take(struct hs_uart *u, uint32_t *value)
{
	unsigned id = u->irq_stale ? iir_id(u) : u->iir;
	uint32_t v = id | (fifo_mode(u) ? HS_UART_IIR_FIFOS_ON : 0U);

	*value = v;
	if (id == HS_UART_IIR_THR_EMPTY)
		return iir_taken_thre(u, v);
	return v;
}

static void read_iir(void *ctx, const struct hs_access *a, uint32_t *value)
{
	iir_take(ctx, value);
}

/* read_iir as IIR's direct read (regs.h). */
static uint32_t read_iir_direct(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);

	return iir_take(d->ctx, d->value);
}

/* FCR write: FIFO enable, clears, trigger. */
static void write_fcr(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_uart *u = ctx;

	timeout_settle(u);
	u->fcr = (uint8_t)(written & 0xC9U);
	if (written & 0x02U) {      /* RXCLR */
		u->rx_count = 0;
		u->rx_errs = 0;
		u->timeout_int = false;
		hs_event_cancel(&u->timeout_ev);
	}
	if (written & 0x04U)        /* TXCLR */
		u->tx_count = 0;
	irq_update(u);
}

/* LCR write: break control to the far end. */
static void write_lcr(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_uart *u = ctx;
	bool brk = nv & LCR_BC;

	timeout_settle(u);
	u->lcr = nv;
	timing_update(u);
	if (brk != u->break_sent) {
		u->break_sent = brk;
		if (u->peer.tx_break)
			u->peer.tx_break(u->peer.ctx, brk);
	}
}

/* The interrupt line after an LSR read cleared an error or found a source
 * stale; v, the value read, back (out of line: lsr_take then keeps nothing
 * across a call). */
static __attribute__((noinline)) uint32_t lsr_taken_update(struct hs_uart *u, uint32_t v)
{
	u->overrun = false;
	irq_update(u);
	return v;
}

/* LSR read: status now; error bits clear.  Only clearing an error (or a
 * source left stale) can move the interrupt line, so a clean read, the
 * drivers' per-byte poll, leaves it alone.  The value read, also left in
 * *value. */
static inline uint32_t lsr_take(struct hs_uart *u, uint32_t *value)
{
	uint32_t v = 0;
	uint8_t head_err = 0;

	if (u->rx_count) {
		head_err = u->rx_err[u->rx_head];
		v |= LSR_DR | head_err;
		if (u->rx_errs && fifo_mode(u))
			v |= LSR_RXFIFOE;
		if (head_err) {     /* reported: cleared by this read */
			u->rx_err[u->rx_head] = 0;
			u->rx_errs--;
		}
	}
	if (u->overrun)
		v |= LSR_OE;
	if (!u->tx_count)
		v |= LSR_THRE;
	if (!u->tx_count && !u->tsr_busy)
		v |= LSR_TEMT;
	*value = v;
	if (u->overrun || head_err || u->irq_stale)
		return lsr_taken_update(u, v);
	return v;
}

static void read_lsr(void *ctx, const struct hs_access *a, uint32_t *value)
{
	lsr_take(ctx, value);
}

/* read_lsr as LSR's direct read (regs.h). */
static uint32_t read_lsr_direct(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);

	return lsr_take(d->ctx, d->value);
}

/* DLL/DLH write: new baud. */
static void write_div(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_uart *u = ctx;

	timeout_settle(u);
	if (a->offset == DLL)
		u->dll = nv;
	else
		u->dlh = nv;
	timing_update(u);
	tx_start(u);
}

/* MCR/MDR writes (cached). */
static void write_mcr_mdr(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_uart *u = ctx;

	if (a->offset == MCR) {
		u->mcr = nv;
	} else {
		timeout_settle(u);
		u->mdr = nv;
		timing_update(u);
	}
}

/* PWREMU_MGMT: reset bits flush receiver/transmitter. */
static void write_pwremu(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_uart *u = ctx;

	u->pwremu = nv;
	if (!(nv & PWREMU_URRST)) {
		u->rx_count = 0;
		u->rx_errs = 0;
		u->overrun = false;
		u->timeout_int = false;
		u->timeout_deferred = false;
		hs_event_cancel(&u->timeout_ev);
	}
	if (!(nv & PWREMU_UTRST)) {
		u->tx_count = 0;
		u->thre_int = false;
	}
	tx_start(u);
	irq_update(u);
}

static const struct hs_reg uart_regs[] = {
	{ .name = "RBR", .offset = RBR, .widths = HS_W8 | HS_W32, .kind = HS_RO, .before_read = read_rbr,
	  .read_direct = read_rbr_direct },
	{ .name = "THR", .offset = RBR, .widths = HS_W8 | HS_W32, .kind = HS_WO, .mask = 0xFF,
	  .after_write = write_thr },
	{ .name = "IER", .offset = IER, .widths = HS_W8 | HS_W32, .kind = HS_RW, .mask = 0x0F,
	  .before_read = read_ier, .after_write = write_ier },
	{ .name = "IIR", .offset = IIR, .widths = HS_W8 | HS_W32, .kind = HS_RO, .reset = 0x01,
	  .before_read = read_iir, .read_direct = read_iir_direct },
	{ .name = "FCR", .offset = IIR, .widths = HS_W8 | HS_W32, .kind = HS_WO, .mask = 0xFF,
	  .after_write = write_fcr },
	{ .name = "LCR", .offset = LCR, .widths = HS_W8 | HS_W32, .kind = HS_RW, .mask = 0xFF,
	  .after_write = write_lcr },
	{ .name = "MCR", .offset = MCR, .widths = HS_W8 | HS_W32, .kind = HS_RW, .mask = 0x3F,
	  .after_write = write_mcr_mdr },
	{ .name = "LSR", .offset = LSR, .widths = HS_W8 | HS_W32, .kind = HS_RO, .reset = 0x60,
	  .before_read = read_lsr, .read_direct = read_lsr_direct },
	{ .name = "MSR", .offset = MSR, .widths = HS_W8 | HS_W32, .kind = HS_RO },
	{ .name = "SCR", .offset = SCR, .widths = HS_W8 | HS_W32, .kind = HS_RW, .mask = 0xFF },
	{ .name = "DLL", .offset = DLL, .widths = HS_W8 | HS_W32, .kind = HS_RW, .mask = 0xFF,
	  .after_write = write_div },
	{ .name = "DLH", .offset = DLH, .widths = HS_W8 | HS_W32, .kind = HS_RW, .mask = 0xFF,
	  .after_write = write_div },
	{ .name = "REVID1", .offset = REVID1, .kind = HS_RO, .reset = 0x11020002 },
	{ .name = "REVID2", .offset = REVID2, .kind = HS_RO },
	{ .name = "PWREMU_MGMT", .offset = PWREMU, .widths = HS_W16 | HS_W32, .kind = HS_RW,
	  .reset = 0x0002, .mask = 0x6001, .after_write = write_pwremu },
	{ .name = "MDR", .offset = MDR, .widths = HS_W8 | HS_W32, .kind = HS_RW, .mask = 0x01,
	  .after_write = write_mcr_mdr },
};

/* ---- life cycle ---- */

ER hs_uart_create(const struct hs_uart_cfg *cfg, struct hs_uart **out)
{
	struct hs_uart *u = calloc(1, sizeof(*u));
	const struct hs_board_cfg *bc = hs_board_config();

	if (!u)
		return E_NOMEM;
	u->cfg = cfg;
	u->r = hs_region_add(&(struct hs_region_cfg){ .name = u->cfg->name, .phys = u->cfg->base,
		.size = 0x1000, .regs = uart_regs, .nregs = HS_ARRAY_SIZE(uart_regs),
		.power = cfg->power, .ctx = u });
	if (!u->r) {
		free(u);
		return E_PAR;
	}
	/* Linux (or the stand-in's firmware loader) leaves the UART out of reset */
	u->pwremu = 0x0002;
	if (!bc || !bc->cold_reset) {
		u->pwremu = 0x6003;
		hs_reg_set(u->r, PWREMU, u->pwremu);
	}
	u->line_high = true;
	u->iir = HS_UART_IIR_NONE;
	timing_update(u);
	*out = u;
	return E_OK;
}

void hs_uart_destroy(struct hs_uart *u)
{
	if (!u)
		return;
	hs_event_cancel(&u->tx_ev);
	hs_event_cancel(&u->timeout_ev);
	hs_event_cancel(&u->break_ev);
	free(u);
}

/* Connects the far end. */
void hs_uart_set_peer(struct hs_uart *u, const struct hs_uart_peer *peer)
{
	if (peer)
		u->peer = *peer;
	else
		memset(&u->peer, 0, sizeof(u->peer));
}

/* UART counters. */
const struct hs_uart_stats *hs_uart_get_stats(const struct hs_uart *u)
{
	return &u->stats;
}
