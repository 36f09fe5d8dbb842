/*
 * ev3api_battery.h — the battery (included by ev3api.h), EV3RT's interface.
 * Not provided yet: every call is EV3API_NOT_YET (an app using one compiles
 * and fails to link, naming the call).
 */
#ifndef EV3API_BATTERY_H
#define EV3API_BATTERY_H

#include "ev3api_not_yet.h"
int ev3_battery_current_mA(void) EV3API_NOT_YET(battery, ev3_battery_current_mA);
int ev3_battery_voltage_mV(void) EV3API_NOT_YET(battery, ev3_battery_voltage_mV);

#endif /* EV3API_BATTERY_H */
