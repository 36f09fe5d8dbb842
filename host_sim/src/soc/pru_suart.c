/*
 * pru_suart.c — the PRU subsystem with TI's soft-UART firmware, McASP0 and
 * the shared RAM, as the ARM sees them (host_sim/devices/pru_suart.h says
 * what is modelled and on whose authority).
 */
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/devices/pru_suart.h"

/* PRUSS offsets (AM1808 TRM, PRU subsystem memory map) */
#define DRAM0		0x0000U
#define DRAM1		0x2000U
#define DRAM_SIZE	0x2000U
#define INTC		0x4000U
#define PRU0_CTRL	0x7000U
#define PRU1_CTRL	0x7800U
#define IRAM0		0x8000U
#define IRAM1		0xC000U
#define IRAM_SIZE	0x1000U

/* PRU INTC registers (AM1808 TRM, PRU subsystem, interrupt controller) */
#define INTC_GER	(INTC + 0x010U)
#define INTC_SISR	(INTC + 0x020U)
#define INTC_SICR	(INTC + 0x024U)
#define INTC_EISR	(INTC + 0x028U)
#define INTC_EICR	(INTC + 0x02CU)
#define INTC_HIEISR	(INTC + 0x034U)
#define INTC_HIDISR	(INTC + 0x038U)
#define INTC_SRSR0	(INTC + 0x200U)
#define INTC_SECR0	(INTC + 0x280U)
#define INTC_ESR0	(INTC + 0x300U)
#define INTC_ECR0	(INTC + 0x380U)
#define INTC_CMR0	(INTC + 0x400U)
#define INTC_HMR0	(INTC + 0x800U)
#define INTC_HIER	(INTC + 0x1500U)
#define NEVENTS		64U
#define NHOSTS		10U
#define EVT_ARM_TO_PRU0	32U
#define EVT_CHANNEL0	34U     /* firmware: event 34 + channel */
#define AINTC_EVTOUT0	3U      /* host interrupt 2 = PRU_EVTOUT0 = AINTC line 3 */

/* PRU control register bits (TRM: PRU CONTROL) */
#define CTRL_SOFT_RST_N	0x1U
#define CTRL_ENABLE	0x2U
#define CTRL_RUNSTATE	0x8000U

/* McASP offsets (AM1808 TRM, McASP registers) */
#define ACLKRCTL	0x70U
#define AHCLKRCTL	0x74U
#define ACLKXCTL	0xB0U
#define AHCLKXCTL	0xB4U
#define SRCTL0		0x180U
#define SRMOD_RX	2U

/* Firmware data RAM layout (TI's suart_pru_regs.h, PRU_SUART_Emulation.hp) */
#define NCHANNELS	8U
#define CH_CTRL		0x0U    /* mode 1:0, SR bit 2, serializer 11:8 */
#define CH_CONFIG1	0x2U    /* prescaler 9:0, oversampling 11:10, masks 12 FE 13 BI 14 timeout 15 overrun */
#define CH_CONFIG2	0x4U    /* bits per character 3:0 (with start and stop), data length - 1 11:8 */
#define CH_STATUS	0x6U    /* READY 0, COMPLETE / FIFO index 1, ERR 2, OVRN 3, FE 4, BI 5, TIMEOUT 6 */
#define CH_ACTIVE	0x7U    /* bit 7: channel active */
#define CH_DATA		0x8U    /* buffer address */
#define CH_BYTES_DONE	0xCU
#define GBL_IMR		0x80U
#define GBL_ISR		0x82U
#define GBL_TIMEOUT	0x88U
#define CTRL_SR		0x4U
#define MODE_TX		1U
#define MODE_RX		2U
#define ST_READY	0x01U
#define ST_COMPLETE	0x02U
#define ST_ERR		0x04U
#define ST_OVRN		0x08U
#define ST_BI		0x20U
#define ST_TIMEOUT	0x40U
#define CFG1_BI_MASK	(1U << 13)
#define CFG1_TIMEOUT	(1U << 14)
#define CFG1_OVRN_MASK	(1U << 15)
#define GBL_ERR_BIT	9U

struct tx_state {
	hs_event_t ev;
	uint32_t buf;           /* shared RAM address of the next byte */
	unsigned left;
	uint64_t char_ns;
	uint32_t baud;
};

struct rx_state {
	hs_event_t timeout_ev, break_ev;
	uint64_t last_end;      /* when the last byte (or break) ended */
	bool line_low;
};

struct hs_pru_suart {
	struct hs_region *pruss, *mcasp, *sram;
	uint64_t raw[2], enabled[2];    /* INTC system event status and enables (events 0..63) */
	bool host_level[NHOSTS];
	struct tx_state tx[NCHANNELS];
	struct rx_state rx[NCHANNELS];
	struct hs_pru_suart_peer peer;
	struct hs_pru_suart_stats stats;
};

static struct hs_pru_suart *the_suart;

/* ---- memories ---- */

/* Byte at offset of a RAM region (stored as 32-bit little-endian words). */
static uint8_t ram_get8(struct hs_region *r, uint32_t off)
{
	return (uint8_t)(hs_reg_get(r, off & ~3U) >> (8U * (off & 3U)));
}

/* Stores a byte at offset of a RAM region, leaving the word's other bytes. */
static void ram_set8(struct hs_region *r, uint32_t off, uint8_t v)
{
	hs_reg_update(r, off & ~3U, 0xFFU << (8U * (off & 3U)), (uint32_t)v << (8U * (off & 3U)));
}

/* Little-endian halfword at offset (any alignment: the firmware's fields are byte-addressed). */
static uint16_t ram_get16(struct hs_region *r, uint32_t off)
{
	return (uint16_t)(ram_get8(r, off) | (ram_get8(r, off + 1U) << 8));
}

/* Stores a little-endian halfword at offset. */
static void ram_set16(struct hs_region *r, uint32_t off, uint16_t v)
{
	ram_set8(r, off, (uint8_t)v);
	ram_set8(r, off + 1U, (uint8_t)(v >> 8));
}

/* Little-endian word at offset. */
static uint32_t ram_get32(struct hs_region *r, uint32_t off)
{
	return ram_get16(r, off) | ((uint32_t)ram_get16(r, off + 2U) << 16);
}

/* Channel register of data RAM 0. */
static uint16_t ch16(struct hs_pru_suart *s, unsigned ch, uint32_t reg)
{
	return ram_get16(s->pruss, DRAM0 + 16U * ch + reg);
}

/* Stores a channel register of data RAM 0. */
static void ch16_set(struct hs_pru_suart *s, unsigned ch, uint32_t reg, uint16_t v)
{
	ram_set16(s->pruss, DRAM0 + 16U * ch + reg, v);
}

/* A channel register byte (status, active bit, bytes counter). */
static uint8_t ch8(struct hs_pru_suart *s, unsigned ch, uint32_t reg)
{
	return ram_get8(s->pruss, DRAM0 + 16U * ch + reg);
}

/* Stores a channel register byte. */
static void ch8_set(struct hs_pru_suart *s, unsigned ch, uint32_t reg, uint8_t v)
{
	ram_set8(s->pruss, DRAM0 + 16U * ch + reg, v);
}

/* A byte of the buffer at a shared RAM address; false (reported) outside the modelled part. */
static bool sram_addr_ok(uint32_t addr, const char *what)
{
	if (addr >= HS_SHARED_RAM_BASE && addr < HS_SHARED_RAM_BASE + HS_SHARED_RAM_MODELLED)
		return true;
	rtos_host_bug("PRUSS", "soft UART %s buffer at 0x%08x: outside the shared RAM (0x%08x, %u bytes)",
		      what, addr, HS_SHARED_RAM_BASE, HS_SHARED_RAM_MODELLED);
	return false;
}

/* ---- interrupt controller ---- */

/* Whether event e is in the set (raw status or enables). */
static bool evt_bit(const uint64_t *set, unsigned e)
{
	return (set[e / 64U] >> (e % 64U)) & 1U;
}

/* Drives PRU_EVTOUT0..7 from the pending, enabled events through CMR and HMR. */
static void intc_update(struct hs_pru_suart *s)
{
	bool level[NHOSTS] = { false };
	bool ger = hs_reg_get(s->pruss, INTC_GER) & 1U;
	uint32_t hier = hs_reg_get(s->pruss, INTC_HIER);

	for (unsigned e = 0; ger && e < NEVENTS; e++) {
		unsigned chan, host;

		if (!evt_bit(s->raw, e) || !evt_bit(s->enabled, e))
			continue;
		chan = (hs_reg_get(s->pruss, INTC_CMR0 + (e & ~3U)) >> (8U * (e & 3U))) & 0xFU;
		host = (hs_reg_get(s->pruss, INTC_HMR0 + (chan & ~3U)) >> (8U * (chan & 3U))) & 0xFU;
		if (host < NHOSTS && ((hier >> host) & 1U))
			level[host] = true;
	}
	for (unsigned h = 2; h < NHOSTS; h++) {
		if (level[h] != s->host_level[h]) {
			s->host_level[h] = level[h];
			hs_intc_set_level(AINTC_EVTOUT0 + h - 2U, level[h]);
		}
	}
}

/* Puts event e in the set or takes it out (an index past 63 is ignored, as the INTC ignores it). */
static void evt_set(uint64_t *set, unsigned e, bool on)
{
	if (e >= NEVENTS)
		return;
	if (on)
		set[e / 64U] |= (uint64_t)1 << (e % 64U);
	else
		set[e / 64U] &= ~((uint64_t)1 << (e % 64U));
}

/* The firmware's PRU_TO_HOST_INTERRUPT: clear, enable and raise event e. */
static void pru_raise(struct hs_pru_suart *s, unsigned e)
{
	evt_set(s->raw, e, true);
	evt_set(s->enabled, e, true);
	s->stats.events++;
	intc_update(s);
}

static void serve_arm_request(struct hs_pru_suart *s);

/* SISR/SICR/EISR/EICR/HIEISR/HIDISR: the indexed set and clear registers; event 32 set wakes the firmware. */
static void intc_index_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_pru_suart *s = ctx;
	unsigned idx = written & 0x3FFU;

	switch (a->offset) {
	case INTC_SISR:
		evt_set(s->raw, idx, true);
		break;
	case INTC_SICR:
		evt_set(s->raw, idx, false);
		break;
	case INTC_EISR:
		evt_set(s->enabled, idx, true);
		break;
	case INTC_EICR:
		evt_set(s->enabled, idx, false);
		break;
	case INTC_HIEISR:
		if (idx < NHOSTS)
			hs_reg_update(s->pruss, INTC_HIER, 0, 1U << idx);
		break;
	case INTC_HIDISR:
		if (idx < NHOSTS)
			hs_reg_update(s->pruss, INTC_HIER, 1U << idx, 0);
		break;
	default:
		break;
	}
	intc_update(s);
	if (a->offset == INTC_SISR && idx == EVT_ARM_TO_PRU0)
		serve_arm_request(s);
}

/* SRSRn/SECRn read the raw status, ESRn/ECRn the enables. */
static void intc_set_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct hs_pru_suart *s = ctx;
	unsigned half = a->index;
	const uint64_t *set = (a->offset & 0x100U) ? s->enabled : s->raw;

	*value = (uint32_t)(set[0] >> (32U * half));
}

/* SRSRn/ESRn set, SECRn/ECRn clear the 1 bits written. */
static void intc_set_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_pru_suart *s = ctx;
	uint32_t base = a->offset - 4U * a->index;
	uint64_t bits = (uint64_t)written << (32U * a->index);

	if (base == INTC_SRSR0)
		s->raw[0] |= bits;
	else if (base == INTC_SECR0)
		s->raw[0] &= ~bits;
	else if (base == INTC_ESR0)
		s->enabled[0] |= bits;
	else
		s->enabled[0] &= ~bits;
	intc_update(s);
}

/* GER, CMR, HMR, HIER changed: the host lines follow. */
static void intc_map_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	intc_update(ctx);
}

/* ---- firmware: timing ---- */

/* The PRU runs the firmware: PRU0 enabled with code loaded. */
static bool pru0_running(struct hs_pru_suart *s)
{
	return (hs_reg_get(s->pruss, PRU0_CTRL) & CTRL_ENABLE) && hs_reg_get(s->pruss, IRAM0) != 0;
}

/* One bit on a channel: McASP bit clock period times the channel's prescaler. */
static uint64_t bit_ns(struct hs_pru_suart *s, unsigned ch, bool rx)
{
	uint32_t hdiv, div, presc = ch16(s, ch, CH_CONFIG1) & 0x3FFU;
	uint64_t cycles;

	if (rx) {
		hdiv = (hs_reg_get(s->mcasp, AHCLKRCTL) & 0xFFFU) + 1U;
		div = (hs_reg_get(s->mcasp, ACLKRCTL) & 0x1FU) + 1U;
		cycles = (uint64_t)hdiv * div * 8U;     /* 8 samples a bit (RFMT slot of 8 bits) */
	} else {
		hdiv = (hs_reg_get(s->mcasp, AHCLKXCTL) & 0xFFFU) + 1U;
		div = (hs_reg_get(s->mcasp, ACLKXCTL) & 0x1FU) + 1U;
		cycles = (uint64_t)hdiv * div;
	}
	return hs_cycles_to_ns(cycles * (presc ? presc : 1U), HS_PRU_AUXCLK_HZ);
}

/* Bits of one character on a channel (Config2: start, data and stop bits). */
static unsigned char_bits(struct hs_pru_suart *s, unsigned ch)
{
	unsigned bits = ch16(s, ch, CH_CONFIG2) & 0xFU;

	return bits ? bits : 10U;
}

/* The firmware's RX_CHN_INTR / DECLARE_COMPLETE: ISR bit, and the event if the IMR allows it. */
static void channel_interrupt(struct hs_pru_suart *s, unsigned ch)
{
	uint16_t imr = ram_get16(s->pruss, DRAM0 + GBL_IMR);

	ram_set16(s->pruss, DRAM0 + GBL_ISR, (uint16_t)(ram_get16(s->pruss, DRAM0 + GBL_ISR) | (1U << ch)));
	if (imr & (1U << ch))
		pru_raise(s, EVT_CHANNEL0 + ch);
}

/* ---- firmware: transmit ---- */

static void tx_next(void *arg);

/* Event: a character left the wire on TX channel ch. */
static void tx_char_done(struct hs_pru_suart *s, unsigned ch)
{
	struct tx_state *t = &s->tx[ch];
	unsigned ser = (ch16(s, ch, CH_CTRL) >> 8) & 0xFU;
	uint8_t byte;

	if (!sram_addr_ok(t->buf, "transmit"))
		return;
	byte = ram_get8(s->sram, t->buf - HS_SHARED_RAM_BASE);
	t->buf++;
	t->left--;
	ch8_set(s, ch, CH_BYTES_DONE, (uint8_t)(ch8(s, ch, CH_BYTES_DONE) + 1U));
	s->stats.tx_bytes++;
	if (s->peer.tx_byte)
		s->peer.tx_byte(s->peer.ctx, ser, byte, t->baud);
	if (t->left) {
		t->ev = hs_event_after(t->char_ns, tx_next, &s->tx[ch]);
		return;
	}
	if (ch8(s, ch, CH_STATUS) & ST_READY) {
		ch8_set(s, ch, CH_STATUS, (uint8_t)((ch8(s, ch, CH_STATUS) | ST_COMPLETE) & ~ST_READY));
		if (ram_get16(s->pruss, DRAM0 + GBL_IMR) & (1U << ch))
			channel_interrupt(s, ch);
	}
}

/* Event: the character in flight on a TX channel (arg: its tx_state) has left the wire. */
static void tx_next(void *arg)
{
	struct tx_state *t = arg;
	struct hs_pru_suart *s = the_suart;

	t->ev = 0;
	tx_char_done(s, (unsigned)(t - s->tx));
}

/* TxServiceRequestHndlr: start sending the channel's buffer. */
static void tx_service(struct hs_pru_suart *s, unsigned ch)
{
	struct tx_state *t = &s->tx[ch];
	uint64_t bns = bit_ns(s, ch, false);

	ch8_set(s, ch, CH_STATUS, (uint8_t)(ch8(s, ch, CH_STATUS) | ST_READY));
	ch8_set(s, ch, CH_ACTIVE, (uint8_t)(ch8(s, ch, CH_ACTIVE) | 0x80U));
	ch8_set(s, ch, CH_BYTES_DONE, 0);
	hs_event_cancel(&t->ev);
	t->buf = ram_get32(s->pruss, DRAM0 + 16U * ch + CH_DATA);
	t->left = ((ch16(s, ch, CH_CONFIG2) >> 8) & 0xFU) + 1U;
	t->char_ns = bns * char_bits(s, ch);
	t->baud = bns ? (uint32_t)((1000000000ULL + bns / 2U) / bns) : 0U;
	t->ev = hs_event_after(t->char_ns, tx_next, t);
}

/* ---- firmware: receive ---- */

/* The RX channel listening on serializer ser (active, serializer in receive mode), or NCHANNELS. */
static unsigned rx_channel_of(struct hs_pru_suart *s, unsigned ser)
{
	if (ser >= HS_MCASP_SERIALIZERS || !pru0_running(s) || !hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_MCASP0)))
		return NCHANNELS;
	if ((hs_reg_get(s->mcasp, SRCTL0 + 4U * ser) & 3U) != SRMOD_RX)
		return NCHANNELS;
	for (unsigned ch = 1; ch < NCHANNELS; ch += 2) {
		if ((ch16(s, ch, CH_CTRL) & 3U) == MODE_RX && ((ch16(s, ch, CH_CTRL) >> 8) & 0xFU) == ser &&
		    (ch8(s, ch, CH_ACTIVE) & 0x80U))
			return ch;
	}
	return NCHANNELS;
}

static void rx_timeout_due(void *arg);

/* Arms the idle timeout of channel ch from the end of its last character. */
static void rx_timeout_arm(struct hs_pru_suart *s, unsigned ch)
{
	struct rx_state *r = &s->rx[ch];
	uint32_t hdiv = (hs_reg_get(s->mcasp, AHCLKRCTL) & 0xFFFU) + 1U;
	uint32_t div = (hs_reg_get(s->mcasp, ACLKRCTL) & 0x1FU) + 1U;
	uint64_t frame_ns = hs_cycles_to_ns((uint64_t)hdiv * div * 8U, HS_PRU_AUXCLK_HZ);
	unsigned tries = ram_get16(s->pruss, DRAM0 + GBL_TIMEOUT);

	hs_event_cancel(&r->timeout_ev);
	r->timeout_ev = hs_event_at(r->last_end + frame_ns * (tries + 1U), rx_timeout_due, r);
}

/* Event: the idle time-out of an RX channel (arg: its rx_state) may be due; the firmware's conditions decide. */
static void rx_timeout_due(void *arg)
{
	struct hs_pru_suart *s = the_suart;
	struct rx_state *r = arg;
	unsigned ch = (unsigned)(r - s->rx);
	unsigned done = ch8(s, ch, CH_BYTES_DONE);
	unsigned len = ((ch16(s, ch, CH_CONFIG2) >> 8) & 0xFU) + 1U;

	r->timeout_ev = 0;
	if (!(ch16(s, ch, CH_CONFIG1) & CFG1_TIMEOUT) || !(ch8(s, ch, CH_STATUS) & ST_READY) || done == 0 ||
	    done == len || !(ch8(s, ch, CH_ACTIVE) & 0x80U))
		return;
	ch8_set(s, ch, CH_STATUS, (uint8_t)(ch8(s, ch, CH_STATUS) | ST_TIMEOUT));
	ch16_set(s, ch, CH_CONFIG1, (uint16_t)(ch16(s, ch, CH_CONFIG1) & ~CFG1_TIMEOUT));
	s->stats.timeouts++;
	channel_interrupt(s, ch);
}

/* A received character's end on channel ch: store, count, interrupt at half and full. */
static void rx_store(struct hs_pru_suart *s, unsigned ch, uint8_t byte)
{
	unsigned done = ch8(s, ch, CH_BYTES_DONE);
	unsigned len = ((ch16(s, ch, CH_CONFIG2) >> 8) & 0xFU) + 1U;
	bool wide = (ch16(s, ch, CH_CONFIG2) & 0xFU) - 2U > 8U;
	uint32_t addr = ram_get32(s->pruss, DRAM0 + 16U * ch + CH_DATA) + (wide ? 2U * done : done);
	uint8_t st;

	if (sram_addr_ok(addr, "receive")) {
		ram_set8(s->sram, addr - HS_SHARED_RAM_BASE, byte);
		if (wide)
			ram_set8(s->sram, addr + 1U - HS_SHARED_RAM_BASE, 0);
	}
	done++;
	ch8_set(s, ch, CH_BYTES_DONE, (uint8_t)done);
	s->stats.rx_bytes++;
	if (done != len && done != 2U * len)
		return;
	st = ch8(s, ch, CH_STATUS);
	if (done == len) {
		st &= (uint8_t)~ST_COMPLETE;
	} else {
		ch8_set(s, ch, CH_BYTES_DONE, 0);
		st |= ST_COMPLETE;
	}
	/* the previous half not yet taken by the ARM: overrun, if its mask allows */
	if (evt_bit(s->raw, EVT_CHANNEL0 + ch) && (ch16(s, ch, CH_CONFIG1) & CFG1_OVRN_MASK))
		st |= ST_OVRN | ST_ERR;
	ch8_set(s, ch, CH_STATUS, st);
	if (st & ST_READY)
		channel_interrupt(s, ch);
}

void hs_pru_suart_rx_byte(struct hs_pru_suart *s, unsigned ser, uint8_t byte, uint32_t baud)
{
	unsigned ch = s ? rx_channel_of(s, ser) : NCHANNELS;
	uint64_t bns;
	uint32_t mine;

	if (ch == NCHANNELS) {
		if (s)
			s->stats.rx_dropped++;
		return;
	}
	bns = bit_ns(s, ch, true);
	mine = bns ? (uint32_t)((1000000000ULL + bns / 2U) / bns) : 0U;
	/* a sender more than 4 % off samples wrong bits: a garbled byte */
	if (!mine || baud + baud / 25U < mine || baud > mine + mine / 25U) {
		s->stats.rx_garbled++;
		byte = (uint8_t)(byte ^ 0x5AU);
	}
	s->rx[ch].last_end = hs_now();
	rx_store(s, ch, byte);
	if (ch16(s, ch, CH_CONFIG1) & CFG1_TIMEOUT)
		rx_timeout_arm(s, ch);
}

/* Event: the line has been low a character time: a break frame (all zero, stop bit low). */
static void rx_break_due(void *arg)
{
	struct hs_pru_suart *s = the_suart;
	struct rx_state *r = arg;
	unsigned ch = (unsigned)(r - s->rx);
	uint16_t imr;

	r->break_ev = 0;
	if (!r->line_low || !(ch8(s, ch, CH_ACTIVE) & 0x80U))
		return;
	s->stats.breaks++;
	ch8_set(s, ch, CH_STATUS, (uint8_t)(ch8(s, ch, CH_STATUS) | ST_BI | ST_ERR));
	imr = ram_get16(s->pruss, DRAM0 + GBL_IMR);
	ram_set16(s->pruss, DRAM0 + GBL_ISR, (uint16_t)(ram_get16(s->pruss, DRAM0 + GBL_ISR) | (1U << GBL_ERR_BIT)));
	if ((imr & (1U << GBL_ERR_BIT)) && (ch16(s, ch, CH_CONFIG1) & CFG1_BI_MASK))
		channel_interrupt(s, ch);
	r->break_ev = hs_event_after(bit_ns(s, ch, true) * char_bits(s, ch), rx_break_due, r);
}

void hs_pru_suart_rx_line(struct hs_pru_suart *s, unsigned ser, bool high)
{
	unsigned ch = s ? rx_channel_of(s, ser) : NCHANNELS;
	struct rx_state *r;

	if (ch == NCHANNELS)
		return;
	r = &s->rx[ch];
	r->line_low = !high;
	hs_event_cancel(&r->break_ev);
	if (!high)
		r->break_ev = hs_event_after(bit_ns(s, ch, true) * char_bits(s, ch), rx_break_due, r);
}

/* RxServiceRequestHndlr: the channel is (again) ready to receive. */
static void rx_service(struct hs_pru_suart *s, unsigned ch)
{
	uint8_t st = ch8(s, ch, CH_STATUS);
	unsigned ser = (ch16(s, ch, CH_CTRL) >> 8) & 0xFU;

	/* the firmware (re)activates the channel's serializer as a receiver */
	if ((hs_reg_get(s->mcasp, SRCTL0 + 4U * ser) & 3U) != SRMOD_RX)
		hs_reg_set(s->mcasp, SRCTL0 + 4U * ser, 0x000EU);
	ch8_set(s, ch, CH_STATUS, (uint8_t)((st & ~ST_TIMEOUT) | ST_READY));
	ch8_set(s, ch, CH_ACTIVE, (uint8_t)(ch8(s, ch, CH_ACTIVE) | 0x80U));
	hs_event_cancel(&s->rx[ch].timeout_ev);
}

/* CHN_SEARCH: serve the lowest channel with a service request, as one pass of the firmware does. */
static void serve_arm_request(struct hs_pru_suart *s)
{
	if (!pru0_running(s))
		return;
	evt_set(s->raw, EVT_ARM_TO_PRU0, false);        /* the firmware clears its event (SECR2) */
	intc_update(s);
	for (unsigned ch = 0; ch < NCHANNELS; ch++) {
		uint16_t ctrl = ch16(s, ch, CH_CTRL);

		if (!(ctrl & CTRL_SR))
			continue;
		ram_set16(s->pruss, DRAM0 + GBL_ISR, (uint16_t)(ram_get16(s->pruss, DRAM0 + GBL_ISR) & ~(1U << ch)));
		ch16_set(s, ch, CH_CTRL, (uint16_t)(ctrl & ~CTRL_SR));
		if ((ctrl & 3U) == MODE_TX)
			tx_service(s, ch);
		else if ((ctrl & 3U) == MODE_RX)
			rx_service(s, ch);
		return;
	}
}

/* ---- PRU control ---- */

/* CONTROL.RUNSTATE reads 1 while the PRU is enabled (it never halts by itself here). */
static void pru_ctrl_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	*value = (*value & ~CTRL_RUNSTATE) | ((*value & CTRL_ENABLE) ? CTRL_RUNSTATE : 0U);
}

/* PRU0 enabled: a pending request is served; disabled: its channels stop. */
static void pru_ctrl_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct hs_pru_suart *s = ctx;

	if (a->offset != PRU0_CTRL)
		return;
	if (nv & CTRL_ENABLE) {
		/* started with a request already pending: the firmware's core loop serves it */
		if (!(old & CTRL_ENABLE) && evt_bit(s->raw, EVT_ARM_TO_PRU0))
			serve_arm_request(s);
		return;
	}
	for (unsigned ch = 0; ch < NCHANNELS; ch++) {     /* halted: nothing more moves */
		hs_event_cancel(&s->tx[ch].ev);
		hs_event_cancel(&s->rx[ch].timeout_ev);
		hs_event_cancel(&s->rx[ch].break_ev);
	}
}

/* ---- declarations ---- */

#define RAM_W (HS_W8 | HS_W16 | HS_W32)
#define CTRL_REGS(base, nm)								\
	{ .name = nm "_CONTROL", .offset = (base), .kind = HS_RW, .mask = 0xFFFF810BU,		\
	  .reset = CTRL_SOFT_RST_N, .before_read = pru_ctrl_read, .after_write = pru_ctrl_written },	\
	{ .name = nm "_STATUS", .offset = (base) + 0x04U, .kind = HS_RO },			\
	{ .name = nm "_WAKEUP_EN", .offset = (base) + 0x08U, .kind = HS_RW },			\
	{ .name = nm "_CYCLE", .offset = (base) + 0x0CU, .kind = HS_RW },			\
	{ .name = nm "_STALL", .offset = (base) + 0x10U, .kind = HS_RO },			\
	{ .name = nm "_CTBIR", .offset = (base) + 0x20U, .kind = HS_RW, .count = 2 },		\
	{ .name = nm "_CTPPR", .offset = (base) + 0x28U, .kind = HS_RW, .count = 2 }

static const struct hs_reg pruss_regs[] = {
	{ .name = "DRAM0_", .offset = DRAM0, .kind = HS_RW, .widths = RAM_W, .count = DRAM_SIZE / 4U },
	{ .name = "DRAM1_", .offset = DRAM1, .kind = HS_RW, .widths = RAM_W, .count = DRAM_SIZE / 4U },
	{ .name = "REVID", .offset = INTC + 0x000U, .kind = HS_RO, .reset = 0x4E82A900U },
	{ .name = "CR", .offset = INTC + 0x004U, .kind = HS_RW, .mask = 0x1CU },
	{ .name = "GER", .offset = INTC_GER, .kind = HS_RW, .mask = 0x1U, .after_write = intc_map_written },
	{ .name = "GNLR", .offset = INTC + 0x01CU, .kind = HS_RW, .mask = 0x800001FFU },
	{ .name = "SISR", .offset = INTC_SISR, .kind = HS_WO, .mask = 0x3FFU, .after_write = intc_index_written },
	{ .name = "SICR", .offset = INTC_SICR, .kind = HS_WO, .mask = 0x3FFU, .after_write = intc_index_written },
	{ .name = "EISR", .offset = INTC_EISR, .kind = HS_WO, .mask = 0x3FFU, .after_write = intc_index_written },
	{ .name = "EICR", .offset = INTC_EICR, .kind = HS_WO, .mask = 0x3FFU, .after_write = intc_index_written },
	{ .name = "HIEISR", .offset = INTC_HIEISR, .kind = HS_WO, .mask = 0x3FFU, .after_write = intc_index_written },
	{ .name = "HIDISR", .offset = INTC_HIDISR, .kind = HS_WO, .mask = 0x3FFU, .after_write = intc_index_written },
	{ .name = "GPIR", .offset = INTC + 0x080U, .kind = HS_RO, .reset = 0x80000000U },
	{ .name = "SRSR", .offset = INTC_SRSR0, .kind = HS_RW, .count = 2,
	  .before_read = intc_set_read, .after_write = intc_set_written },
	{ .name = "SECR", .offset = INTC_SECR0, .kind = HS_RW, .count = 2,
	  .before_read = intc_set_read, .after_write = intc_set_written },
	{ .name = "ESR", .offset = INTC_ESR0, .kind = HS_RW, .count = 2,
	  .before_read = intc_set_read, .after_write = intc_set_written },
	{ .name = "ECR", .offset = INTC_ECR0, .kind = HS_RW, .count = 2,
	  .before_read = intc_set_read, .after_write = intc_set_written },
	{ .name = "CMR", .offset = INTC_CMR0, .kind = HS_RW, .mask = 0x0F0F0F0FU, .count = 16,
	  .after_write = intc_map_written },
	{ .name = "HMR", .offset = INTC_HMR0, .kind = HS_RW, .mask = 0x0F0F0F0FU, .count = 3,
	  .after_write = intc_map_written },
	{ .name = "HIPIR", .offset = INTC + 0x900U, .kind = HS_RO, .count = 10, .reset = 0x80000000U },
	{ .name = "SIPR", .offset = INTC + 0xD00U, .kind = HS_RW, .count = 2, .reset = 0xFFFFFFFFU },
	{ .name = "SITR", .offset = INTC + 0xD80U, .kind = HS_RW, .count = 2 },
	{ .name = "HINLR", .offset = INTC + 0x1100U, .kind = HS_RW, .count = 10, .mask = 0x800001FFU },
	{ .name = "HIER", .offset = INTC_HIER, .kind = HS_RW, .mask = 0x3FFU, .after_write = intc_map_written },
	CTRL_REGS(PRU0_CTRL, "PRU0"),
	CTRL_REGS(PRU1_CTRL, "PRU1"),
	{ .name = "IRAM0_", .offset = IRAM0, .kind = HS_RW, .widths = RAM_W, .count = IRAM_SIZE / 4U },
	{ .name = "IRAM1_", .offset = IRAM1, .kind = HS_RW, .widths = RAM_W, .count = IRAM_SIZE / 4U },
};

/* McASP0: the registers TI's soft-UART driver programs (AM1808 TRM, McASP). */
static const struct hs_reg mcasp_regs[] = {
	{ .name = "REV", .offset = 0x00U, .kind = HS_RO, .reset = 0x44300A02U },
	{ .name = "PFUNC", .offset = 0x10U, .kind = HS_RW },
	{ .name = "PDIR", .offset = 0x14U, .kind = HS_RW },
	{ .name = "PDOUT", .offset = 0x18U, .kind = HS_RW },
	{ .name = "PDIN", .offset = 0x1CU, .kind = HS_RW },
	{ .name = "PDCLR", .offset = 0x20U, .kind = HS_RW },
	{ .name = "GBLCTL", .offset = 0x44U, .kind = HS_RW, .mask = 0x1F1FU },
	{ .name = "AMUTE", .offset = 0x48U, .kind = HS_RW },
	{ .name = "DLBCTL", .offset = 0x4CU, .kind = HS_RW },
	{ .name = "DITCTL", .offset = 0x50U, .kind = HS_RW },
	{ .name = "RGBLCTL", .offset = 0x60U, .kind = HS_RW },
	{ .name = "RMASK", .offset = 0x64U, .kind = HS_RW },
	{ .name = "RFMT", .offset = 0x68U, .kind = HS_RW },
	{ .name = "AFSRCTL", .offset = 0x6CU, .kind = HS_RW },
	{ .name = "ACLKRCTL", .offset = ACLKRCTL, .kind = HS_RW },
	{ .name = "AHCLKRCTL", .offset = AHCLKRCTL, .kind = HS_RW },
	{ .name = "RTDM", .offset = 0x78U, .kind = HS_RW },
	{ .name = "RINTCTL", .offset = 0x7CU, .kind = HS_RW },
	{ .name = "RSTAT", .offset = 0x80U, .kind = HS_W1C, .mask = 0x1FFU },
	{ .name = "RSLOT", .offset = 0x84U, .kind = HS_RO },
	{ .name = "RCLKCHK", .offset = 0x88U, .kind = HS_RW },
	{ .name = "REVTCTL", .offset = 0x8CU, .kind = HS_RW },
	{ .name = "XGBLCTL", .offset = 0xA0U, .kind = HS_RW },
	{ .name = "XMASK", .offset = 0xA4U, .kind = HS_RW },
	{ .name = "XFMT", .offset = 0xA8U, .kind = HS_RW },
	{ .name = "AFSXCTL", .offset = 0xACU, .kind = HS_RW },
	{ .name = "ACLKXCTL", .offset = ACLKXCTL, .kind = HS_RW },
	{ .name = "AHCLKXCTL", .offset = AHCLKXCTL, .kind = HS_RW },
	{ .name = "XTDM", .offset = 0xB8U, .kind = HS_RW },
	{ .name = "XINTCTL", .offset = 0xBCU, .kind = HS_RW },
	{ .name = "XSTAT", .offset = 0xC0U, .kind = HS_W1C, .mask = 0x1FFU },
	{ .name = "XSLOT", .offset = 0xC4U, .kind = HS_RO },
	{ .name = "XCLKCHK", .offset = 0xC8U, .kind = HS_RW },
	{ .name = "XEVTCTL", .offset = 0xCCU, .kind = HS_RW },
	{ .name = "SRCTL", .offset = SRCTL0, .kind = HS_RW, .mask = 0x3FU, .count = HS_MCASP_SERIALIZERS },
	{ .name = "XBUF", .offset = 0x200U, .kind = HS_RW, .count = HS_MCASP_SERIALIZERS },
	{ .name = "RBUF", .offset = 0x280U, .kind = HS_RW, .count = HS_MCASP_SERIALIZERS },
};

static const struct hs_reg sram_regs[] = {
	{ .name = "SHARED_RAM_", .offset = 0, .kind = HS_RW, .widths = RAM_W, .count = HS_SHARED_RAM_MODELLED / 4U },
};

/* Registers the PRUSS, McASP0 and shared RAM regions: E_OK, E_NOMEM, or E_PAR if they cannot be placed. */
static ER pru_suart_create(const struct hs_board_cfg *cfg, void **ctx)
{
	struct hs_pru_suart *s = calloc(1, sizeof(*s));

	if (!s)
		return E_NOMEM;
	s->pruss = hs_region_add(&(struct hs_region_cfg){ .name = "PRUSS", .phys = HS_PRUSS_BASE, .size = 0x10000U,
		.regs = pruss_regs, .nregs = HS_ARRAY_SIZE(pruss_regs), .power = HS_PSC0_MODULE(HS_LPSC0_PRU), .ctx = s });
	s->mcasp = hs_region_add(&(struct hs_region_cfg){ .name = "MCASP0", .phys = HS_MCASP0_BASE, .size = 0x3000U,
		.regs = mcasp_regs, .nregs = HS_ARRAY_SIZE(mcasp_regs), .power = HS_PSC1_MODULE(HS_LPSC1_MCASP0), .ctx = s });
	s->sram = hs_region_add(&(struct hs_region_cfg){ .name = "SHARED_RAM", .phys = HS_SHARED_RAM_BASE,
		.size = HS_SHARED_RAM_MODELLED, .regs = sram_regs, .nregs = HS_ARRAY_SIZE(sram_regs), .ctx = s });
	if (!s->pruss || !s->mcasp || !s->sram) {
		free(s);
		return E_PAR;
	}
	the_suart = s;
	*ctx = s;
	return E_OK;
}

/* Cancels the model's events and frees it. */
static void pru_suart_destroy(void *ctx)
{
	struct hs_pru_suart *s = ctx;

	for (unsigned ch = 0; ch < NCHANNELS; ch++) {
		hs_event_cancel(&s->tx[ch].ev);
		hs_event_cancel(&s->rx[ch].timeout_ev);
		hs_event_cancel(&s->rx[ch].break_ev);
	}
	if (the_suart == s)
		the_suart = NULL;
	free(s);
}

const struct hs_device hs_pru_suart_device = { "PRU_SUART", pru_suart_create, NULL, pru_suart_destroy };

struct hs_pru_suart *hs_pru_suart(void)
{
	return the_suart;
}

void hs_pru_suart_set_peer(struct hs_pru_suart *s, const struct hs_pru_suart_peer *peer)
{
	if (!s)
		return;
	if (peer)
		s->peer = *peer;
	else
		memset(&s->peer, 0, sizeof(s->peer));
}

const struct hs_pru_suart_stats *hs_pru_suart_get_stats(const struct hs_pru_suart *s)
{
	return &s->stats;
}
