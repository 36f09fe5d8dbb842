/*
 * core_parts.h — constructors of the core peripherals and of the trap
 * handler, called by board.c (not part of the public API).
 */
#ifndef HOST_SIM_CORE_PARTS_H
#define HOST_SIM_CORE_PARTS_H

#include <stdbool.h>
#include "t_stddef.h"
#include "host_sim/psc.h"

/* Each creates its region(s) in the state U-Boot/Linux leave (cold: TRM reset). */
ER hs_psc_create(bool cold);
void hs_psc_destroy(void);
/* Where module's state is kept (hs_psc_state's answer), for the access path's power check. */
const enum hs_psc_state *hs_psc_state_ref(unsigned module);
ER hs_syscfg_create(bool cold);
void hs_syscfg_destroy(void);
ER hs_aintc_create(bool cold);
void hs_aintc_destroy(void);
ER hs_gpio_create(bool cold, bool pinmux_check);
void hs_gpio_destroy(void);
ER hs_timer64p3_create(bool cold);
void hs_timer64p3_destroy(void);
ER hs_pllc_create(bool cold);

/* Installs the SIGSEGV handler that emulates plain pointer accesses to the
 * window space (x86-64), or that reports them clearly elsewhere.  Returns
 * true if accesses are emulated. */
bool hs_trap_install(void);
void hs_trap_remove(void);
/* Why emulation is unavailable ("" if available). */
const char *hs_trap_reason(void);

/* Forgets trace signals and closes files (board shutdown). */
void hs_trace_reset(void);

#endif /* HOST_SIM_CORE_PARTS_H */
