/*
 * pwm_svc.c — d_pwm's interface on the RTOS: the module's extended service
 * calls (pwm_hack.h) and its configuration fragment.  A call that passes the
 * caller's memory reaches the driver only through its file operations, so the
 * driver's own checks (lengths, masks, copy_*_user against the caller's
 * domain) guard it.  The hot path, PWM_FN_RUN, takes its values in registers:
 * no user memory is touched, and the two commands built here go to the
 * handlers d_pwm's write() dispatches to (pwm_module_run), which check the
 * mask and the value as for a write().  The driver is in pwm_hack.c.
 */
#include "hack_svc.h"
#include "pwm_hack.h"
#include "pwm_module.h"

/* Writes one command of len bytes from the caller's memory. */
static ER pwm_write_command(intptr_t cmd, intptr_t len)
{
	if (len <= 0 || len > LMS_PWM_CMD_MAX)
		return E_PAR;
	return lx_errno_to_er(lx_dev_write(pwm_file, (const char __user *)cmd, (size_t)len, NULL));
}

/* PWM_FN_COMMAND: one command. */
ER_UINT svc_pwm_command(intptr_t cmd, intptr_t len, intptr_t p3, intptr_t p4,
			       intptr_t p5, ID cdmid)
{
	return pwm_write_command(cmd, len);
}

/* PWM_FN_COMMAND2: two commands; the second runs only if the first succeeded. */
ER_UINT svc_pwm_command2(intptr_t cmd_a, intptr_t len_a, intptr_t cmd_b,
				intptr_t len_b, intptr_t p5, ID cdmid)
{
	ER ercd = pwm_write_command(cmd_a, len_a);

	return ercd == E_OK ? pwm_write_command(cmd_b, len_b) : ercd;
}

/*
 * PWM_FN_RUN: OUTPUT_SPEED or OUTPUT_POWER of value on port, then OUTPUT_START.
 * The commands are built here and handed to the handlers d_pwm's write()
 * dispatches them to (cmd_speed or cmd_power, then cmd_start), which check the
 * port mask and the value and take the driver's lock as for a write().
 */
ER_UINT svc_pwm_run(intptr_t opcode, intptr_t port, intptr_t value, intptr_t p4,
			   intptr_t p5, ID cdmid)
{
	u8 set[3], start[2];
	int ret;

	if (opcode != LMS_PWM_OUTPUT_SPEED && opcode != LMS_PWM_OUTPUT_POWER)
		return E_PAR;
	if (port < 0 || port >= LMS_PWM_PORTS)
		return E_ID;
	if (value < S8_MIN || value > S8_MAX)	/* the command carries an s8 */
		return E_PAR;
	if (!pwm_file)
		return E_OBJ;
	set[0] = (u8)opcode;
	set[1] = start[1] = (u8)(1U << port);
	set[2] = (u8)(s8)value;
	start[0] = LMS_PWM_OUTPUT_START;
	ret = pwm_module_run(set, start);
	return ret ? lx_errno_to_er(ret) : E_OK;
}

/* PWM_FN_READ: the "R T " status text into the caller's buffer; the byte count. */
ER_UINT svc_pwm_read(intptr_t buf, intptr_t len, intptr_t p3, intptr_t p4,
			    intptr_t p5, ID cdmid)
{
	ssize_t ret;

	if (len < 0 || len > INT_MAX)
		return E_PAR;
	ret = lx_dev_read(pwm_file, (char __user *)buf, (size_t)len, NULL);
	return ret < 0 ? lx_errno_to_er(ret) : (ER_UINT)ret;
}

/* PWM_FN_BUSY: the ReadyStatus mask (a byte the driver updates atomically). */
ER_UINT svc_pwm_busy(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4,
			    intptr_t p5, ID cdmid)
{
	return pwm_file ? (ER_UINT)pwm_module_ready_status() : E_OBJ;
}

/* PWM_FN_SET_BUSY: ORs mask into the busy masks through /dev/lms_motor. */
ER_UINT svc_pwm_set_busy(intptr_t mask, intptr_t p2, intptr_t p3, intptr_t p4,
				intptr_t p5, ID cdmid)
{
	u8 byte = (u8)mask;

	if (mask < 0 || mask > LMS_PWM_PORT_MASK)
		return E_PAR;
	return lx_errno_to_er(kernel_write(motor_file, &byte, 1, NULL));
}

/* PWM_FN_MOTOR_DATA: copies one port's MOTORDATA to the caller. */
ER_UINT svc_pwm_motor_data(intptr_t port, intptr_t out, intptr_t p3, intptr_t p4,
				  intptr_t p5, ID cdmid)
{
	if (port < 0 || port >= LMS_PWM_PORTS)
		return E_ID;
	if (!motor_map)
		return E_OBJ;
	if (copy_to_user((void __user *)out, &motor_map[port], sizeof(motor_map[port])))
		return E_MACV;
	return E_OK;
}

/* PWM_FN_MOTOR_MAP: the address of the shared MOTORDATA[4]. */
ER_UINT svc_pwm_motor_map(intptr_t out, intptr_t p2, intptr_t p3, intptr_t p4,
				 intptr_t p5, ID cdmid)
{
	if (!motor_map)
		return E_OBJ;
	if (copy_to_user((void __user *)out, &motor_map, sizeof(motor_map)))
		return E_MACV;
	return E_OK;
}

static const struct rtos_svc_cfg pwm_svcs[] = {
	{ PWM_FN_COMMAND,    svc_pwm_command,    256 },
	{ PWM_FN_COMMAND2,   svc_pwm_command2,   256 },
	{ PWM_FN_READ,       svc_pwm_read,       256 },
	{ PWM_FN_BUSY,       svc_pwm_busy,       64 },
	{ PWM_FN_SET_BUSY,   svc_pwm_set_busy,   256 },
	{ PWM_FN_MOTOR_DATA, svc_pwm_motor_data, 256 },
	{ PWM_FN_MOTOR_MAP,  svc_pwm_motor_map,  256 },
	{ PWM_FN_RUN,        svc_pwm_run,        256 },
};

const struct rtos_cfg pwm_hack_cfg = {
	.name = "pwm_hack",
	.svcs = RTOS_TABLE(pwm_svcs),
	.svc_first = PWM_FN_FIRST, .svc_count = PWM_FN_COUNT,
};
