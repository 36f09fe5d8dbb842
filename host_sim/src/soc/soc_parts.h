/*
 * soc_parts.h — constructors of the AM1808 peripherals every board has,
 * called by the board assembly (board.c); not part of the public API.
 */
#ifndef HOST_SIM_SOC_PARTS_H
#define HOST_SIM_SOC_PARTS_H

#include <stdbool.h>
#include "t_stddef.h"

/* Each creates its region(s) in the state U-Boot/Linux leave (cold: TRM reset). */
ER hs_psc_create(bool cold);
void hs_psc_destroy(void);
ER hs_syscfg_create(bool cold);
void hs_syscfg_destroy(void);
ER hs_aintc_create(bool cold);
void hs_aintc_destroy(void);
ER hs_gpio_create(bool cold, bool pinmux_check);
void hs_gpio_destroy(void);
ER hs_timer64p3_create(bool cold);
void hs_timer64p3_destroy(void);
ER hs_timer64p1_create(bool cold);
void hs_timer64p1_destroy(void);
ER hs_pllc_create(bool cold);

#endif /* HOST_SIM_SOC_PARTS_H */
