/*
 * test_pwm_hack.c — pwm_hack's service calls around the driver's life cycle:
 * the reserved function codes, module exit (devices gone, outputs coasting,
 * every call E_OBJ, memory returned), loading again, and a load that fails
 * (a register block taken): E_OBJ everywhere, nothing left registered,
 * claimed or allocated.
 */
#include <linux/module.h>
#include <linux/interrupt.h>
#include <linux/ioport.h>
#include <linux/gpio.h>
#include <linux_compat/devfs.h>
#include <linux_compat/heap.h>

#include "pwm_test.h"

static bool all_obj(void)
{
	uint8_t b[3] = { LMS_PWM_OUTPUT_SPEED, 0x01, 10 };
	char st[4];
	struct lms_motor_data md;
	const struct lms_motor_data *map;

	return pwm_command(b, 3) == E_OBJ && pwm_command2(b, 3, b, 3) == E_OBJ &&
	       pwm_read_status(st, 4) == E_OBJ && pwm_busy() == E_OBJ &&
	       pwm_set_busy(1) == E_OBJ && pwm_motor_data(0, &md) == E_OBJ &&
	       pwm_motor_map(&map) == E_OBJ && pwm_run(LMS_PWM_OUTPUT_SPEED, 0, 10) == E_OBJ;
}

static irqreturn_t probe_isr(int irq, void *dev_id)
{
	return IRQ_HANDLED;
}

/* The failing load must undo everything: a second unload, then a load that finds
 * its register block taken. */
static void failed_load(void)
{
	static const struct { unsigned long phys, size; } blocks[] = {
		{ 0x01F02000, 0x80 }, { 0x01F06000, 0x60 }, { 0x01F07000, 0x60 }, { 0x01F0D000, 0x80 },
	};
	struct module *mod = lx_module_find("d_pwm");
	struct lx_heap_stats st0, st;
	int irq = gpio_to_irq(HS_GPIO(5, 11));
	bool claimed = true;

	lx_modules_exit();
	lx_heap_get_stats(&st0);
	ok(request_mem_region(0x01F0D000, 0x80, "squatter") != NULL, "someone else claims TIMER64P3");
	is_int(lx_modules_init(), 1, "the load fails");
	ok(mod && mod->state == MODULE_STATE_FAILED && mod->init_result == -EBUSY,
	   "d_pwm's init answered -EBUSY (%d)", mod ? mod->init_result : 0);
	release_mem_region(0x01F0D000, 0x80);
	ok(!lx_dev_exists("/dev/lms_pwm") && !lx_dev_exists("/dev/lms_motor"), "no device left registered");
	lx_heap_get_stats(&st);
	is_int(st.in_use, st0.in_use, "no memory left allocated");
	for (unsigned i = 0; i < 4; i++) {
		if (!request_mem_region(blocks[i].phys, blocks[i].size, "probe"))
			claimed = false;
		else
			release_mem_region(blocks[i].phys, blocks[i].size);
	}
	ok(claimed, "every register block it claimed is free again");
	ok(request_irq(irq, probe_isr, 0, "probe", &claimed) == 0, "its tacho interrupt is free again");
	free_irq(irq, &claimed);
	ok(all_obj(), "every service call answers E_OBJ");
}

static void life_cycle_body(void)
{
	struct lx_heap_stats before, after;
	struct hbridge_drive d;
	int undefined = 0;

	for (FN fn = PWM_FN_FIRST + 8; fn <= PWM_FN_LAST; fn++)
		if (cal_svc(fn, 0, 0, 0, 0, 0) == E_RSFN)
			undefined++;
	is_int(undefined, PWM_FN_COUNT - 8, "function codes %d..%d are reserved: E_RSFN", PWM_FN_FIRST + 8, PWM_FN_LAST);
	ok(lx_dev_exists("/dev/lms_pwm") && lx_dev_exists("/dev/lms_motor"), "both devices registered");

	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x0F, 50);
	pwm_cmd(LMS_PWM_OUTPUT_START, 0x0F);
	pwm_set_busy(0x03);
	dly_tsk(200);
	ok(motor_dps(0) > 300 && motor_dps(3) > 300, "motors running before the unload");

	lx_heap_get_stats(&before);
	lx_modules_exit();
	lx_heap_get_stats(&after);
	ok(!lx_dev_exists("/dev/lms_pwm") && !lx_dev_exists("/dev/lms_motor"), "unload removes the devices");
	ok(after.in_use < before.in_use, "unload returns the MOTORDATA memory (%zu -> %zu bytes in use)",
	   before.in_use, after.in_use);
	ok(all_obj(), "every service call answers E_OBJ after the unload");
	d = hs_motor_drive(ev3_output_motor(0));
	ok(d.fwd == 0 && d.rev == 0 && d.brake == 0, "outputs coast after the unload");
	dly_tsk(1500);
	ok(fabs(motor_dps(0)) < 1 && fabs(motor_dps(3)) < 1, "and nothing drives them any more");

	ok(lx_modules_init() == 0, "loading again succeeds");
	ok(pwm_busy() == 0, "fresh state: nothing busy");
	ok(motor_data_of(0).tacho_sensor == 0, "fresh state: counters at 0");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x01, 50) == E_OK &&
	   pwm_cmd(LMS_PWM_OUTPUT_START, 0x01) == E_OK, "commands work again");
	dly_tsk(400);
	ok(fabs(motor_dps(0) - PWM_LARGE_DPS(50)) < 0.05 * PWM_LARGE_DPS(50),
	   "and regulate again (%.0f deg/s)", motor_dps(0));
	dly_tsk(100);
	ok(motor_data_of(0).tacho_sensor > 100, "the tacho counts again (%d)", motor_data_of(0).tacho_sensor);
	failed_load();
}

int main(void)
{
	const int motors[4] = { HS_MOTOR_LARGE, HS_MOTOR_MEDIUM, HS_MOTOR_LARGE, HS_MOTOR_LARGE };

	tap_plan(23);
	ok(pwm_test_run(life_cycle_body, motors), "body ran to its end");
	return tap_done();
}
