/*
 * battery.c — the battery voltage every board model reads (motors, the ADC
 * front end).  The ports model sets it and tells the motors
 * (ev3_set_battery_mv), so the models reading it need not know each other.
 */
#include "host_sim/devices/ev3_brick.h"

static uint32_t battery_mv = EV3_BATTERY_MV_DEFAULT;

uint32_t ev3_battery_mv(void)
{
	return battery_mv;
}

void ev3_battery_store(uint32_t mv)
{
	battery_mv = mv;
}
