/*
 * app.c — nxt_sensors: the three NXT I2C sensors of EV3RT's API, read the
 * way EV3RT apps read them.
 *
 * A HiTechnic accelerometer on port 1, a HiTechnic colour sensor on port 2
 * and LEGO's NXT temperature sensor on port 3 are configured, then read
 * every PERIOD_MS for ROUNDS rounds; each round's values are logged, and at
 * the end the last values with the number of readings that failed.  The
 * temperature is logged in hundredths of a degree (syslog has no %f).
 */
#include "ev3api.h"
#include "app.h"

void main_task(intptr_t exinf)
{
	int16_t axes[3] = { 0, 0, 0 };
	uint8_t color = 0;
	rgb_raw_t rgb = { 0, 0, 0 };
	float temp = 0.0f;
	int failures = 0;

	ev3_sensor_config(ACCEL_PORT, HT_NXT_ACCEL_SENSOR);
	ev3_sensor_config(COLOR_PORT, HT_NXT_COLOR_SENSOR);
	ev3_sensor_config(TEMP_PORT, NXT_TEMP_SENSOR);

	for (int round = 0; round < ROUNDS; round++) {
		if (!ht_nxt_accel_sensor_measure(ACCEL_PORT, axes))
			failures++;
		if (!ht_nxt_color_sensor_measure_color(COLOR_PORT, &color))
			failures++;
		if (!ht_nxt_color_sensor_measure_rgb(COLOR_PORT, &rgb))
			failures++;
		if (!nxt_temp_sensor_measure(TEMP_PORT, &temp))
			failures++;
		syslog(LOG_INFO, "nxt_sensors: round %d accel %d %d %d color %d temp %d",
		       round, axes[0], axes[1], axes[2], color, (int)(temp * 100.0f));
		tslp_tsk(PERIOD_MS);
	}
	syslog(LOG_NOTICE, "nxt_sensors: accel %d %d %d color %d rgb %d %d %d temp %d failures %d",
	       axes[0], axes[1], axes[2], color, rgb.r, rgb.g, rgb.b, (int)(temp * 100.0f), failures);
	ext_tsk();
}
