/*
 * pwm_hack.h — d_pwm's interface on the RTOS: extended service calls
 * (function codes PWM_FN_FIRST.. are d_pwm's) and the configuration fragment that
 * defines them.  Plain TOPPERS C: applications and the api include it.
 *
 * Every call checks its arguments and returns a TOPPERS code:
 *   E_PAR   bad length, opcode, port mask or value (the driver's -EINVAL)
 *   E_ID    port number out of range
 *   E_MACV  a buffer the calling task may not access (the driver's -EFAULT)
 *   E_OBJ   the driver is not loaded (its module_init failed)
 */
#ifndef EV3LX_PWM_HACK_H
#define EV3LX_PWM_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: PWM_FN_FIRST .. + PWM_FN_COUNT - 1
 * (EV3LX_FNCD_BASE moves every module's range, -DPWM_FN_FIRST=n this one; boot rejects ranges
 * that overlap another module's). */
#ifndef PWM_FN_FIRST
#define PWM_FN_FIRST (EV3LX_FNCD_BASE + 0)
#endif
#define PWM_FN_COUNT 15
#define PWM_FN_LAST  (PWM_FN_FIRST + PWM_FN_COUNT - 1)

#define PWM_FN_COMMAND     (PWM_FN_FIRST + 0)   /* (const void *cmd, uint_t len): one command written to /dev/lms_pwm */
#define PWM_FN_COMMAND2    (PWM_FN_FIRST + 1)   /* (cmd_a, len_a, cmd_b, len_b): two commands, the second only if the first succeeded */
#define PWM_FN_READ        (PWM_FN_FIRST + 2)   /* (char *buf, uint_t len): read() of /dev/lms_pwm ("R T "), returns bytes */
#define PWM_FN_BUSY        (PWM_FN_FIRST + 3)   /* (): the busy (ReadyStatus) port mask, 0..15 */
#define PWM_FN_SET_BUSY    (PWM_FN_FIRST + 4)   /* (uint_t mask): write() of one byte to /dev/lms_motor */
#define PWM_FN_MOTOR_DATA  (PWM_FN_FIRST + 5)   /* (uint_t port, struct lms_motor_data *out): one port's MOTORDATA */
#define PWM_FN_MOTOR_MAP   (PWM_FN_FIRST + 6)   /* (const struct lms_motor_data **out): address of MOTORDATA[4] */
#define PWM_FN_RUN         (PWM_FN_FIRST + 7)   /* (opcode, port, value): OUTPUT_SPEED or OUTPUT_POWER, then OUTPUT_START */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "lms_pwm.h"

/* The DEF_SVC rows (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg pwm_hack_cfg;

/* Writes one command of lms_pwm.h's protocol. */
static inline ER pwm_command(const void *cmd, uint_t len)
{
	return (ER)cal_svc(PWM_FN_COMMAND, (intptr_t)cmd, (intptr_t)len, 0, 0, 0);
}

/* Writes two commands in one call (e.g. OUTPUT_SPEED then OUTPUT_START). */
static inline ER pwm_command2(const void *cmd_a, uint_t len_a, const void *cmd_b, uint_t len_b)
{
	return (ER)cal_svc(PWM_FN_COMMAND2, (intptr_t)cmd_a, (intptr_t)len_a,
			   (intptr_t)cmd_b, (intptr_t)len_b, 0);
}

/*
 * Runs port (0..3) at value (-100..100) with opcode LMS_PWM_OUTPUT_SPEED
 * (regulated) or LMS_PWM_OUTPUT_POWER, then starts it: the two commands of
 * pwm_command2, with the values passed in registers (no buffer to probe).
 */
static inline ER pwm_run(uint8_t opcode, uint_t port, int value)
{
	return (ER)cal_svc(PWM_FN_RUN, (intptr_t)opcode, (intptr_t)port, (intptr_t)value, 0, 0);
}

/* Reads the "R T " status text; returns the byte count or an error. */
static inline ER_UINT pwm_read_status(char *buf, uint_t len)
{
	return cal_svc(PWM_FN_READ, (intptr_t)buf, (intptr_t)len, 0, 0, 0);
}

/* The mask of ports running a limited (STEP/TIME) command. */
static inline ER_UINT pwm_busy(void)
{
	return cal_svc(PWM_FN_BUSY, 0, 0, 0, 0, 0);
}

/* Marks ports busy (LEGO's /dev/lms_motor write). */
static inline ER pwm_set_busy(uint_t mask)
{
	return (ER)cal_svc(PWM_FN_SET_BUSY, (intptr_t)mask, 0, 0, 0, 0);
}

/* Copies port's (0..3) tacho counts, speed and sensor counts. */
static inline ER pwm_motor_data(uint_t port, struct lms_motor_data *out)
{
	return (ER)cal_svc(PWM_FN_MOTOR_DATA, (intptr_t)port, (intptr_t)out, 0, 0, 0);
}

/* The shared MOTORDATA[4] (refreshed every 2 ms), for callers allowed to read it. */
static inline ER pwm_motor_map(const struct lms_motor_data **out)
{
	return (ER)cal_svc(PWM_FN_MOTOR_MAP, (intptr_t)out, 0, 0, 0, 0);
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_PWM_HACK_H */
