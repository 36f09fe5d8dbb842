/*
 * iic_svc.c — d_iic's interface on the RTOS: the module's extended
 * service calls (iic_hack.h) and its configuration fragment.  The calls reach
 * the driver through its file operations, so its own checks guard them after
 * the ones here; the port state is read from the driver's own table
 * (iic_module_port_state), as its read() prints it.
 * The driver is in iic_hack.c.
 */
#include "hack_svc.h"
#include "iic_hack.h"
#include "iic_module.h"

/* Common checks: task context, port 0..3, the driver up.  E_OK or the error. */
static ER iic_hack_check(intptr_t port)
{
	if (sns_ctx())
		return E_CTX;
	if (port < 0 || port >= LMS_IIC_PORTS)
		return E_ID;
	return iic_hack_file() ? E_OK : E_OBJ;
}

static bool iic_hack_port_running(intptr_t port)
{
	u8 state = iic_module_port_state((unsigned int)port);

	return state != LMS_IIC_STATE_IDLE && state != LMS_IIC_STATE_EXIT;
}

/* SET_CONN: @port gets @conn and @mode, the other ports keep what they have. */
static ER iic_hack_set_conn(intptr_t port, s8 conn, s8 mode)
{
	struct lms_iic_devcon dc;
	unsigned int i;

	for (i = 0; i < LMS_IIC_PORTS; i++) {
		dc.connection[i] = iic_hack_port_running(i) ? LMS_CONN_NXT_IIC : 0;
		dc.type[i] = 0;
		dc.mode[i] = iic_module_port_mode(i);
	}
	dc.connection[port] = conn;
	dc.mode[port] = mode;
	return lx_errno_to_er(lx_dev_ioctl_kernel(iic_file, LMS_IIC_SET_CONN, &dc));
}

/* IIC_FN_START */
ER_UINT svc_iic_start(intptr_t port, intptr_t mode, intptr_t p3, intptr_t p4,
			     intptr_t p5, ID cdmid)
{
	ER ercd = iic_hack_check(port);

	if (ercd != E_OK)
		return ercd;
	if (mode < 0 || mode > S8_MAX)
		return E_PAR;
	return iic_hack_set_conn(port, LMS_CONN_NXT_IIC, (s8)mode);
}

/* IIC_FN_STOP */
ER_UINT svc_iic_stop(intptr_t port, intptr_t p2, intptr_t p3, intptr_t p4,
			    intptr_t p5, ID cdmid)
{
	ER ercd = iic_hack_check(port);

	return ercd != E_OK ? ercd : iic_hack_set_conn(port, 0, 0);
}

/* IIC_FN_TYPE_INFO: READ_TYPE_INFO into the caller's IICSTR. */
ER_UINT svc_iic_type_info(intptr_t port, intptr_t out, intptr_t p3, intptr_t p4,
				 intptr_t p5, ID cdmid)
{
	struct lms_iic_str s = { .port = (s8)port };
	ER ercd = iic_hack_check(port);

	if (ercd != E_OK)
		return ercd;
	if (prb_mem((void *)out, sizeof(s), TSK_SELF, TPM_WRITE) != E_OK)
		return E_MACV;
	if (!iic_hack_port_running(port))
		return E_OBJ;
	ercd = lx_errno_to_er(lx_dev_ioctl_kernel(iic_file, LMS_IIC_READ_TYPE_INFO, &s));
	if (ercd == E_OK && copy_to_user((void __user *)out, &s, sizeof(s)))
		return E_MACV;
	return ercd;
}

/* IIC_FN_SET: the caller's IICSTR, checked here, then IIC_SET. */
ER_UINT svc_iic_set(intptr_t in, intptr_t p2, intptr_t p3, intptr_t p4,
			   intptr_t p5, ID cdmid)
{
	struct lms_iic_str s;
	ER ercd;

	if (sns_ctx())
		return E_CTX;
	if (prb_mem((const void *)in, sizeof(s), TSK_SELF, TPM_READ) != E_OK ||
	    copy_from_user(&s, (const void __user *)in, sizeof(s)))
		return E_MACV;
	ercd = iic_hack_check(s.port);
	if (ercd != E_OK)
		return ercd;
	return lx_errno_to_er(lx_dev_ioctl_kernel(iic_file, LMS_IIC_SET, &s));
}

/* IIC_FN_SETUP: one IIC_SETUP round on the caller's IICDAT. */
ER_UINT svc_iic_setup(intptr_t io, intptr_t p2, intptr_t p3, intptr_t p4,
			     intptr_t p5, ID cdmid)
{
	struct lms_iic_dat d;
	ER ercd;

	if (sns_ctx())
		return E_CTX;
	if (prb_mem((void *)io, sizeof(d), TSK_SELF, TPM_READ | TPM_WRITE) != E_OK ||
	    copy_from_user(&d, (const void __user *)io, sizeof(d)))
		return E_MACV;
	ercd = iic_hack_check(d.port);
	if (ercd != E_OK)
		return ercd;
	if (!iic_hack_port_running(d.port))
		return E_OBJ;
	ercd = lx_errno_to_er(lx_dev_ioctl_kernel(iic_file, LMS_IIC_SETUP, &d));
	if (ercd == E_OK && copy_to_user((void __user *)io, &d, sizeof(d)))
		return E_MACV;
	return ercd;
}

/* IIC_FN_MAP: the address of the shared memory. */
ER_UINT svc_iic_map(intptr_t out, intptr_t p2, intptr_t p3, intptr_t p4,
			   intptr_t p5, ID cdmid)
{
	ER ercd = iic_hack_check(0);

	if (ercd != E_OK)
		return ercd;
	if (copy_to_user((void __user *)out, &iic_hack_map, sizeof(iic_hack_map)))
		return E_MACV;
	return E_OK;
}

/* IIC_FN_STATE */
ER_UINT svc_iic_state(intptr_t port, intptr_t p2, intptr_t p3, intptr_t p4,
			     intptr_t p5, ID cdmid)
{
	ER ercd = iic_hack_check(port);

	return ercd != E_OK ? ercd : (ER_UINT)iic_module_port_state((unsigned int)port);
}

/* ATT_INI: forget the previous boot's file. */
void iic_hack_boot(intptr_t exinf)
{
	iic_file = NULL;
	iic_hack_map = NULL;
}

static const struct rtos_svc_cfg iic_svcs[] = {
	{ IIC_FN_START,     svc_iic_start,     512 },
	{ IIC_FN_STOP,      svc_iic_stop,      512 },
	{ IIC_FN_TYPE_INFO, svc_iic_type_info, 256 },
	{ IIC_FN_SET,       svc_iic_set,       256 },
	{ IIC_FN_SETUP,     svc_iic_setup,     256 },
	{ IIC_FN_MAP,       svc_iic_map,       128 },
	{ IIC_FN_STATE,     svc_iic_state,     128 },
};

static const struct rtos_ini_cfg iic_inis[] = {
	{ iic_hack_boot, 0 },
};

const struct rtos_cfg iic_hack_cfg = {
	.name = "iic_hack",
	.svcs = RTOS_TABLE(iic_svcs),
	.svc_first = IIC_FN_FIRST, .svc_count = IIC_FN_COUNT,
	.inis = RTOS_TABLE(iic_inis),
};
