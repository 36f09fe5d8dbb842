/*
 * timer64.h — TIMER64P3 of the AM1808, the free-running counter LEGO's
 * drivers time with.  Host only.
 *
 * TIMER64P3 is modelled from its registers: its input clock is the ASYNC3
 * domain, HS_PLL1_SYSCLK2_HZ = 132 MHz as LEGO configures PLL1 (24 MHz x 22
 * / 2 / 2); in dual 32-bit unchained mode TIM34 counts input / (TDDR34 + 1)
 * (LEGO: TGCR = 0x3306 → 33 MHz, so TIM34 >> 8 ticks every ~7.76 us) and
 * TIM12 counts the input clock.  Counters run while TCR.ENAMODE is
 * continuous and the half is out of reset, wrap after PRD, and are computed
 * from the virtual clock at each read — exact at any instant.
 */
#ifndef HOST_SIM_TIMER64_H
#define HOST_SIM_TIMER64_H

#include <stdint.h>

/* TIMER64P3 counters as a read at this virtual instant would return them. */
uint32_t hs_timer64p3_tim12(void);
uint32_t hs_timer64p3_tim34(void);
/* Frequency TIM34 counts at under the current TGCR/TCR (0 if stopped). */
uint64_t hs_timer64p3_tim34_hz(void);

/*
 * TIMER64P1 counts the 24 MHz oscillator and pulses TINT12_1 / TINT34_1
 * (AINTC 23 / 24) when a half matches its period with INTCTLSTAT's
 * PRDINTENxx set: the tick of the NXT I2C bit engine.  Its TIM34 rate now
 * (0 if stopped).
 */
uint64_t hs_timer64p1_tim34_hz(void);

#endif /* HOST_SIM_TIMER64_H */
