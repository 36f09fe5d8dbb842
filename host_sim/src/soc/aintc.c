/*
 * aintc.c — the ARM interrupt controller (AINTC) as a register view of the
 * interrupt lines rtos_stub dispatches, and the request path of the models.
 * Host only.
 *
 * rtos_stub owns delivery: enable state (CFG_INT TA_ENAINT, ena_int,
 * dis_int), latched and level requests, priorities and nesting.  Reading an
 * AINTC status or enable register shows that state; writing EISR/EICR/ESR/ECR
 * enables or disables the line there, SISR/SRSR raise it and SICR/SECR clear
 * it.  CMR shows the channel implied by the CFG_INT priority (channel
 * 2 + intpri - TMIN_INTPRI, so -7 is channel 2, the highest IRQ channel);
 * GER, HIER, CR, VBR and VSR hold their values but do not gate delivery,
 * which is the kernel's business on the host as on the target.
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/intc.h"
#include "host_sim/regs.h"
#include "host_sim/trace.h"
#include "soc_parts.h"

#define AINTC_VBR     0x050U
#define AINTC_VSR     0x054U
#define AINTC_HIER    0x1500U
#define NO_PENDING    0x80000000U

static struct {
	struct hs_region *region;
	struct hs_signal *sig[HS_INTC_NSYSINT];
} ic;

/* Names of the DA850 system interrupts the EV3 uses, for traces. */
static const char *sysint_name(INTNO n)
{
	static const char *const gpio[] = { "gpio_b0", "gpio_b1", "gpio_b2", "gpio_b3", "gpio_b4",
					    "gpio_b5", "gpio_b6", "gpio_b7", "gpio_b8" };

	if (n >= 3U && n <= 10U) {
		static const char *const pru[] = { "pru_evtout0", "pru_evtout1", "pru_evtout2", "pru_evtout3",
						   "pru_evtout4", "pru_evtout5", "pru_evtout6", "pru_evtout7" };
		return pru[n - 3U];
	}
	if (n >= 42U && n <= 50U)
		return gpio[n - 42U];
	switch (n) {
	case 20: return "spi0";
	case 21: return "t64p0_tint12";
	case 22: return "t64p0_tint34";
	case 25: return "uart0";
	case 53: return "uart1";
	case 56: return "spi1";
	case 96: return "t64p3_tint";
	default: return "";
	}
}

/* Declares the trace signal of sysint, low, on its first request while the AINTC
 * exists (out of line: requests are frequent). */
static __attribute__((noinline)) struct hs_signal *declare_sysint_signal(INTNO n)
{
	char name[40];
	const char *what = sysint_name(n);

	snprintf(name, sizeof(name), "int%u%s%s", (unsigned)n, *what ? "_" : "", what);
	ic.sig[n] = hs_trace_signal("irq", name, 1);
	hs_trace_set(ic.sig[n], 0);
	return ic.sig[n];
}

/* true if sysint is a valid system interrupt, else reports the caller's bug. */
static bool sysint_ok(INTNO n, const char *what)
{
	if (n < HS_INTC_NSYSINT)
		return true;
	rtos_host_bug("host_sim", "%s: system interrupt %u does not exist (0..%u)", what, (unsigned)n,
		      HS_INTC_NSYSINT - 1U);
	return false;
}

void hs_intc_raise(INTNO sysint)
{
	if (!sysint_ok(sysint, "hs_intc_raise"))
		return;
	if (ic.sig[sysint])
		hs_trace_pulse(ic.sig[sysint]);
	else if (ic.region)
		hs_trace_pulse(declare_sysint_signal(sysint));
	rtos_host_irq_raise(sysint);
}

void hs_intc_set_level(INTNO sysint, bool asserted)
{
	if (!sysint_ok(sysint, "hs_intc_set_level"))
		return;
	if (ic.sig[sysint])
		hs_trace_set(ic.sig[sysint], asserted);
	else if (ic.region)
		hs_trace_set(declare_sysint_signal(sysint), asserted);
	rtos_host_irq_set_level(sysint, asserted);
}

bool hs_intc_pending(INTNO sysint)
{
	return sysint < HS_INTC_NSYSINT && rtos_host_irq_pending(sysint);
}

unsigned hs_intc_channel(INTNO sysint)
{
	PRI pri;

	if (sysint >= HS_INTC_NSYSINT)
		return 0;
	pri = rtos_host_irq_priority(sysint);
	if (pri < TMIN_INTPRI || pri > TMAX_INTPRI)
		return 0;
	return (unsigned)(2 + pri - TMIN_INTPRI);
}

/* Enables or disables sysint in rtos_stub on behalf of a register write. */
static void set_enable(INTNO n, bool on, const char *reg)
{
	ER er;

	if (n >= HS_INTC_NSYSINT) {
		rtos_host_bug("host_sim", "AINTC.%s: system interrupt %u does not exist", reg, (unsigned)n);
		return;
	}
	er = on ? ena_int(n) : dis_int(n);
	if (er != E_OK)
		rtos_host_bug("host_sim", "AINTC.%s: %s of system interrupt %u refused by the kernel (error %d; no CFG_INT for it?)",
			      reg, on ? "enable" : "disable", (unsigned)n, (int)er);
}

/* Highest-priority pending and enabled interrupt among channels [lo, hi], or NO_PENDING. */
static uint32_t highest_pending(unsigned lo, unsigned hi)
{
	uint32_t best = NO_PENDING;
	unsigned best_ch = 0;

	for (INTNO n = 0; n < HS_INTC_NSYSINT; n++) {
		unsigned ch;

		if (!rtos_host_irq_pending(n) || !rtos_host_irq_enabled(n))
			continue;
		ch = hs_intc_channel(n);
		if (ch < lo || ch > hi)
			continue;
		if (best == NO_PENDING || ch < best_ch) {
			best = n;
			best_ch = ch;
		}
	}
	return best;
}

/* Vector address of a pending index: VBR + index * (VSR + 1) * 4. */
static uint32_t vector_of(uint32_t idx)
{
	uint32_t vbr = hs_reg_get(ic.region, AINTC_VBR);
	uint32_t vsr = hs_reg_get(ic.region, AINTC_VSR) & 0xFFU;

	return idx == NO_PENDING ? vbr : vbr + idx * (vsr + 1U) * 4U;
}

/* Status and enable banks: bit b of bank i is system interrupt 32*i + b. */
static void bank_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	const char *n = a->reg->name;
	uint32_t v = 0;

	(void)ctx;
	for (unsigned b = 0; b < 32U; b++) {
		INTNO s = 32U * a->index + b;
		bool bit;

		if (s >= HS_INTC_NSYSINT)
			break;
		if (n[0] == 'S' && n[1] == 'R')        /* SRSR: raw status */
			bit = rtos_host_irq_pending(s);
		else if (n[0] == 'S')                  /* SECR: enabled status */
			bit = rtos_host_irq_pending(s) && rtos_host_irq_enabled(s);
		else                                   /* ESR, ECR: enables */
			bit = rtos_host_irq_enabled(s);
		if (bit)
			v |= 1U << b;
	}
	*value = v;
}

static void bank_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	const char *n = a->reg->name;

	(void)ctx; (void)old; (void)now;
	for (unsigned b = 0; b < 32U; b++) {
		INTNO s = 32U * a->index + b;

		if (!(written & (1U << b)))
			continue;
		if (s >= HS_INTC_NSYSINT) {
			rtos_host_bug("host_sim", "AINTC.%s[%u]: bit %u is system interrupt %u, which does not exist",
				      n, a->index, b, (unsigned)s);
			continue;
		}
		if (strcmp(n, "SRSR") == 0)
			hs_intc_raise(s);
		else if (strcmp(n, "SECR") == 0)
			rtos_host_irq_clear(s);
		else
			set_enable(s, strcmp(n, "ESR") == 0, n);
	}
}

/* Indexed commands: the written value is a system interrupt number. */
static void index_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	const char *n = a->reg->name;
	INTNO s = written & 0x3FFU;

	(void)ctx; (void)old; (void)now;
	if (strcmp(n, "HIEISR") == 0 || strcmp(n, "HIEICR") == 0) {
		if (s > 1U)
			rtos_host_bug("host_sim", "AINTC.%s: host interrupt %u does not exist (0 FIQ, 1 IRQ)", n, (unsigned)s);
		else
			hs_reg_update(ic.region, AINTC_HIER, 1U << s, strcmp(n, "HIEISR") == 0 ? 1U << s : 0U);
		return;
	}
	if (s >= HS_INTC_NSYSINT) {
		rtos_host_bug("host_sim", "AINTC.%s: system interrupt %u does not exist", n, (unsigned)s);
		return;
	}
	if (strcmp(n, "SISR") == 0)
		hs_intc_raise(s);
	else if (strcmp(n, "SICR") == 0)
		rtos_host_irq_clear(s);
	else
		set_enable(s, strcmp(n, "EISR") == 0, n);
}

/* CMRn: four 8-bit channel fields, derived from the CFG_INT priorities. */
static void cmr_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	uint32_t v = 0;

	(void)ctx;
	for (unsigned k = 0; k < 4U; k++) {
		INTNO s = 4U * a->index + k;

		if (s < HS_INTC_NSYSINT)
			v |= (uint32_t)hs_intc_channel(s) << (8U * k);
	}
	*value = v;
}

/* GPIR/GPVR/HIPIRn/HIPVRn: the highest-priority pending interrupt. */
static void prio_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	const char *n = a->reg->name;
	uint32_t idx;

	(void)ctx;
	if (n[0] == 'G')
		idx = highest_pending(0, 31);
	else if (a->index == 0)
		idx = highest_pending(0, 1);   /* host interrupt 0: FIQ, channels 0-1 */
	else
		idx = highest_pending(2, 31);  /* host interrupt 1: IRQ, channels 2-31 */
	*value = strstr(n, "VR") ? vector_of(idx) : idx;
}

static const struct hs_reg aintc_regs[] = {
	{ .name = "REVID",  .offset = 0x000, .kind = HS_RO, .reset = 0x4E82A900 },
	{ .name = "CR",     .offset = 0x004, .kind = HS_RW, .mask = 0x0000001C },
	{ .name = "GER",    .offset = 0x010, .kind = HS_RW, .mask = 0x1 },
	{ .name = "GNLR",   .offset = 0x01C, .kind = HS_RW, .mask = 0x800001FF, .reset = 0x100 },
	{ .name = "SISR",   .offset = 0x020, .kind = HS_WO, .mask = 0x3FF, .after_write = index_written },
	{ .name = "SICR",   .offset = 0x024, .kind = HS_WO, .mask = 0x3FF, .after_write = index_written },
	{ .name = "EISR",   .offset = 0x028, .kind = HS_WO, .mask = 0x3FF, .after_write = index_written },
	{ .name = "EICR",   .offset = 0x02C, .kind = HS_WO, .mask = 0x3FF, .after_write = index_written },
	{ .name = "HIEISR", .offset = 0x034, .kind = HS_WO, .mask = 0x3FF, .after_write = index_written },
	{ .name = "HIEICR", .offset = 0x038, .kind = HS_WO, .mask = 0x3FF, .after_write = index_written },
	{ .name = "VBR",    .offset = AINTC_VBR, .kind = HS_RW },
	{ .name = "VSR",    .offset = AINTC_VSR, .kind = HS_RW, .mask = 0xFF },
	{ .name = "VNR",    .offset = 0x058, .kind = HS_RW },
	{ .name = "GPIR",   .offset = 0x080, .kind = HS_RO, .before_read = prio_read },
	{ .name = "GPVR",   .offset = 0x084, .kind = HS_RO, .before_read = prio_read },
	{ .name = "SRSR",   .offset = 0x200, .kind = HS_W1S, .count = 4, .before_read = bank_read, .after_write = bank_written },
	{ .name = "SECR",   .offset = 0x280, .kind = HS_W1C, .count = 4, .before_read = bank_read, .after_write = bank_written },
	{ .name = "ESR",    .offset = 0x300, .kind = HS_W1S, .count = 4, .before_read = bank_read, .after_write = bank_written },
	{ .name = "ECR",    .offset = 0x380, .kind = HS_W1C, .count = 4, .before_read = bank_read, .after_write = bank_written },
	{ .name = "CMR",    .offset = 0x400, .kind = HS_RO, .count = 26, .before_read = cmr_read },
	{ .name = "HIPIR",  .offset = 0x900, .kind = HS_RO, .count = 2, .before_read = prio_read, .reset = NO_PENDING },
	{ .name = "HINLR",  .offset = 0x1100, .kind = HS_RW, .count = 2, .mask = 0x800001FF, .reset = 0x100 },
	{ .name = "HIER",   .offset = AINTC_HIER, .kind = HS_RW, .mask = 0x3 },
	{ .name = "HIPVR",  .offset = 0x1600, .kind = HS_RO, .count = 2, .before_read = prio_read },
};

ER hs_aintc_create(bool cold)
{
	memset(&ic, 0, sizeof(ic));
	ic.region = hs_region_add(&(struct hs_region_cfg){
		.name = "AINTC", .phys = HS_AINTC_BASE, .size = 0x2000,
		.regs = aintc_regs, .nregs = HS_ARRAY_SIZE(aintc_regs), .power = HS_NO_PSC });
	if (!ic.region)
		return E_SYS;
	if (!cold) {
		/* The RTOS enables the controller and the IRQ host interrupt at start. */
		hs_reg_set(ic.region, 0x010, 1);
		hs_reg_set(ic.region, AINTC_HIER, 2);
	}
	return E_OK;
}

void hs_aintc_destroy(void)
{
	memset(&ic, 0, sizeof(ic));
}
