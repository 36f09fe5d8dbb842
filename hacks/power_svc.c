/*
 * power_svc.c — d_power's interface on the RTOS: the module's extended
 * service calls (power_hack.h) and its configuration fragment.  The calls reach
 * the driver only through its file operations (read, write), so its own
 * checks guard them.
 * The driver is in power_hack.c.
 */
#include "hack_svc.h"
#include "power_hack.h"
#include "power_module.h"

/* Common checks: task context, the driver up. */
static ER power_hack_check(void)
{
	if (sns_ctx())
		return E_CTX;
	return power_file ? E_OK : E_OBJ;
}

/* POWER_FN_RECHARGEABLE: read() of the two-character answer from offset 0. */
ER_UINT svc_power_rechargeable(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4,
				      intptr_t p5, ID cdmid)
{
	char text[LMS_POWER_READ_SIZE];
	loff_t pos = 0;
	ssize_t ret;
	ER ercd = power_hack_check();

	if (ercd != E_OK)
		return ercd;
	ret = kernel_read(power_file, text, sizeof(text), &pos);
	if (ret != sizeof(text))
		return lx_errno_to_er(ret < 0 ? ret : -EIO);
	return text[0] == LMS_POWER_RECHARGEABLE;
}

/* POWER_FN_TEST_PIN: write() of one level byte. */
ER_UINT svc_power_test_pin(intptr_t level, intptr_t p2, intptr_t p3, intptr_t p4,
				  intptr_t p5, ID cdmid)
{
	u8 byte = (u8)level;
	loff_t pos = 0;
	ER ercd = power_hack_check();

	if (ercd != E_OK)
		return ercd;
	if (level != 0 && level != 1)
		return E_PAR;
	return lx_errno_to_er(kernel_write(power_file, &byte, 1, &pos));
}

static const struct rtos_svc_cfg power_svcs[] = {
	{ POWER_FN_RECHARGEABLE, svc_power_rechargeable, 256 },
	{ POWER_FN_TEST_PIN,     svc_power_test_pin,     256 },
};

const struct rtos_cfg power_hack_cfg = {
	.name = "power_hack",
	.svcs = RTOS_TABLE(power_svcs),
	.svc_first = POWER_FN_FIRST, .svc_count = POWER_FN_COUNT,
};
