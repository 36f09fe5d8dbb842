/*
 * sil_dly.c — sil_dly_nse for the AM1808 (ARM926EJ-S at 300 MHz): a
 * calibrated busy loop, as TOPPERS targets provide it.
 *
 * Calibration: the loop body is SUBS (1 cycle) + taken BNE (3 cycles) = 4
 * cycles per iteration with the loop in the I-cache, 13.33 ns at 300 MHz.
 * The iteration count is rounded up from (dlytim - SIL_DLY_OVERHEAD_NS) / 13.33
 * (multiplying by 77/1024, i.e. dividing by 13.30, never by more), so the
 * delay is at least dlytim; a slower clock or cache misses only lengthen it.
 */
#include "sil.h"

/* Call, argument checks and the multiply: about 30 cycles. */
#define SIL_DLY_OVERHEAD_NS 100U

/* Busy-waits at least dlytim ns. */
void sil_dly_nse(ulong_t dlytim)
{
	uint32_t loops;

	if (dlytim <= SIL_DLY_OVERHEAD_NS)
		return;
	loops = (uint32_t)((((uint64_t)(dlytim - SIL_DLY_OVERHEAD_NS)) * 77U + 1023U) >> 10);
	if (loops == 0)
		return;
	__asm__ volatile("1:\n\tsubs %0, %0, #1\n\tbne 1b" : "+r"(loops) : : "cc");
}
