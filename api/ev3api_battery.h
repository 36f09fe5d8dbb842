/*
 * ev3api_battery.h — the battery, as EV3RT's API has it (included by ev3api.h).
 *
 * Both calls read d_analog's battery channels (the raw counts it publishes
 * in its shared ANALOG area, unfiltered) and convert them with the FINAL
 * board's constants LEGO's c_ui and EV3RT use: battery current through a
 * 0.11 Ω shunt amplified 22×, the pack voltage as twice the divided cell
 * voltage plus the shunt's drop plus a 0.05 V diode.  EV3RT's convention:
 * they return the value; when d_analog is not loaded, or the caller is not
 * a task, they log a warning and return 0.  Before d_analog's first
 * battery sample (within 8 ms of its start) the voltage reads 0.
 */
#ifndef EV3API_BATTERY_H
#define EV3API_BATTERY_H

#ifdef __cplusplus
extern "C" {
#endif

/* Current drawn from the battery (brick and motors), mA. */
int ev3_battery_current_mA(void);
/* Battery terminal voltage, mV. */
int ev3_battery_voltage_mV(void);

#ifdef __cplusplus
}
#endif

#endif /* EV3API_BATTERY_H */
