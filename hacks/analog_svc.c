/*
 * analog_svc.c — d_analog's interface on the RTOS: the module's extended
 * service calls (analog_hack.h) and its configuration fragment.  Calls reach
 * the driver through its file operations and its mapped ANALOG area; the
 * driver's own checks (lengths, pin commands, copy_*_user against the
 * caller's domain) guard them.
 * The driver is in analog_hack.c.
 */
#include "hack_svc.h"
#include "analog_hack.h"
#include "analog_module.h"

/* ANALOG_FN_MAP: the address of the shared ANALOG area. */
ER_UINT svc_analog_map(intptr_t out, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5,
			      ID cdmid)
{
	if (sns_ctx())
		return E_CTX;
	if (!analog_map_addr)
		return E_OBJ;
	if (copy_to_user((void __user *)out, &analog_map_addr, sizeof(analog_map_addr)))
		return E_MACV;
	return E_OK;
}

/* ANALOG_FN_INPUT: one input port's detected device and pin voltages. */
ER_UINT svc_analog_input(intptr_t port, intptr_t out, intptr_t p3, intptr_t p4,
				intptr_t p5, ID cdmid)
{
	const struct lms_analog *a = analog_map_addr;
	struct analog_input_state st;

	if (sns_ctx())
		return E_CTX;
	if (port < 0 || port >= LMS_ANALOG_INPUTS)
		return E_ID;
	if (!a)
		return E_OBJ;
	st.type = a->in_dcm[port];
	st.conn = a->in_conn[port];
	st.pin1_mv = lms_analog_raw_to_mv(READ_ONCE(a->in_pin1[port]));
	st.pin6_mv = lms_analog_raw_to_mv(READ_ONCE(a->in_pin6[port]));
	return copy_to_user((void __user *)out, &st, sizeof(st)) ? E_MACV : E_OK;
}

/* ANALOG_FN_OUTPUT: one output port's detected device and pin 5 voltage. */
ER_UINT svc_analog_output(intptr_t port, intptr_t out, intptr_t p3, intptr_t p4,
				 intptr_t p5, ID cdmid)
{
	const struct lms_analog *a = analog_map_addr;
	struct analog_output_state st;

	if (sns_ctx())
		return E_CTX;
	if (port < 0 || port >= LMS_ANALOG_OUTPUTS)
		return E_ID;
	if (!a)
		return E_OBJ;
	st.type = a->out_dcm[port];
	st.conn = a->out_conn[port];
	st.pin5_mv = lms_analog_raw_to_mv(READ_ONCE(a->out_pin5[port]));
	return copy_to_user((void __user *)out, &st, sizeof(st)) ? E_MACV : E_OK;
}

/* ANALOG_FN_DCM_WRITE: exactly one command per input port, from the caller's memory. */
ER_UINT svc_analog_dcm_write(intptr_t cmd, intptr_t len, intptr_t p3, intptr_t p4,
				    intptr_t p5, ID cdmid)
{
	if (sns_ctx())
		return E_CTX;
	if (len != LMS_DCM_WRITE_SIZE)
		return E_PAR;
	return lx_errno_to_er(lx_dev_write(dcm_file, (const char __user *)cmd, (size_t)len, NULL));
}

/* Reads a device from its start into the caller's buffer; the byte count. */
static ER_UINT analog_read_from_start(struct file *file, intptr_t buf, intptr_t len)
{
	loff_t pos = 0;
	ssize_t ret;

	if (sns_ctx())
		return E_CTX;
	if (len < 0 || len > S32_MAX)		/* the count must fit the ER_UINT result */
		return E_PAR;
	ret = lx_dev_read(file, (char __user *)buf, (size_t)len, &pos);
	return ret < 0 ? lx_errno_to_er(ret) : (ER_UINT)ret;
}

/* ANALOG_FN_DCM_READ: in_dcm[4], out_dcm[4], '\r', 0. */
ER_UINT svc_analog_dcm_read(intptr_t buf, intptr_t len, intptr_t p3, intptr_t p4,
				   intptr_t p5, ID cdmid)
{
	return analog_read_from_start(dcm_file, buf, len);
}

/* ANALOG_FN_TEXT: a fresh text dump. */
ER_UINT svc_analog_text(intptr_t buf, intptr_t len, intptr_t p3, intptr_t p4, intptr_t p5,
			       ID cdmid)
{
	return analog_read_from_start(analog_file, buf, len);
}

static const struct rtos_svc_cfg analog_svcs[] = {
	{ ANALOG_FN_MAP,       svc_analog_map,       256 },
	{ ANALOG_FN_INPUT,     svc_analog_input,     256 },
	{ ANALOG_FN_OUTPUT,    svc_analog_output,    256 },
	{ ANALOG_FN_DCM_WRITE, svc_analog_dcm_write, 256 },
	{ ANALOG_FN_DCM_READ,  svc_analog_dcm_read,  256 },
	{ ANALOG_FN_TEXT,      svc_analog_text,      1024 },
};

const struct rtos_cfg analog_hack_cfg = {
	.name = "analog_hack",
	.svcs = RTOS_TABLE(analog_svcs),
	.svc_first = ANALOG_FN_FIRST, .svc_count = ANALOG_FN_COUNT,
};
