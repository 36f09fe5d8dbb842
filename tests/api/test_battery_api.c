/*
 * test_battery_api.c — ev3_battery_voltage_mV / ev3_battery_current_mA end
 * to end: application task -> ev3api -> d_analog's shared ANALOG area <-
 * d_analog sampling the simulated ADC <- host_sim's battery, whose terminal
 * voltage sags with the current two loaded large motors draw (kept below
 * the 2.07 A at which the FINAL front end's current channel saturates).
 */
#include "api_test.h"
#include "host_sim/devices/ev3_power.h"

static int irq_mv = -1;

static void attach(void)
{
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(3, HS_MOTOR_LARGE, NULL);
	hs_motor_set_load(ev3_output_motor(0), 0.15, 0);
	hs_motor_set_load(ev3_output_motor(3), 0.15, 0);
}

static void from_irq(void *arg)
{
	(void)arg;
	irq_mv = ev3_battery_voltage_mV();
}

static void body(void)
{
	int idle_mv, idle_ma, load_mv, load_ma, model_mv, after_mv;

	dly_tsk(50);
	idle_mv = ev3_battery_voltage_mV();
	idle_ma = ev3_battery_current_mA();
	in_range(idle_ma, 95, 105, "idle: the brick's 100 mA (%d mA)", idle_ma);
	in_range(idle_mv, 8935, 8965, "idle: 9 V less 0.5 ohm x 0.1 A (%d mV)", idle_mv);

	is_int(ev3_motor_config(EV3_PORT_A, UNREGULATED_MOTOR), E_OK, "config A");
	is_int(ev3_motor_config(EV3_PORT_D, UNREGULATED_MOTOR), E_OK, "config D");
	is_int(ev3_motor_set_power(EV3_PORT_A, 100), E_OK, "A at full power");
	is_int(ev3_motor_set_power(EV3_PORT_D, 100), E_OK, "D at full power");
	dly_tsk(500);
	load_mv = ev3_battery_voltage_mV();
	load_ma = ev3_battery_current_mA();
	model_mv = (int)ev3_power_terminal_mv();
	ok(load_ma > 1200 && load_ma < 2000, "two loaded motors: the current rises to %d mA", load_ma);
	ok(idle_mv - load_mv > 500, "the voltage drops by %d mV", idle_mv - load_mv);
	in_range(load_mv, model_mv - 40, model_mv + 40, "and reads the battery's terminal voltage (%d, model %d mV)",
		 load_mv, model_mv);
	in_range(load_mv, 9000 - load_ma / 2 - 40, 9000 - load_ma / 2 + 40,
		 "V = EMF - R x I from the API's own figures");

	ev3_motor_stop(EV3_PORT_A, false);
	ev3_motor_stop(EV3_PORT_D, false);
	dly_tsk(500);
	after_mv = ev3_battery_voltage_mV();
	in_range(after_mv, idle_mv - 15, idle_mv + 15, "stopped: back to the idle voltage (%d mV)", after_mv);

	hs_sim_at(rtos_host_now() + AT_MS, from_irq, NULL);
	dly_tsk(2);
	in_range(irq_mv, idle_mv - 15, idle_mv + 15, "from an interrupt handler: the same reading (shared memory)");
}

int main(void)
{
	tap_plan(13);
	ok(at_run(attach, body, 9, 10), "the application finished");
	return tap_done();
}
