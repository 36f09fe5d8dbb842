/*
 * syscfg.h — SYSCFG0/SYSCFG1 as models see them: pin multiplexing, chip
 * configuration (CFGCHIP0..4) and the pull-up/down enables.  Host only.
 *
 * SYSCFG0's protected registers (PINMUXn, CFGCHIPn, ...) take a write only
 * between the KICK0R/KICK1R unlock and the next lock; a write while locked is
 * dropped, as on the chip, and reported as a bug.
 */
#ifndef HOST_SIM_SYSCFG_H
#define HOST_SIM_SYSCFG_H

#include <stdbool.h>
#include <stdint.h>

/* KICK0R/KICK1R offsets in SYSCFG0 and the values that unlock the protected
 * registers (AM1808 TRM, SYSCFG chapter, "Kick Registers"). */
#define HS_SYSCFG0_KICK0  0x38U
#define HS_SYSCFG0_KICK1  0x3CU
#define HS_KICK0_UNLOCK   0x83E70B13U
#define HS_KICK1_UNLOCK   0x95A4F1E0U
/* CFGCHIPn offset in SYSCFG0 (AM1808 TRM, SYSCFG chapter: CFGCHIP0 at 0x17C). */
#define HS_SYSCFG0_CFGCHIP(n)	(0x17CU + 4U * (unsigned)(n))
#define HS_CFGCHIP1_TBCLKSYNC (1U << 12)

/* Current PINMUXn (0..19). */
uint32_t hs_syscfg_pinmux(unsigned n);
/* PINMUXn's stored value, for a model that consults it on every pin change
 * (valid while the board exists); NULL without SYSCFG0 or for n >= 20. */
const uint32_t *hs_syscfg_pinmux_ptr(unsigned n);
/* The 4-bit function field of PINMUXn at bit shift (0, 4, ... 28). */
unsigned hs_syscfg_pinmux_field(unsigned n, unsigned shift);
/* Current CFGCHIPn (0..4). */
uint32_t hs_syscfg_cfgchip(unsigned n);
/* true if CFGCHIP1.TBCLKSYNC is set (eHRPWM time bases run). */
bool hs_syscfg_tbclksync(void);
/* true while SYSCFG0 is unlocked. */
bool hs_syscfg_unlocked(void);
/* SYSCFG1 PUPD_ENA / PUPD_SEL. */
uint32_t hs_syscfg_pupd_ena(void);
uint32_t hs_syscfg_pupd_sel(void);

/* Called after a SYSCFG0 register changed: its offset (0x120+4n for PINMUXn,
 * 0x17C+4n for CFGCHIPn), old and new value. */
typedef void (*hs_syscfg_watch_fn)(void *ctx, uint32_t offset, uint32_t old, uint32_t now);
/* Calls fn on every change; returns a handle > 0 or 0. */
int hs_syscfg_watch(hs_syscfg_watch_fn fn, void *ctx);
void hs_syscfg_unwatch(int handle);

#endif /* HOST_SIM_SYSCFG_H */
