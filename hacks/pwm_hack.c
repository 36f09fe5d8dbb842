/*
 * pwm_hack.c — d_pwm on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: its
 * init and exit, the devices it opens for the service calls, and the entry to
 * the handlers d_pwm's write() dispatches to (pwm_module.h).  Only Linux
 * headers: the service calls themselves are pwm_svc.c.
 */
#define KBUILD_MODNAME "d_pwm"
/* The driver's module_init/exit become plain pointers, called by ours below. */
#define LX_HACK_DRIVER_INIT pwm_driver_init
#define LX_HACK_DRIVER_EXIT pwm_driver_exit

#include "d_pwm.c"

#include "driver_common.h"

#include "pwm_module.h"

struct file *pwm_file;       /* /dev/lms_pwm */
struct file *motor_file;     /* /dev/lms_motor */
const struct lms_motor_data *motor_map;

/* Loads d_pwm, then opens its devices and maps MOTORDATA for the service calls. */
static int __init pwm_hack_init(void)
{
	void *map;
	int ret;

	ret = pwm_driver_init();
	if (ret)
		return ret;
	ret = lx_dev_open("/dev/" LMS_PWM_DEVICE_NAME, O_RDWR, &pwm_file);
	if (!ret)
		ret = lx_dev_open("/dev/" LMS_MOTOR_DEVICE_NAME, O_RDWR, &motor_file);
	if (!ret)
		ret = lx_dev_mmap(motor_file, LMS_MOTOR_DATA_SIZE, &map);
	if (ret) {
		pr_err("pwm_hack: cannot open d_pwm's devices (%d)\n", ret);
		lx_dev_close(pwm_file);
		lx_dev_close(motor_file);
		pwm_file = motor_file = NULL;
		pwm_driver_exit();
		return ret;
	}
	motor_map = map;
	return 0;
}
module_init(pwm_hack_init);

/* Closes the devices (the service calls then answer E_OBJ), then unloads d_pwm. */
static void __exit pwm_hack_exit(void)
{
	struct file *pwm = pwm_file, *motor = motor_file;

	pwm_file = NULL;
	motor_file = NULL;
	motor_map = NULL;
	lx_dev_close(pwm);
	lx_dev_close(motor);
	pwm_driver_exit();
}
module_exit(pwm_hack_exit);

/* OUTPUT_SPEED or OUTPUT_POWER (set), then OUTPUT_START (start), through d_pwm's handlers. */
int pwm_module_run(const u8 *set, const u8 *start)
{
	int ret = set[0] == LMS_PWM_OUTPUT_SPEED ? cmd_speed(set) : cmd_power(set);

	return ret ? ret : cmd_start(start);
}

/* The ReadyStatus mask (a byte d_pwm updates atomically). */
u8 pwm_module_ready_status(void)
{
	return READ_ONCE(ready_status);
}
