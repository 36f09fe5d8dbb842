/*
 * test_power.c — d_power on host_sim's power pins: what loading it does to
 * the supplies and the test pin, its file operations as LEGO's user space
 * uses them (read the pack type, write one level byte, ioctl 0), bad
 * requests refused with nothing changed, and power_hack's service calls
 * with their argument and context checks.
 */
#include <linux/fcntl.h>
#include <linux/errno.h>
#include <linux_compat/devfs.h>
#include "tap.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_power.h"
#include <linux_compat/config.h>
#include "power_hack.h"

#define TASK_ID   1
#define STACK     (64 * 1024)
#define MS        1000000ULL

static bool done;
static ER irq_ercd[2];

static struct ev3_power_pins pins(void)
{
	struct ev3_power_pins p;

	ev3_power_pins_state(&p);
	return p;
}

static void at_load(void)
{
	struct ev3_power_pins p = pins();

	ok(p.main_on && p.rail_5v_on, "loaded: P_EN and 5VPENON driven high");
	ok(!p.test_high, "the test pin driven low");
}

static void file_operations(void)
{
	char buf[4] = "";
	char one[2] = { 1, 0 }, zero[1] = { 0 };	/* on the stack: the task's own memory */
	struct file *f;
	loff_t pos = 0;

	if (lx_dev_open("/dev/" LMS_POWER_DEVICE_NAME, O_RDWR, &f))
		tap_bail_out("cannot open /dev/lms_power");
	is_int(lx_dev_read(f, buf, sizeof(buf), &pos), 2, "read: two characters");
	ok(buf[0] == '0' && buf[1] == '\r', "AA cells: \"0\\r\"");
	is_int(lx_dev_read(f, buf, sizeof(buf), &pos), 0, "at offset 2: end of file");
	is_int(ev3_power_set_rechargeable(true), E_OK, "a rechargeable pack fitted");
	pos = 0;
	is_int(lx_dev_read(f, buf, 1, &pos), 1, "a one-byte read");
	is_int(buf[0], '1', "rechargeable: '1'");
	is_int(lx_dev_read(f, buf, sizeof(buf), &pos), 1, "the rest from offset 1");
	is_int(buf[0], '\r', "'\\r'");
	is_int(lx_dev_read(f, NULL, 2, NULL), -EFAULT, "read into NULL: -EFAULT");

	is_int(lx_dev_write(f, one, 1, NULL), 1, "write of one non-zero byte: 1");
	ok(pins().test_high, "test pin high");
	is_int(lx_dev_write(f, one, 2, NULL), -EINVAL, "write of two bytes: -EINVAL");
	is_int(lx_dev_write(f, one, 0, NULL), -EINVAL, "write of none: -EINVAL");
	is_int(lx_dev_write(f, NULL, 1, NULL), -EFAULT, "write from NULL: -EFAULT");
	ok(pins().test_high && pins().test_changes == 1, "refused writes change nothing");
	is_int(lx_dev_write(f, zero, 1, NULL), 1, "write of a zero byte: 1");
	ok(!pins().test_high, "test pin low");
	is_int(lx_dev_ioctl(f, 0, 0), 0, "ioctl 0 (LEGO's POWER opcode): accepted");
	lx_dev_close(f);
	ev3_power_set_rechargeable(false);
}

static void from_irq(void *arg)
{
	(void)arg;
	irq_ercd[0] = (ER)power_svc_rechargeable();
	irq_ercd[1] = power_svc_test_pin(1);
}

static void service_calls(void)
{
	is_int(power_svc_rechargeable(), 0, "service call: AA cells");
	ev3_power_set_rechargeable(true);
	is_int(power_svc_rechargeable(), 1, "service call: rechargeable");
	is_int(power_svc_test_pin(1), E_OK, "test pin 1");
	ok(pins().test_high, "pin high");
	is_int(power_svc_test_pin(2), E_PAR, "level 2: E_PAR");
	is_int(power_svc_test_pin((uint_t)-1), E_PAR, "level -1: E_PAR");
	ok(pins().test_high, "and the pin did not change");
	is_int(power_svc_test_pin(0), E_OK, "test pin 0");
	ok(!pins().test_high, "pin low");
	hs_sim_at(rtos_host_now() + MS, from_irq, NULL);
	dly_tsk(2);
	ok(irq_ercd[0] == E_CTX && irq_ercd[1] == E_CTX, "non-task context: E_CTX for both");
	ok(!pins().test_high, "and the pin did not change");
}

static void task(intptr_t exinf)
{
	(void)exinf;
	at_load();
	file_operations();
	service_calls();
	done = true;
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = {
		{ TASK_ID, TA_ACT, 0, task, 8, STACK, TDOM_KERNEL, "power_test" },
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, &power_hack_cfg, NULL };
	static const struct rtos_cfg cfg = {
		.name = "power_test", .tasks = tasks, .ntasks = 1, .includes = includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 11 };

	tap_plan(32);
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		tap_bail_out("no brick");
	}
	for (unsigned i = 0; !done && i < 100; i++)
		hs_sim_run_for(100 * MS);
	ok(done, "the test task finished");
	hs_sim_shutdown();
	return tap_done();
}
