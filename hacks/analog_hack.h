/*
 * analog_hack.h — d_analog's interface on the RTOS: extended service calls
 * (function codes ANALOG_FN_FIRST.. are d_analog's) and the configuration fragment that
 * defines them.  Plain TOPPERS C: applications and the api include it.
 *
 * Every call checks its arguments and returns a TOPPERS code:
 *   E_ID    port number out of range
 *   E_PAR   bad length or pin command (the driver's -EINVAL)
 *   E_MACV  a buffer the calling task may not access (the driver's -EFAULT)
 *   E_NOSPT a request d_analog does not implement (NXT colour commands)
 *   E_OBJ   the driver is not loaded (its module_init failed)
 *   E_CTX   called from non-task context
 */
#ifndef EV3LX_ANALOG_HACK_H
#define EV3LX_ANALOG_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: ANALOG_FN_FIRST .. + ANALOG_FN_COUNT - 1
 * (EV3LX_FNCD_BASE moves every module's range, -DANALOG_FN_FIRST=n this one; boot rejects ranges
 * that overlap another module's). */
#ifndef ANALOG_FN_FIRST
#define ANALOG_FN_FIRST (EV3LX_FNCD_BASE + 15)
#endif
#define ANALOG_FN_COUNT 16
#define ANALOG_FN_LAST  (ANALOG_FN_FIRST + ANALOG_FN_COUNT - 1)

#define ANALOG_FN_MAP        (ANALOG_FN_FIRST + 0)  /* (const struct lms_analog **out): address of ANALOG */
#define ANALOG_FN_INPUT      (ANALOG_FN_FIRST + 1)  /* (uint_t port, struct analog_input_state *out) */
#define ANALOG_FN_OUTPUT     (ANALOG_FN_FIRST + 2)  /* (uint_t port, struct analog_output_state *out) */
#define ANALOG_FN_DCM_WRITE  (ANALOG_FN_FIRST + 3)  /* (const char *cmd, uint_t len): write() of /dev/lms_dcm */
#define ANALOG_FN_DCM_READ   (ANALOG_FN_FIRST + 4)  /* (char *buf, uint_t len): read() of /dev/lms_dcm, returns bytes */
#define ANALOG_FN_TEXT       (ANALOG_FN_FIRST + 5)  /* (char *buf, uint_t len): the text dump from its start, returns bytes */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "lms_analog.h"

/* An input port now: what detection found and the pin voltages. */
struct analog_input_state {
	int8_t type;                /* LMS_TYPE_* */
	int8_t conn;                /* LMS_CONN_* */
	uint16_t pin1_mv;
	uint16_t pin6_mv;
};

/* An output port now. */
struct analog_output_state {
	int8_t type;                /* LMS_TYPE_* */
	int8_t conn;                /* LMS_CONN_* */
	uint16_t pin5_mv;
};

/* The DEF_SVC rows (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg analog_hack_cfg;

/* The shared ANALOG area (sampled every 1 ms), for callers allowed to read it. */
static inline ER analog_map(const struct lms_analog **out)
{
	return (ER)cal_svc(ANALOG_FN_MAP, (intptr_t)out, 0, 0, 0, 0);
}

/* Copies input port's (0..3) detected device and pin voltages. */
static inline ER analog_input(uint_t port, struct analog_input_state *out)
{
	return (ER)cal_svc(ANALOG_FN_INPUT, (intptr_t)port, (intptr_t)out, 0, 0, 0);
}

/* Copies output port's (0..3 = A..D) detected device and pin 5 voltage. */
static inline ER analog_output(uint_t port, struct analog_output_state *out)
{
	return (ER)cal_svc(ANALOG_FN_OUTPUT, (intptr_t)port, (intptr_t)out, 0, 0, 0);
}

/* Writes LMS_DCM_WRITE_SIZE pin commands, one per input port (lms_analog.h). */
static inline ER analog_dcm_write(const char *cmd, uint_t len)
{
	return (ER)cal_svc(ANALOG_FN_DCM_WRITE, (intptr_t)cmd, (intptr_t)len, 0, 0, 0);
}

/* Sets one input port's pins (LMS_DCM_FLOAT or LMS_DCM_PINS(bits)), others unchanged. */
static inline ER analog_set_pins(uint_t port, char cmd)
{
	char all[LMS_DCM_WRITE_SIZE] = { LMS_DCM_KEEP, LMS_DCM_KEEP, LMS_DCM_KEEP, LMS_DCM_KEEP };

	if (port >= LMS_ANALOG_INPUTS)
		return E_ID;
	all[port] = cmd;
	return analog_dcm_write(all, sizeof(all));
}

/* Reads in_dcm[4], out_dcm[4], '\r', 0 (len >= LMS_DCM_READ_SIZE); returns the byte count. */
static inline ER_UINT analog_dcm_read(char *buf, uint_t len)
{
	return cal_svc(ANALOG_FN_DCM_READ, (intptr_t)buf, (intptr_t)len, 0, 0, 0);
}

/* Reads the driver's text dump (truncated to len); returns the byte count. */
static inline ER_UINT analog_text(char *buf, uint_t len)
{
	return cal_svc(ANALOG_FN_TEXT, (intptr_t)buf, (intptr_t)len, 0, 0, 0);
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_ANALOG_HACK_H */
