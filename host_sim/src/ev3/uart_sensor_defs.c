/*
 * uart_sensor_defs.c — what each EV3 UART sensor advertises, from the
 * decoded power-up captures (logic-analyser captures of real sensors published
 * in JakubVanek/lms2012-stuff: colour 47N3, gyro 49N3, ultrasonic
 * 50N3, IR 36N8, firmware 1.10E) and the timing notes there.
 *
 * Data rates (the same captures): gyro about 330 frames/s (one every
 * 3 ms here), ultrasonic one every 21-25 ms (23 ms here), colour and IR one
 * per NACK with a steady value plus one whenever the value changes (checked
 * every 10 ms here, LEGO's typedata "Time" for these types).
 */
#include <stddef.h>
#include "host_sim/devices/uart_sensor.h"

#define MS 1000U

static const struct uart_sensor_mode color_modes[] = {
	{ "COL-REFLECT", 0, 100, 0, 100, "pct", 1, LUMP_DATA8, 3, 0, 0, false, false },
	{ "COL-AMBIENT", 0, 100, 0, 100, "pct", 1, LUMP_DATA8, 3, 0, 0, false, false },
	{ "COL-COLOR", 0, 8, 0, 8, "col", 1, LUMP_DATA8, 2, 0, 0, false, false },
	{ "REF-RAW", 0, 1020.1875f, 0, 1020.1875f, NULL, 2, LUMP_DATA16, 4, 0, 0, false, false },
	{ "RGB-RAW", 0, 1020.1875f, 0, 1020.1875f, NULL, 3, LUMP_DATA16, 4, 0, 0, false, false },
	{ "COL-CAL", 0, 65535, 0, 65535, NULL, 4, LUMP_DATA16, 5, 0, 0, true, false },
};

static const struct uart_sensor_mode us_modes[] = {
	{ "US-DIST-CM", 0, 2550, 0, 255, "cm", 1, LUMP_DATA16, 5, 1, 23 * MS, false, false },
	{ "US-DIST-IN", 0, 1000, 0, 100, "inch", 1, LUMP_DATA16, 5, 1, 23 * MS, false, false },
	{ "US-LISTEN", 0, 1, 0, 1, NULL, 1, LUMP_DATA8, 1, 0, 23 * MS, false, false },
	{ "US-SI-CM", 0, 2550, 0, 255, "cm", 1, LUMP_DATA16, 5, 1, 0, false, true },
	{ "US-SI-IN", 0, 1000, 0, 100, "inch", 1, LUMP_DATA16, 5, 1, 0, false, true },
	{ "US-DC-CM", 0, 2550, 0, 255, "cm", 1, LUMP_DATA16, 5, 1, 23 * MS, false, false },
	{ "US-DC-IN", 0, 1000, 0, 100, "inch", 1, LUMP_DATA16, 5, 1, 23 * MS, false, false },
};

static const struct uart_sensor_mode gyro_modes[] = {
	{ "GYRO-ANG", -180, 180, -180, 180, "deg", 1, LUMP_DATA16, 4, 0, 3 * MS, false, false },
	{ "GYRO-RATE", -440, 440, -440, 440, "d/s", 1, LUMP_DATA16, 3, 0, 3 * MS, false, false },
	{ "GYRO-FAS", -2000, 2000, -2000, 2000, NULL, 1, LUMP_DATA16, 4, 0, 3 * MS, false, false },
	{ "GYRO-G&A", -180, 180, -180, 180, NULL, 2, LUMP_DATA16, 5, 0, 3 * MS, false, false },
	{ "GYRO-CAL", 0, 65535, 0, 65535, NULL, 4, LUMP_DATA16, 5, 0, 3 * MS, false, false },
};

static const struct uart_sensor_mode ir_modes[] = {
	{ "IR-PROX", 0, 100, 0, 100, "pct", 1, LUMP_DATA8, 3, 0, 0, false, false },
	{ "IR-SEEK", -100, 100, -100, 100, "pct", 8, LUMP_DATA8, 3, 0, 0, false, false },
	{ "IR-REMOTE", 0, 10, 0, 10, "btn", 4, LUMP_DATA8, 3, 0, 0, false, false },
	{ "IR-REM-A", 0, 65535, 0, 65535, NULL, 1, LUMP_DATA16, 6, 0, 0, false, false },
	{ "IR-S-ALT", 0, 100, 0, 100, "pct", 4, LUMP_DATA8, 3, 0, 0, true, false },
	{ "IR-CAL", 0, 65535, 0, 65535, NULL, 2, LUMP_DATA16, 5, 0, 0, false, false },
};

/* Handshake durations are the captured ones (LEGO's d_uart_mod.c handshake, last step); the
 * auto-ID low times lie in the measured 502-506 ms. */
static const struct uart_sensor_def defs[] = {
	{ "EV3 colour sensor", UART_SENSOR_TYPE_COLOR, 6, 3, 57600, 503 * MS, 1300 * MS,
	  7 * MS, 80 * MS, 1000 * MS, 10 * MS, false, color_modes },
	{ "EV3 ultrasonic sensor", UART_SENSOR_TYPE_ULTRASONIC, 7, 3, 57600, 505 * MS, 1600 * MS,
	  7 * MS, 80 * MS, 1000 * MS, 10 * MS, false, us_modes },
	{ "EV3 gyro sensor", UART_SENSOR_TYPE_GYRO, 5, 2, 57600, 504 * MS, 1020 * MS,
	  7 * MS, 80 * MS, 1000 * MS, 10 * MS, false, gyro_modes },
	{ "EV3 infrared sensor", UART_SENSOR_TYPE_IR, 6, 3, 57600, 502 * MS, 1290 * MS,
	  7 * MS, 80 * MS, 1000 * MS, 10 * MS, true, ir_modes },
};

/* Built-in definition by type number. */
const struct uart_sensor_def *uart_sensor_def_for_type(uint8_t type)
{
	for (size_t i = 0; i < sizeof(defs) / sizeof(defs[0]); i++)
		if (defs[i].type == type)
			return &defs[i];
	return NULL;
}
