/*
 * uart_svc.c — d_uart's interface on the RTOS: the module's extended
 * service calls (uart_hack.h) and its configuration fragment.  The calls
 * reach the driver only through its file operations, so its own checks
 * (ports, modes, lengths, copy_*_user against the caller's domain) guard
 * every call, after the ones here.
 * The driver is in uart_hack.c.
 */
#include "hack_svc.h"
#include "uart_hack.h"
#include "uart_module.h"

/* Common checks: task context, port 0..3, the driver up.  E_OK or the error. */
static ER uart_hack_check(intptr_t port)
{
	if (sns_ctx())
		return E_CTX;
	if (port < 0 || port >= LMS_UART_PORTS)
		return E_ID;
	return uart_hack_file() ? E_OK : E_OBJ;
}

/* SET_CONN: @port gets @conn and @mode, the other ports keep what they have. */
static ER uart_hack_set_conn(intptr_t port, s8 conn, s8 mode)
{
	struct lms_uart_devcon dc;
	unsigned int i;

	for (i = 0; i < LMS_UART_PORTS; i++) {
		bool running = READ_ONCE(uart_map->ext.port[i].state) != LMS_UART_STATE_IDLE;

		dc.connection[i] = running ? LMS_CONN_INPUT_UART : 0;
		dc.type[i] = 0;
		dc.mode[i] = READ_ONCE(uart_map->ext.port[i].mode);
	}
	dc.connection[port] = conn;
	dc.mode[port] = mode;
	return lx_errno_to_er(lx_dev_ioctl_kernel(uart_file, LMS_UART_SET_CONN, &dc));
}

/* UART_FN_SET_MODE */
ER_UINT svc_uart_set_mode(intptr_t port, intptr_t mode, intptr_t p3, intptr_t p4,
				 intptr_t p5, ID cdmid)
{
	ER ercd = uart_hack_check(port);

	if (ercd != E_OK)
		return ercd;
	if (mode < 0 || mode >= LMS_UART_MODES)
		return E_PAR;
	return uart_hack_set_conn(port, LMS_CONN_INPUT_UART, (s8)mode);
}

/* UART_FN_STOP */
ER_UINT svc_uart_stop(intptr_t port, intptr_t p2, intptr_t p3, intptr_t p4,
			     intptr_t p5, ID cdmid)
{
	ER ercd = uart_hack_check(port);

	return ercd != E_OK ? ercd : uart_hack_set_conn(port, 0, 0);
}

/* UART_FN_MODE_INFO: the description from the shared memory, once the sensor has given it. */
ER_UINT svc_uart_mode_info(intptr_t port, intptr_t mode, intptr_t out, intptr_t p4,
				  intptr_t p5, ID cdmid)
{
	ER ercd = uart_hack_check(port);

	if (ercd != E_OK)
		return ercd;
	if (mode < 0 || mode >= LMS_UART_MODES)
		return E_PAR;
	if (prb_mem((void *)out, sizeof(struct lms_uart_types), TSK_SELF, TPM_WRITE) != E_OK)
		return E_MACV;
	if (READ_ONCE(uart_map->ext.port[port].state) == LMS_UART_STATE_IDLE ||
	    !READ_ONCE(uart_map->ext.port[port].modes))
		return E_OBJ;	/* no sensor has described itself yet */
	if (mode >= uart_map->ext.port[port].modes)
		return E_PAR;
	if (copy_to_user((void __user *)out, &uart_map->lms.types[port][mode],
			 sizeof(struct lms_uart_types)))
		return E_MACV;
	return E_OK;
}

/* UART_FN_CLEAR_CHANGED */
ER_UINT svc_uart_clear_changed(intptr_t port, intptr_t p2, intptr_t p3, intptr_t p4,
				      intptr_t p5, ID cdmid)
{
	struct lms_uart_ctl ctl = { .port = (s8)port };
	ER ercd = uart_hack_check(port);

	if (ercd != E_OK)
		return ercd;
	return lx_errno_to_er(lx_dev_ioctl_kernel(uart_file, LMS_UART_CLEAR_CHANGED, &ctl));
}

/* UART_FN_WRITE: [port, data...] written to the device. */
ER_UINT svc_uart_write(intptr_t port, intptr_t data, intptr_t len, intptr_t p4,
			      intptr_t p5, ID cdmid)
{
	u8 cmd[1 + LMS_UART_DATA_SIZE];
	ER ercd = uart_hack_check(port);

	if (ercd != E_OK)
		return ercd;
	if (len < 1 || len > LMS_UART_DATA_SIZE)
		return E_PAR;
	if (prb_mem((const void *)data, (SIZE)len, TSK_SELF, TPM_READ) != E_OK ||
	    copy_from_user(cmd + 1, (const void __user *)data, (unsigned long)len))
		return E_MACV;
	cmd[0] = (u8)port;
	return lx_errno_to_er(kernel_write(uart_file, cmd, (size_t)len + 1, NULL));
}

/* UART_FN_MAP: the address of the shared memory. */
ER_UINT svc_uart_map(intptr_t out, intptr_t p2, intptr_t p3, intptr_t p4,
			    intptr_t p5, ID cdmid)
{
	ER ercd = uart_hack_check(0);

	if (ercd != E_OK)
		return ercd;
	if (copy_to_user((void __user *)out, &uart_map, sizeof(uart_map)))
		return E_MACV;
	return E_OK;
}

/* ATT_INI: forget the previous boot's file.  Which UARTs serve ports 3 and 4
 * is the board's to say: it passes d_uart.port3_* / port4_* as boot arguments. */
void uart_hack_boot(intptr_t exinf)
{
	uart_file = NULL;
	uart_map = NULL;
}

static const struct rtos_svc_cfg uart_svcs[] = {
	{ UART_FN_SET_MODE,      svc_uart_set_mode,      512 },
	{ UART_FN_STOP,          svc_uart_stop,          512 },
	{ UART_FN_MODE_INFO,     svc_uart_mode_info,     256 },
	{ UART_FN_CLEAR_CHANGED, svc_uart_clear_changed, 256 },
	{ UART_FN_WRITE,         svc_uart_write,         256 },
	{ UART_FN_MAP,           svc_uart_map,           128 },
};

static const struct rtos_ini_cfg uart_inis[] = {
	{ uart_hack_boot, 0 },
};

const struct rtos_cfg uart_hack_cfg = {
	.name = "uart_hack",
	.svcs = RTOS_TABLE(uart_svcs),
	.svc_first = UART_FN_FIRST, .svc_count = UART_FN_COUNT,
	.inis = RTOS_TABLE(uart_inis),
};
