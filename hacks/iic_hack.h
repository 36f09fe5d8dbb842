/*
 * iic_hack.h — d_iic's interface on the RTOS: extended service calls
 * (function codes IIC_FN_FIRST.. are d_iic's) and the configuration fragment
 * that defines them.  Plain TOPPERS C: applications and the api include it.
 *
 * A port is handed to d_iic with iic_svc_start (LEGO's SET_CONN with the NXT
 * I2C connection); the driver probes the sensor (iic_svc_type_info gives the
 * strings), iic_svc_set gives the setup and poll strings, and the answers
 * arrive in the shared memory's raw ring (iic_svc_map; lms_iic_sample below)
 * without further calls.  iic_svc_setup runs one raw transaction (LEGO's
 * IIC_SETUP: call it again until the result is not LMS_IIC_BUSY).
 *
 * Every call checks its arguments and returns a TOPPERS code:
 *   E_ID    port number out of range (0..3 are ports 1..4)
 *   E_PAR   a length out of range (strings 0..4 bytes, reads -32..32, writes 1..32)
 *   E_MACV  a buffer the calling task may not access
 *   E_OBJ   the port is not started (type info, setup), or the driver is not loaded
 *   E_CTX   called from non-task context
 */
#ifndef EV3LX_IIC_HACK_H
#define EV3LX_IIC_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: IIC_FN_FIRST .. + IIC_FN_COUNT - 1
 * (EV3LX_FNCD_BASE moves every module's range, -DIIC_FN_FIRST=n this one; boot rejects ranges
 * that overlap another module's). */
#ifndef IIC_FN_FIRST
#define IIC_FN_FIRST (EV3LX_FNCD_BASE + 95)
#endif
#define IIC_FN_COUNT 16
#define IIC_FN_LAST  (IIC_FN_FIRST + IIC_FN_COUNT - 1)

#define IIC_FN_START     (IIC_FN_FIRST + 0)  /* (uint_t port, uint_t mode): NXT I2C on the port */
#define IIC_FN_STOP      (IIC_FN_FIRST + 1)  /* (uint_t port): give the port back */
#define IIC_FN_TYPE_INFO (IIC_FN_FIRST + 2)  /* (uint_t port, struct lms_iic_str *out): probed strings */
#define IIC_FN_SET       (IIC_FN_FIRST + 3)  /* (const struct lms_iic_str *in): setup and poll strings */
#define IIC_FN_SETUP     (IIC_FN_FIRST + 4)  /* (struct lms_iic_dat *io): one IIC_SETUP round */
#define IIC_FN_MAP       (IIC_FN_FIRST + 5)  /* (const struct lms_iic **out): the shared memory */
#define IIC_FN_STATE     (IIC_FN_FIRST + 6)  /* (uint_t port): the port's LMS_IIC_STATE_* */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "lms_iic.h"

/* The DEF_SVC rows (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg iic_hack_cfg;

/* Hands input port (0..3) to d_iic (mode: a changed mode re-sends the setup string). */
static inline ER iic_svc_start(uint_t port, uint_t mode)
{
	return (ER)cal_svc(IIC_FN_START, (intptr_t)port, (intptr_t)mode, 0, 0, 0);
}

/* Stops d_iic on the port (its pins float again). */
static inline ER iic_svc_stop(uint_t port)
{
	return (ER)cal_svc(IIC_FN_STOP, (intptr_t)port, 0, 0, 0, 0);
}

/* The manufacturer and sensor type strings the probe found (empty before). */
static inline ER iic_svc_type_info(uint_t port, struct lms_iic_str *out)
{
	return (ER)cal_svc(IIC_FN_TYPE_INFO, (intptr_t)port, (intptr_t)out, 0, 0, 0);
}

/* Auto-polling of in->port: setup string once, then the poll string every in->time ms. */
static inline ER iic_svc_set(const struct lms_iic_str *in)
{
	return (ER)cal_svc(IIC_FN_SET, (intptr_t)in, 0, 0, 0, 0);
}

/* One IIC_SETUP round: io->result is LMS_IIC_BUSY until the answer is in io->rd_data. */
static inline ER iic_svc_setup(struct lms_iic_dat *io)
{
	return (ER)cal_svc(IIC_FN_SETUP, (intptr_t)io, 0, 0, 0, 0);
}

/* The driver's shared memory (LEGO's IIC), read-only for callers. */
static inline ER iic_svc_map(const struct lms_iic **out)
{
	return (ER)cal_svc(IIC_FN_MAP, (intptr_t)out, 0, 0, 0, 0);
}

/* The port's state (LMS_IIC_STATE_*), or an error code. */
static inline ER_UINT iic_svc_state(uint_t port)
{
	return cal_svc(IIC_FN_STATE, (intptr_t)port, 0, 0, 0, 0);
}

/* The newest polled answer of port, or NULL if there is none yet (lock-free: the driver fills
 * a slot before publishing its index and reuses it only 300 samples later). */
static inline const int8_t *lms_iic_sample(const struct lms_iic *shm, unsigned int port)
{
	if (!(*(const volatile int8_t *)&shm->status[port] & LMS_IIC_DATA_READY))
		return (const int8_t *)0;
	return shm->raw[port][*(const volatile uint16_t *)&shm->actual[port]];
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_IIC_HACK_H */
