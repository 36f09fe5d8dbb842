/*
 * app.c — gyrocal: a gyro held still is calibrated as LEGO's Gyro Boy does
 * it: 200 rate readings 4 ms apart are its offset if they span less than
 * 2 deg/s.  It calibrates CALIBRATIONS times and logs how many passed, the
 * widest span and how many readings were not 0.
 */
#include "ev3api.h"
#include "app.h"

static const sensor_port_t gyro_sensor = EV3_PORT_2;

void main_task(intptr_t exinf)
{
	int passed = 0, widest = 0, off_zero = 0, first = -1;

	ev3_sensor_config(gyro_sensor, GYRO_SENSOR);
	ev3_gyro_sensor_reset(gyro_sensor);
	for (int c = 0; c < CALIBRATIONS; c++) {
		int gMn = 1000, gMx = -100;

		for (int i = 0; i < SAMPLES; i++) {
			int gyro = ev3_gyro_sensor_get_rate(gyro_sensor);

			if (gyro > gMx)
				gMx = gyro;
			if (gyro < gMn)
				gMn = gyro;
			off_zero += gyro != 0;
			tslp_tsk(4);
		}
		if (gMx - gMn < 2)
			passed++;
		if (c == 0)
			first = gMx - gMn < 2;
		if (gMx - gMn > widest)
			widest = gMx - gMn;
	}
	syslog(LOG_NOTICE, "gyrocal: first %s, %d of %d passed, widest span %d, %d of %d readings not 0",
	       first ? "passed" : "failed", passed, CALIBRATIONS, widest, off_zero, CALIBRATIONS * SAMPLES);
}
