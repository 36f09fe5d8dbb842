/*
 * psc.c — PSC0 and PSC1, the power and sleep controllers: module states
 * change on PTCMD.GO, and regions of disabled modules are dead.  Host only.
 *
 * Transitions complete at once (PTSTAT never shows GOSTAT busy): a driver
 * that waits for PTSTAT and MDSTAT and one that does not (d_pwm) both work,
 * as they do on the chip, where the transition takes a few module clocks.
 */
#include <stdlib.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "soc_parts.h"
#include "../core/space_internal.h"

#define PSC_NMOD       32U
#define PSC_PTCMD      0x120U
#define PSC_PTSTAT     0x128U
#define PSC_MDSTAT0    0x800U
#define PSC_MDCTL0     0xA00U
#define MDCTL_NEXT     0x7U
#define MDSTAT_STATE   0x3FU
#define MDSTAT_MRST    (1U << 10)  /* module reset deasserted */
#define MDSTAT_MCKOUT  (1U << 12)  /* module clock on */
#define MAX_WATCHES    32U

struct psc {
	unsigned id;                   /* 0 or 1 */
	struct hs_region *region;
	enum hs_psc_state state[PSC_NMOD];
	bool live[PSC_NMOD];           /* state == HS_PSC_ENABLE, for the register space (told of each change) */
};

static struct psc pscs[2];
static struct {
	unsigned module;
	hs_psc_watch_fn fn;
	void *ctx;
} watches[MAX_WATCHES];

/* MDSTAT value for a state. */
static uint32_t mdstat_of(enum hs_psc_state st)
{
	uint32_t v = (uint32_t)st;

	if (st == HS_PSC_ENABLE || st == HS_PSC_DISABLE)
		v |= MDSTAT_MRST;
	if (st == HS_PSC_ENABLE)
		v |= MDSTAT_MCKOUT;
	return v;
}

/* Moves module m of psc to state st, updating MDSTAT and telling watchers. */
static void psc_set_state(struct psc *p, unsigned m, enum hs_psc_state st)
{
	enum hs_psc_state old = p->state[m];
	unsigned module = (p->id == 0U ? HS_PSC0_MODULE(m) : HS_PSC1_MODULE(m));

	p->state[m] = st;
	if (p->live[m] != (st == HS_PSC_ENABLE)) {
		p->live[m] = st == HS_PSC_ENABLE;
		hs_space_power_changed();
	}
	if (p->region)
		hs_reg_set(p->region, PSC_MDSTAT0 + 4U * m, mdstat_of(st));
	if (old == st)
		return;
	rtos_host_trace("host_sim", "PSC%u module %u: state %d -> %d", p->id, m, (int)old, (int)st);
	for (unsigned i = 0; i < MAX_WATCHES; i++)
		if (watches[i].fn && watches[i].module == module)
			watches[i].fn(watches[i].ctx, module, old, st);
}

/* PTCMD written: GO[0] and GO[1] start the transitions of the modules in
 * power domain 0 and 1 whose MDCTL.NEXT differs from their state.  Every
 * modelled module sits in domain 0 (PD1 is the DSP's/shared RAM's). */
static void ptcmd_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	struct psc *p = ctx;

	(void)a; (void)old; (void)now;
	if (written & 1U) {
		for (unsigned m = 0; m < PSC_NMOD; m++) {
			uint32_t next = hs_reg_get(p->region, PSC_MDCTL0 + 4U * m) & MDCTL_NEXT;

			if (next <= HS_PSC_ENABLE && (enum hs_psc_state)next != p->state[m])
				psc_set_state(p, m, (enum hs_psc_state)next);
		}
	}
	/* GO bits are self-clearing. */
	hs_reg_set(p->region, PSC_PTCMD, 0);
}

static const struct hs_reg psc_regs[] = {
	{ .name = "REVID",   .offset = 0x000, .kind = HS_RO, .reset = 0x44823A00 },
	{ .name = "INTEVAL", .offset = 0x018, .kind = HS_WO, .mask = 0x1 },
	{ .name = "MERRPR0", .offset = 0x040, .kind = HS_RO },
	{ .name = "MERRCR0", .offset = 0x050, .kind = HS_WO },
	{ .name = "PERRPR",  .offset = 0x060, .kind = HS_RO },
	{ .name = "PERRCR",  .offset = 0x068, .kind = HS_WO },
	{ .name = "PTCMD",   .offset = PSC_PTCMD, .kind = HS_RW, .mask = 0x3, .after_write = ptcmd_written },
	{ .name = "PTSTAT",  .offset = PSC_PTSTAT, .kind = HS_RO },
	{ .name = "PDSTAT",  .offset = 0x200, .kind = HS_RO, .count = 2, .reset = 0x00000301 },
	{ .name = "PDCTL",   .offset = 0x300, .kind = HS_RW, .count = 2, .reset = 0x001FF101 },
	{ .name = "PDCFG",   .offset = 0x400, .kind = HS_RO, .count = 2, .reset = 0x0000000D },
	{ .name = "MDSTAT",  .offset = PSC_MDSTAT0, .kind = HS_RO, .count = PSC_NMOD },
	{ .name = "MDCTL",   .offset = PSC_MDCTL0, .kind = HS_RW, .count = PSC_NMOD, .mask = 0x80000107 },
};

/* Modules Linux/U-Boot leave enabled (what the EV3 kernel has running; SPI1: the display's SPI
 * master keeps its clock on from probe). */
static const unsigned psc0_on[] = {
	HS_LPSC0_EDMA_CC0, 1, 2, HS_LPSC0_EMIFA, HS_LPSC0_SPI0, HS_LPSC0_MMCSD0, HS_LPSC0_AINTC,
	HS_LPSC0_ARM_RAMROM, HS_LPSC0_UART0, 10, 11, 12, HS_LPSC0_ARM,
};
static const unsigned psc1_on[] = {
	HS_LPSC1_USB0, HS_LPSC1_GPIO, HS_LPSC1_EMIF3, HS_LPSC1_SPI1, HS_LPSC1_I2C1, HS_LPSC1_UART1, HS_LPSC1_UART2,
	21, 24, 25, 26, 27, 28, 29, 30, 31,
};
/* Modules running even at TRM reset (always-on or boot-critical). */
static const unsigned psc0_cold_on[] = { HS_LPSC0_AINTC, HS_LPSC0_ARM_RAMROM, HS_LPSC0_ARM };

/* Creates one PSC region. */
static ER psc_create_one(unsigned id, uintptr_t phys, const unsigned *on, unsigned non)
{
	struct psc *p = &pscs[id];

	memset(p, 0, sizeof(*p));
	p->id = id;
	p->region = hs_region_add(&(struct hs_region_cfg){
		.name = id == 0U ? "PSC0" : "PSC1", .phys = phys, .size = 0x1000,
		.regs = psc_regs, .nregs = HS_ARRAY_SIZE(psc_regs), .power = HS_NO_PSC, .ctx = p });
	if (!p->region)
		return E_SYS;
	for (unsigned i = 0; i < non; i++) {
		p->state[on[i]] = HS_PSC_ENABLE;
		p->live[on[i]] = true;
		hs_reg_set(p->region, PSC_MDCTL0 + 4U * on[i], HS_PSC_ENABLE);
	}
	for (unsigned m = 0; m < PSC_NMOD; m++)
		hs_reg_set(p->region, PSC_MDSTAT0 + 4U * m, mdstat_of(p->state[m]));
	hs_space_power_changed();
	return E_OK;
}

static const bool *psc_live_flag(unsigned module);
static const char *psc_state_name(unsigned module);

ER hs_psc_create(bool cold)
{
	static const struct hs_power_controller controller = { psc_live_flag, psc_state_name };
	ER er;

	memset(watches, 0, sizeof(watches));
	hs_set_power_controller(&controller);
	if (cold)
		er = psc_create_one(0, HS_PSC0_BASE, psc0_cold_on, HS_ARRAY_SIZE(psc0_cold_on));
	else
		er = psc_create_one(0, HS_PSC0_BASE, psc0_on, HS_ARRAY_SIZE(psc0_on));
	if (er == E_OK)
		er = cold ? psc_create_one(1, HS_PSC1_BASE, NULL, 0)
			  : psc_create_one(1, HS_PSC1_BASE, psc1_on, HS_ARRAY_SIZE(psc1_on));
	return er;
}

void hs_psc_destroy(void)
{
	memset(pscs, 0, sizeof(pscs));
	memset(watches, 0, sizeof(watches));
	hs_space_power_changed();
}

/* The PSC and module number of an HS_PSCx_MODULE value; NULL if invalid. */
static struct psc *psc_of(unsigned module, unsigned *m)
{
	unsigned which = module >> 8;

	*m = module & 0xFFU;
	if ((which != 1U && which != 2U) || *m >= PSC_NMOD)
		return NULL;
	return &pscs[which - 1U];
}

enum hs_psc_state hs_psc_state(unsigned module)
{
	unsigned m;
	struct psc *p;

	if (module == HS_NO_PSC)
		return HS_PSC_ENABLE;
	p = psc_of(module, &m);
	return p ? p->state[m] : HS_PSC_SWRSTDISABLE;
}

/* The register space's power check: module's live flag, stable for the
 * process's life (the PSC state is static); every change of it is told to
 * the space (hs_space_power_changed). */
static const bool *psc_live_flag(unsigned module)
{
	static const bool always = true, never = false;
	unsigned m;
	struct psc *p;

	if (module == HS_NO_PSC)
		return &always;
	p = psc_of(module, &m);
	return p ? &p->live[m] : &never;
}

/* The state's name in the TRM's words, for bug reports. */
static const char *psc_state_name(unsigned module)
{
	switch (hs_psc_state(module)) {
	case HS_PSC_SWRSTDISABLE: return "SwRstDisable";
	case HS_PSC_SYNCRESET: return "SyncReset";
	case HS_PSC_DISABLE: return "Disable";
	default: return "Enable";
	}
}

bool hs_psc_enabled(unsigned module)
{
	return hs_psc_state(module) == HS_PSC_ENABLE;
}

void hs_psc_force(unsigned module, enum hs_psc_state st)
{
	unsigned m;
	struct psc *p = psc_of(module, &m);

	if (!p || (unsigned)st > HS_PSC_ENABLE) {
		rtos_host_bug("host_sim", "hs_psc_force: bad module 0x%x or state %d", module, (int)st);
		return;
	}
	if (p->region)
		hs_reg_update(p->region, PSC_MDCTL0 + 4U * m, MDCTL_NEXT, (uint32_t)st);
	psc_set_state(p, m, st);
}

int hs_psc_watch(unsigned module, hs_psc_watch_fn fn, void *ctx)
{
	for (unsigned i = 0; i < MAX_WATCHES; i++) {
		if (!watches[i].fn) {
			watches[i].module = module;
			watches[i].fn = fn;
			watches[i].ctx = ctx;
			return (int)i + 1;
		}
	}
	return 0;
}

void hs_psc_unwatch(int handle)
{
	if (handle > 0 && (unsigned)handle <= MAX_WATCHES)
		watches[handle - 1].fn = NULL;
}
