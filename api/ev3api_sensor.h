/*
 * ev3api_sensor.h — sensors (included by ev3api.h): EV3RT's calls and
 * ev3lx's checked forms (the naming rule is in ev3api.h).
 */
#ifndef EV3API_SENSOR_H
#define EV3API_SENSOR_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"

typedef enum {
	EV3_PORT_1 = 0, EV3_PORT_2 = 1, EV3_PORT_3 = 2, EV3_PORT_4 = 3,
	TNUM_SENSOR_PORT = 4
} sensor_port_t;

typedef enum {
	NONE_SENSOR = 0,
	ULTRASONIC_SENSOR = 1,   /* EV3 ultrasonic (UART type 30) */
	GYRO_SENSOR = 2,         /* EV3 gyro (UART type 32) */
	TOUCH_SENSOR = 3,        /* EV3 touch (analog) */
	COLOR_SENSOR = 4,        /* EV3 colour (UART type 29) */
	INFRARED_SENSOR = 5,     /* EV3 infrared (UART type 33) */
	HT_NXT_ACCEL_SENSOR = 6, /* HiTechnic NXT acceleration (I2C, d_iic) */
	HT_NXT_COLOR_SENSOR = 7, /* HiTechnic NXT colour, v1 or V2 (I2C, d_iic) */
	NXT_TEMP_SENSOR = 8,     /* LEGO NXT temperature (I2C, d_iic) */
	TNUM_SENSOR_TYPE = 9
} sensor_type_t;

typedef enum {
	COLOR_NONE = 0, COLOR_BLACK = 1, COLOR_BLUE = 2, COLOR_GREEN = 3,
	COLOR_YELLOW = 4, COLOR_RED = 5, COLOR_WHITE = 6, COLOR_BROWN = 7,
	TNUM_COLOR = 8
} colorid_t;

typedef struct {
	uint16_t r, g, b;
} rgb_raw_t;

/* Infrared beacon per channel (1..4 at index 0..3): heading -25..25,
 * distance 0..100 (-128: no beacon on the channel). */
typedef struct {
	int8_t heading[4];
	int8_t distance[4];
} ir_seek_t;

/* Infrared remote buttons held per channel, as a bit mask. */
typedef struct {
	uint8_t channel[4];
} ir_remote_t;

#define IR_RED_UP_BUTTON    1U
#define IR_RED_DOWN_BUTTON  2U
#define IR_BLUE_UP_BUTTON   4U
#define IR_BLUE_DOWN_BUTTON 8U
#define IR_BEACON_BUTTON    16U

/* ---- EV3RT (getters: 0 / false and a warning on error) ---- */

ER ev3_sensor_config(sensor_port_t port, sensor_type_t type);
/* The configured type, or E_ID. */
ER_UINT ev3_sensor_get_type(sensor_port_t port);

colorid_t ev3_color_sensor_get_color(sensor_port_t port);
uint8_t ev3_color_sensor_get_reflect(sensor_port_t port);     /* 0..100 */
uint8_t ev3_color_sensor_get_ambient(sensor_port_t port);     /* 0..100 */
void ev3_color_sensor_get_rgb_raw(sensor_port_t port, rgb_raw_t *val);

int16_t ev3_gyro_sensor_get_angle(sensor_port_t port);        /* degrees */
int16_t ev3_gyro_sensor_get_rate(sensor_port_t port);         /* degrees/s */
/* Recalibrates (GYRO-CAL) and restarts the angle at 0. */
ER ev3_gyro_sensor_reset(sensor_port_t port);

int16_t ev3_ultrasonic_sensor_get_distance(sensor_port_t port);   /* cm */
/* Whether another ultrasonic sensor is heard. */
bool_t ev3_ultrasonic_sensor_listen(sensor_port_t port);

int8_t ev3_infrared_sensor_get_distance(sensor_port_t port);  /* 0..100 */
ir_seek_t ev3_infrared_sensor_seek(sensor_port_t port);
ir_remote_t ev3_infrared_sensor_get_remote(sensor_port_t port);

bool_t ev3_touch_sensor_is_pressed(sensor_port_t port);

/* NXT I2C sensors (true when measured): acceleration X, Y, Z in counts (10-bit,
 * about 200 per g); HiTechnic colour number (0..17) and RGB (0..255 each);
 * temperature in degrees Celsius (1/16 degree steps). */
bool_t ht_nxt_accel_sensor_measure(sensor_port_t port, int16_t axes[3]);
bool_t ht_nxt_color_sensor_measure_color(sensor_port_t port, uint8_t *color);
bool_t ht_nxt_color_sensor_measure_rgb(sensor_port_t port, rgb_raw_t *val);
bool_t nxt_temp_sensor_measure(sensor_port_t port, float *temp);

/* ---- ev3lx's checked forms ---- */

/* Declares what is on an input port and starts it (an NXT I2C type: d_iic
 * probes the sensor and polls it).  E_ID, E_PAR, E_OBJ (a driver is not
 * loaded), E_CTX. */
ER ev3lx_sensor_config(sensor_port_t port, sensor_type_t type);
/* The configured type.  E_ID, E_MACV. */
ER ev3lx_sensor_get_type(sensor_port_t port, sensor_type_t *p_type);

/* The readers below answer E_ID, E_OBJ (not configured as that type, or
 * another kind of sensor answered), E_MACV, E_TMOUT, E_CTX (when the sensor
 * must be waited for outside a task). */

/* Gyro: angle in degrees since the last reset; rate in degrees/s. */
ER ev3lx_gyro_sensor_get_angle(sensor_port_t port, int16_t *p_angle);
ER ev3lx_gyro_sensor_get_rate(sensor_port_t port, int16_t *p_rate);
/* Recalibrates (GYRO-CAL) and restarts the angle at 0. */
ER ev3lx_gyro_sensor_reset(sensor_port_t port);

/* Ultrasonic: distance in cm (255 = nothing in range); whether another
 * ultrasonic sensor is heard (US-LISTEN). */
ER ev3lx_ultrasonic_sensor_get_distance(sensor_port_t port, int16_t *p_cm);
ER ev3lx_ultrasonic_sensor_listen(sensor_port_t port, bool *p_heard);

/* Touch. */
ER ev3lx_touch_sensor_is_pressed(sensor_port_t port, bool *p_pressed);

/* Colour: one of 8 colours; reflected or ambient light 0..100 %; raw RGB. */
ER ev3lx_color_sensor_get_color(sensor_port_t port, colorid_t *p_color);
ER ev3lx_color_sensor_get_reflect(sensor_port_t port, uint8_t *p_pct);
ER ev3lx_color_sensor_get_ambient(sensor_port_t port, uint8_t *p_pct);
ER ev3lx_color_sensor_get_rgb_raw(sensor_port_t port, rgb_raw_t *p_rgb);

/* Infrared: proximity 0..100 %; beacons (IR-SEEK); remote buttons (IR-REMOTE). */
ER ev3lx_infrared_sensor_get_distance(sensor_port_t port, int8_t *p_pct);
ER ev3lx_infrared_sensor_seek(sensor_port_t port, ir_seek_t *p_seek);
ER ev3lx_infrared_sensor_get_remote(sensor_port_t port, ir_remote_t *p_remote);

/* NXT I2C sensors: the newest polled answer.  The first reading after
 * ev3lx_sensor_config waits for the probe and the first poll (E_TMOUT after
 * 1 s) and checks the probed identification (E_OBJ if it is not the
 * configured sensor's). */
ER ev3lx_ht_nxt_accel_sensor_measure(sensor_port_t port, int16_t axes[3]);
ER ev3lx_ht_nxt_color_sensor_measure_color(sensor_port_t port, uint8_t *p_color);
ER ev3lx_ht_nxt_color_sensor_measure_rgb(sensor_port_t port, rgb_raw_t *p_rgb);
ER ev3lx_nxt_temp_sensor_measure(sensor_port_t port, float *p_temp);

/* Any UART sensor: the newest raw sample of its current mode (at most 32 bytes). */
ER ev3lx_uart_sensor_get_raw(sensor_port_t port, void *buf, uint_t size);

#ifdef __cplusplus
}
#endif

#endif /* EV3API_SENSOR_H */
