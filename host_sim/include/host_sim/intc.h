/*
 * intc.h — the AINTC as models see it: interrupt requests of peripherals.
 * Host only.
 *
 * rtos_stub is the CPU side (enable state per CFG_INT/ena_int, masking,
 * priorities, ISR dispatch); the AINTC region is the register view of the
 * same lines (ESR/ECR, SRSR/SECR, SISR/SICR, EISR/EICR, CMR, HIPIR...), so a
 * driver that touches the AINTC sees the state rtos_stub acts on.  Models
 * raise requests through these calls, which also trace the line.
 * System interrupt numbers are DA850's (GPIO bank b: 42+b, UART0 25, UART1 53).
 */
#ifndef HOST_SIM_INTC_H
#define HOST_SIM_INTC_H

#include <stdbool.h>
#include "kernel.h"

#define HS_INTC_NSYSINT  101U   /* system interrupts 0..100 */

/* An event (pulse) on system interrupt sysint: latched until delivered or cleared. */
void hs_intc_raise(INTNO sysint);
/* Level request of a peripheral (delivered while asserted). */
void hs_intc_set_level(INTNO sysint, bool asserted);
/* Status (raw, latched) of sysint: what SRSR reads. */
bool hs_intc_pending(INTNO sysint);
/* AINTC channel of sysint (CMR view, derived from the CFG_INT priority). */
unsigned hs_intc_channel(INTNO sysint);

#endif /* HOST_SIM_INTC_H */
