/*
 * ev3api_cyc.h — EV3 cyclic handlers (included by ev3api.h).
 *
 * EV3_CRE_CYC(ID, { attr, exinf, handler, period_ms, phase_ms }) in app.cfg
 * creates, under ID, a kernel cyclic handler that wakes a task of the app's
 * domain which runs handler(exinf): the handler body is in task context and
 * may call any task service.  These start and stop it; their checked form is
 * the kernel's sta_cyc/stp_cyc on the same ID.
 */
#ifndef EV3API_CYC_H
#define EV3API_CYC_H

#ifdef __cplusplus
extern "C" {
#endif

#include "kernel.h"

/* Starts the EV3 cyclic handler ID (its first call one period from now,
 * unless it has a phase).  E_ID, E_NOEXS, E_OACV, E_CTX. */
ER ev3_sta_cyc(ID ev3cycid);
/* Stops it; a call in progress finishes.  E_ID, E_NOEXS, E_OACV, E_CTX. */
ER ev3_stp_cyc(ID ev3cycid);

#ifdef __cplusplus
}
#endif

#endif /* EV3API_CYC_H */
