/*
 * power.c — the EV3's battery front end and power pins (ev3_power.h).
 *
 * The battery channels follow the FINAL board's constants as LEGO's c_ui
 * and EV3RT convert them (shunt 0.11 Ω with gain 22 on the battery
 * current, 0.055 Ω with gain 19 on the motor current, a 1:2 divider after
 * the shunt and a 0.05 V diode on the cell voltage).
 */
#include <string.h>
#include "host_sim/gpio.h"
#include "host_sim/trace.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/ev3_power.h"

#define BATT_SHUNT_OHM        0.11
#define BATT_SHUNT_GAIN       22.0
#define MOTOR_SHUNT_OHM       0.055
#define MOTOR_SHUNT_GAIN      19.0
#define CELL_DIODE_V          0.05
#define CELL_DIVIDER          0.5
#define ADC_FULL_SCALE_MV     5000U
#define BATTERY_TEMP_MV       1500U  /* no source converts BatteryTemp: a fixed mid-scale level */

static struct {
	bool ready;
	uint32_t mohm;
	bool rechargeable;
	struct ev3_power_pins pins;
	int watches[3];
	struct hs_signal *sig_test, *sig_5v;
} power;

ER ev3_power_set_resistance_mohm(uint32_t mohm)
{
	if (!power.ready)
		return E_OBJ;
	if (mohm > EV3_POWER_MAX_MOHM)
		return E_PAR;
	power.mohm = mohm;
	return E_OK;
}

static void recharge_apply(void)
{
	hs_gpio_drive(EV3_POWER_RECHARGE_PIN, power.rechargeable ? HS_EXT_LOW : HS_EXT_PULL_UP);
}

ER ev3_power_set_rechargeable(bool rechargeable)
{
	if (!power.ready)
		return E_OBJ;
	power.rechargeable = rechargeable;
	recharge_apply();
	return E_OK;
}

double ev3_power_battery_current_a(void)
{
	return EV3_POWER_BRICK_MA / 1000.0 + ev3_motors_current_a();
}

/* Terminal voltage for a total current amps, in volts (never below 0). */
static double terminal_v(double amps)
{
	double v = ev3_battery_mv() / 1000.0 - amps * power.mohm / 1000.0;

	return v > 0 ? v : 0;
}

uint32_t ev3_power_terminal_mv(void)
{
	return (uint32_t)(terminal_v(ev3_power_battery_current_a()) * 1000.0 + 0.5);
}

/* Volts as ADC millivolts, clamped to the converter's 0..5 V. */
static uint32_t adc_mv(double volts)
{
	if (volts <= 0)
		return 0;
	return volts * 1000.0 >= ADC_FULL_SCALE_MV ? ADC_FULL_SCALE_MV
						   : (uint32_t)(volts * 1000.0 + 0.5);
}

uint32_t ev3_power_adc_mv(unsigned ch, double motor_a)
{
	double amps = EV3_POWER_BRICK_MA / 1000.0 + motor_a;

	switch (ch) {
	case EV3_ADC_BATTERY_VOLTAGE:
		return adc_mv((terminal_v(amps) - amps * BATT_SHUNT_OHM - CELL_DIODE_V) *
			      CELL_DIVIDER);
	case EV3_ADC_BATTERY_CURRENT:
		return adc_mv(amps * BATT_SHUNT_OHM * BATT_SHUNT_GAIN);
	case EV3_ADC_MOTOR_CURRENT:
		return adc_mv(motor_a * MOTOR_SHUNT_OHM * MOTOR_SHUNT_GAIN);
	case EV3_ADC_BATTERY_TEMP:
		return BATTERY_TEMP_MV;
	default:
		return 0;
	}
}

/* ---- power pins ---- */

static bool driven_high(unsigned pin)
{
	bool level;

	return hs_gpio_soc_output(pin, &level) && level;
}

static void pin_changed(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	bool test = driven_high(EV3_POWER_TEST_PIN);

	(void)ctx; (void)pin; (void)st;
	power.pins.main_on = driven_high(EV3_POWER_P_EN_PIN);
	power.pins.rail_5v_on = driven_high(EV3_POWER_5V_PIN);
	if (test != power.pins.test_high)
		power.pins.test_changes++;
	power.pins.test_high = test;
	hs_trace_set(power.sig_test, test);
	hs_trace_set(power.sig_5v, power.pins.rail_5v_on);
}

void ev3_power_pins_state(struct ev3_power_pins *out)
{
	*out = power.pins;
}

/* ---- the board device ---- */

static ER power_create(const struct hs_board_cfg *cfg, void **ctx)
{
	static const unsigned watched[3] = { EV3_POWER_P_EN_PIN, EV3_POWER_5V_PIN, EV3_POWER_TEST_PIN };

	memset(&power, 0, sizeof(power));
	power.mohm = EV3_POWER_DEFAULT_MOHM;
	power.sig_test = hs_trace_signal("power", "test_pin", 1);
	power.sig_5v = hs_trace_signal("power", "rail_5v", 1);
	recharge_apply();
	for (unsigned i = 0; i < 3; i++) {
		if (!(cfg && cfg->cold_reset))
			hs_gpio_mux_as_gpio(watched[i]);	/* the board code's pin setup */
		power.watches[i] = hs_gpio_watch(watched[i], pin_changed, NULL);
		if (!power.watches[i])
			return E_NOMEM;
	}
	power.ready = true;
	*ctx = &power;
	return E_OK;
}

static void power_destroy(void *ctx)
{
	(void)ctx;
	for (unsigned i = 0; i < 3; i++)
		hs_gpio_unwatch(power.watches[i]);
	power.ready = false;
}

const struct hs_device ev3_power_device = { "EV3_POWER", power_create, NULL, power_destroy };
