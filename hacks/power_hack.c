/*
 * power_hack.c — d_power on the RTOS: the Linux driver source included
 * byte-for-byte, then its interface as extended service calls
 * (power_hack.h).  The calls reach the driver only through its file
 * operations (read, write), so its own checks guard them.
 */
#define KBUILD_MODNAME "d_power"
#include "driver_common.h"

/* Renames: the driver's module_init/exit become plain pointers, called by ours below. */
#pragma push_macro("module_init")
#pragma push_macro("module_exit")
#undef module_init
#undef module_exit
#define module_init(fn) static int (*const power_driver_init)(void) = fn
#define module_exit(fn) static void (*const power_driver_exit)(void) = fn

#include "d_power.c"

#undef module_init
#undef module_exit
#pragma pop_macro("module_init")
#pragma pop_macro("module_exit")

#include "power_hack.h"

static struct file *power_file;		/* /dev/lms_power */

/* Loads d_power, then opens its device for the service calls. */
static int __init power_hack_init(void)
{
	int ret;

	power_file = NULL;
	ret = power_driver_init();
	if (ret)
		return ret;
	ret = lx_dev_open("/dev/" LMS_POWER_DEVICE_NAME, O_RDWR, &power_file);
	if (ret) {
		pr_err("power_hack: cannot open d_power's device (%d)\n", ret);
		power_file = NULL;
		power_driver_exit();
	}
	return ret;
}
module_init(power_hack_init);

/* Closes the device (the service calls then answer E_OBJ) and unloads d_power. */
static void __exit power_hack_exit(void)
{
	struct file *file = power_file;

	WRITE_ONCE(power_file, NULL);
	lx_dev_close(file);
	power_driver_exit();
}
module_exit(power_hack_exit);

/* Common checks: task context, the driver up. */
static ER power_hack_check(void)
{
	if (sns_ctx())
		return E_CTX;
	return power_file ? E_OK : E_OBJ;
}

/* POWER_FN_RECHARGEABLE: read() of the two-character answer from offset 0. */
static ER_UINT svc_power_rechargeable(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4,
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
static ER_UINT svc_power_test_pin(intptr_t level, intptr_t p2, intptr_t p3, intptr_t p4,
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
