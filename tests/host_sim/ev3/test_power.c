/*
 * test_power.c — the battery front end and power pins of ev3_power.h: the
 * ADC's battery channels at rest follow the FINAL board's constants (the
 * c_ui conversion gives the terminal voltage back), the terminal voltage
 * sags by R × I when a stalled motor draws current, the sense pin follows
 * the pack type, and the power pins are seen as the SoC drives them.
 */
#include "devtest.h"
#include "host_sim/devices/ev3_power.h"

#define NEAR(got, want, tol, ...) in_range((double)(got), (double)(want) - (tol), (double)(want) + (tol), __VA_ARGS__)

/* LEGO's c_ui / EV3RT conversion (FINAL constants), from channel millivolts. */
static double batt_v(void)
{
	return ev3_adc_channel_mv(EV3_ADC_BATTERY_VOLTAGE) / 1000.0 / 0.5 +
	       ev3_adc_channel_mv(EV3_ADC_BATTERY_CURRENT) / 1000.0 / 22.0 + 0.05;
}

static double batt_a(void)
{
	return ev3_adc_channel_mv(EV3_ADC_BATTERY_CURRENT) / 1000.0 / 22.0 / 0.11;
}

int main(void)
{
	struct ev3_power_pins pins;
	double idle_v, idle_a, load_v, load_a, motor_a;

	tap_plan(20);
	devtest_boot(5, NULL);

	/* at rest: 9 V EMF, 0.1 A brick draw, 0.5 Ω */
	idle_a = batt_a();
	idle_v = batt_v();
	NEAR(idle_a, 0.100, 0.003, "idle current 0.1 A from BatteryCurrent (%.3f A)", idle_a);
	NEAR(idle_v, 8.950, 0.005, "idle voltage = EMF - 0.5 ohm x 0.1 A (%.3f V)", idle_v);
	is_int(ev3_power_terminal_mv(), 8950, "the model's terminal voltage agrees");
	is_int(ev3_adc_channel_mv(EV3_ADC_MOTOR_CURRENT), 0, "no motor current");
	is_int(ev3_adc_channel_mv(EV3_ADC_BATTERY_TEMP), 1500, "BatteryTemp at its fixed level");

	/* a large motor at full power against a load */
	is_int(ev3_attach_motor(0, HS_MOTOR_LARGE, NULL), E_OK, "large motor on port A");
	hs_motor_set_load(ev3_output_motor(0), 0.3, 0);
	devtest_pwm_setup();
	devtest_duty(0, 10000);
	devtest_bridge(0, 1);
	hs_sim_run_for(200 * MS);
	motor_a = ev3_motors_current_a();
	load_a = batt_a();
	load_v = batt_v();
	ok(motor_a > 1.0, "the loaded motor draws %.2f A", motor_a);
	NEAR(load_a, motor_a + 0.1, 0.01, "battery current = motor + brick (%.3f A)", load_a);
	NEAR(ev3_adc_channel_mv(EV3_ADC_MOTOR_CURRENT) / 1000.0 / 19.0 / 0.055, motor_a, 0.01,
	     "MotorCurrent through 0.055 ohm x 19");
	NEAR(load_v, 9.0 - 0.5 * load_a, 0.01, "voltage sags by R x I (%.3f V)", load_v);
	ok(idle_v - load_v > 0.5, "more than 0.5 V below the idle voltage");

	is_int(ev3_power_set_resistance_mohm(0), E_OK, "an ideal battery");
	NEAR(batt_v(), 9.0, 0.01, "no sag without resistance");
	is_int(ev3_power_set_resistance_mohm(EV3_POWER_MAX_MOHM + 1), E_PAR, "too much resistance refused");
	devtest_bridge(0, 0);

	/* the pack type on SW_RECHARGE */
	gpio_float(EV3_POWER_RECHARGE_PIN);
	is_int(gpio_in(EV3_POWER_RECHARGE_PIN), 1, "AA cells: the sense pin reads high");
	is_int(ev3_power_set_rechargeable(true), E_OK, "a rechargeable pack fitted");
	is_int(gpio_in(EV3_POWER_RECHARGE_PIN), 0, "rechargeable: the sense pin reads low");

	/* the power pins as the SoC drives them */
	ev3_power_pins_state(&pins);
	ok(!pins.main_on && !pins.rail_5v_on, "supplies undriven at reset");
	gpio_out(EV3_POWER_P_EN_PIN, 1);
	gpio_out(EV3_POWER_5V_PIN, 1);
	gpio_out(EV3_POWER_TEST_PIN, 1);
	ev3_power_pins_state(&pins);
	ok(pins.main_on && pins.rail_5v_on && pins.test_high, "P_EN, 5VPENON and the test pin driven high");
	gpio_out(EV3_POWER_TEST_PIN, 0);
	ev3_power_pins_state(&pins);
	ok(!pins.test_high && pins.test_changes == 2, "test pin low again, two changes (%u)", pins.test_changes);

	hs_sim_shutdown();
	return tap_done();
}
