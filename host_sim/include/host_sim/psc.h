/*
 * psc.h — PSC0/PSC1 module power states, as models see them.  Host only.
 *
 * A driver enables a module by writing MDCTLn.NEXT and PTCMD.GO; the
 * transition completes at once (MDSTAT follows).  Regions declared with
 * .power = HS_PSCx_MODULE(n) are dead (every access is a bug report) while
 * the module is not in the Enable state.
 */
#ifndef HOST_SIM_PSC_H
#define HOST_SIM_PSC_H

#include <stdbool.h>
#include "host_sim/regs.h"

/* LPSC numbers (DA850). */
#define HS_LPSC0_EDMA_CC0   0U
#define HS_LPSC0_EMIFA      3U
#define HS_LPSC0_SPI0       4U
#define HS_LPSC0_MMCSD0     5U
#define HS_LPSC0_AINTC      6U
#define HS_LPSC0_ARM_RAMROM 7U
#define HS_LPSC0_UART0      9U
#define HS_LPSC0_PRU        13U
#define HS_LPSC0_ARM        14U
#define HS_LPSC1_USB0       1U
#define HS_LPSC1_GPIO       3U
#define HS_LPSC1_EMIF3      6U
#define HS_LPSC1_MCASP0     7U
#define HS_LPSC1_SPI1       10U
#define HS_LPSC1_I2C1       11U
#define HS_LPSC1_UART1      12U
#define HS_LPSC1_UART2      13U
#define HS_LPSC1_EHRPWM     17U
#define HS_LPSC1_ECAP       20U

/* MDSTAT/MDCTL states. */
enum hs_psc_state {
	HS_PSC_SWRSTDISABLE = 0,
	HS_PSC_SYNCRESET = 1,
	HS_PSC_DISABLE = 2,
	HS_PSC_ENABLE = 3,
};

/* Current state of module (HS_PSCx_MODULE(n)); HS_NO_PSC is always enabled. */
enum hs_psc_state hs_psc_state(unsigned module);
/* true if module is in the Enable state. */
bool hs_psc_enabled(unsigned module);
/* Forces a state without a register access (test setup). */
void hs_psc_force(unsigned module, enum hs_psc_state st);

/* Called after module changed state (a model may reset itself on disable). */
typedef void (*hs_psc_watch_fn)(void *ctx, unsigned module, enum hs_psc_state old, enum hs_psc_state now);
/* Calls fn on every state change of module; returns a handle > 0 or 0. */
int hs_psc_watch(unsigned module, hs_psc_watch_fn fn, void *ctx);
void hs_psc_unwatch(int handle);

#endif /* HOST_SIM_PSC_H */
