/*
 * ev3api.h — the EV3 C API for application tasks, in the paper's and EV3RT's
 * naming.
 *
 * Every call crosses the extended-service-call boundary into hacks/ (or reads
 * shared memory a driver published through its mmap), never driver
 * internals.  Every call returns a TOPPERS error code; values come back
 * through pointers:
 *   E_OK    done
 *   E_ID    bad port
 *   E_PAR   bad value or type
 *   E_OBJ   the port is not configured, or configured as another type
 *   E_MACV  a pointer the calling task may not access
 *   E_TMOUT a sensor did not deliver in time (no call waits without bound)
 *   E_CTX   called from non-task context (handlers, ISRs)
 *
 * docs/api.md has every function, its errors and an example.
 */
#ifndef EV3API_H
#define EV3API_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"
#include "rtos_cfg.h"

/* ---- Ports ---- */

typedef enum {
	EV3_PORT_A = 0, EV3_PORT_B, EV3_PORT_C, EV3_PORT_D,
	TNUM_MOTOR_PORT
} motor_port_t;

typedef enum {
	EV3_PORT_1 = 0, EV3_PORT_2, EV3_PORT_3, EV3_PORT_4,
	TNUM_SENSOR_PORT
} sensor_port_t;

/* ---- Motors ---- */

typedef enum {
	NONE_MOTOR = 0,          /* port not used */
	MEDIUM_MOTOR,            /* EV3 medium motor, speed-regulated */
	LARGE_MOTOR,             /* EV3 large motor, speed-regulated */
	UNREGULATED_MOTOR,       /* any DC motor, power only */
	TNUM_MOTOR_TYPE
} motor_type_t;

/* Declares what is on an output port; resets its counts.  E_ID, E_PAR. */
ER ev3_motor_config(motor_port_t port, motor_type_t type);
/* The configured type.  E_ID, E_MACV. */
ER ev3_motor_get_type(motor_port_t port, motor_type_t *p_type);
/* Runs at a regulated speed, -100..100 (% of the motor's maximum).  E_ID, E_PAR, E_OBJ. */
ER ev3_motor_set_speed(motor_port_t port, int speed);
/* Runs at an unregulated power, -100..100.  E_ID, E_PAR, E_OBJ. */
ER ev3_motor_set_power(motor_port_t port, int power);
/* Measured speed, -100..100.  E_ID, E_OBJ, E_MACV. */
ER ev3_motor_get_speed(motor_port_t port, int *p_speed);
/* Stops: brake = hold the position, else coast.  E_ID, E_OBJ. */
ER ev3_motor_stop(motor_port_t port, bool brake);
/* Cumulative tacho counts in degrees.  E_ID, E_OBJ, E_MACV. */
ER ev3_motor_get_counts(motor_port_t port, int32_t *p_counts);
/* Zeroes the cumulative counts.  E_ID, E_OBJ. */
ER ev3_motor_reset_counts(motor_port_t port);
/* Turns by degrees (sign gives the direction) at |speed| 1..100, then holds.
 * blocking: waits until done (E_TMOUT if the motor does not finish in time,
 * e.g. stalled).  E_ID, E_PAR, E_OBJ, E_CTX. */
ER ev3_motor_rotate(motor_port_t port, int degrees, int speed, bool blocking);
/* Whether a rotate/limited command is still running on the port.  E_ID, E_OBJ, E_MACV. */
ER ev3_motor_is_busy(motor_port_t port, bool *p_busy);
/* Drives two motors synchronised: speed -100..100, turn -200..200 (0 straight,
 * +-100 one wheel stopped, +-200 spinning on the spot).  E_ID, E_PAR, E_OBJ. */
ER ev3_motor_steer(motor_port_t left, motor_port_t right, int speed, int turn);
/* The same, stopping both after the first motor has turned by degrees (> 0). */
ER ev3_motor_sync(motor_port_t left, motor_port_t right, int speed, int turn, int degrees);

/* ---- Sensors ---- */

typedef enum {
	NONE_SENSOR = 0,
	ULTRASONIC_SENSOR,       /* EV3 ultrasonic (UART type 30) */
	GYRO_SENSOR,             /* EV3 gyro (UART type 32) */
	TOUCH_SENSOR,            /* EV3 touch (analog) */
	COLOR_SENSOR,            /* EV3 colour (UART type 29) */
	INFRARED_SENSOR,         /* EV3 infrared (UART type 33) */
	TNUM_SENSOR_TYPE
} sensor_type_t;

typedef enum {
	COLOR_NONE = 0, COLOR_BLACK, COLOR_BLUE, COLOR_GREEN,
	COLOR_YELLOW, COLOR_RED, COLOR_WHITE, COLOR_BROWN,
	TNUM_COLOR
} colorid_t;

typedef struct {
	uint16_t r, g, b;
} rgb_raw_t;

/* Declares what is on an input port and starts it.  E_ID, E_PAR. */
ER ev3_sensor_config(sensor_port_t port, sensor_type_t type);
/* The configured type.  E_ID, E_MACV. */
ER ev3_sensor_get_type(sensor_port_t port, sensor_type_t *p_type);

/* Gyro: angle in degrees since the last reset; rate in degrees/s. */
ER ev3_gyro_sensor_get_angle(sensor_port_t port, int16_t *p_angle);
ER ev3_gyro_sensor_get_rate(sensor_port_t port, int16_t *p_rate);
/* Restarts the angle at 0 (the sensor resets its angle on a mode change). */
ER ev3_gyro_sensor_reset(sensor_port_t port);

/* Ultrasonic: distance in cm (255 = nothing in range). */
ER ev3_ultrasonic_sensor_get_distance(sensor_port_t port, int16_t *p_cm);

/* Touch. */
ER ev3_touch_sensor_is_pressed(sensor_port_t port, bool *p_pressed);

/* Colour: one of 8 colours; reflected or ambient light 0..100 %; raw RGB. */
ER ev3_color_sensor_get_color(sensor_port_t port, colorid_t *p_color);
ER ev3_color_sensor_get_reflect(sensor_port_t port, uint8_t *p_pct);
ER ev3_color_sensor_get_ambient(sensor_port_t port, uint8_t *p_pct);
ER ev3_color_sensor_get_rgb_raw(sensor_port_t port, rgb_raw_t *p_rgb);

/* Infrared: proximity 0..100 %. */
ER ev3_infrared_sensor_get_distance(sensor_port_t port, int8_t *p_pct);

/* Any UART sensor: the newest raw sample of its current mode (at most 32 bytes). */
ER ev3_uart_sensor_get_raw(sensor_port_t port, void *buf, uint_t size);

/* ---- Brick ---- */

typedef enum {
	LED_OFF = 0, LED_RED, LED_GREEN, LED_ORANGE,
	TNUM_LED_COLOR
} ledcolor_t;

typedef enum {
	LEFT_BUTTON = 0, RIGHT_BUTTON, UP_BUTTON, DOWN_BUTTON, ENTER_BUTTON, BACK_BUTTON,
	TNUM_BUTTON
} button_t;

typedef void (*ev3_button_handler_t)(intptr_t exinf);

/* Both brick LEDs.  E_PAR, E_CTX. */
ER ev3_led_set_color(ledcolor_t color);
/* Whether the button is held down now (debounced).  E_ID, E_MACV. */
ER ev3_button_is_pressed(button_t button, bool *p_pressed);
/* Calls handler(exinf) in the button task (not in the GPIO interrupt) each
 * time the button is released after a press; NULL removes it.  E_ID, E_CTX. */
ER ev3_button_set_on_clicked(button_t button, ev3_button_handler_t handler, intptr_t exinf);

/*
 * The button task that runs click handlers, and the semaphore guarding the
 * handler table: IDs reserved from the top of the application ranges
 * (linux_compat holds task TNUM_TSKID).  The task runs in user domain
 * EV3_BUTTON_TASK_DOMAIN (the application's by convention; TDOM_KERNEL for
 * applications without user domains), so handlers have that domain's rights.
 * rel_wai(EV3_BUTTON_TSKID) stops it cleanly; act_tsk starts it again.
 * Each may be overridden at build time (-D).
 */
#ifndef EV3_BUTTON_TSKID
#define EV3_BUTTON_TSKID          (TNUM_TSKID - 1)
#endif
#ifndef EV3_BUTTON_SEMID
#define EV3_BUTTON_SEMID          TNUM_SEMID
#endif
#ifndef EV3_BUTTON_TASK_PRIORITY
#define EV3_BUTTON_TASK_PRIORITY  5
#endif
#ifndef EV3_BUTTON_TASK_DOMAIN
#define EV3_BUTTON_TASK_DOMAIN    1
#endif
#ifndef EV3_BUTTON_TASK_STACK
#define EV3_BUTTON_TASK_STACK     (16 * 1024)
#endif

#include "ev3api_battery.h"

/* ---- Configuration ---- */

/* What an application INCLUDEs: linux_compat, the four drivers' service calls,
 * the API's button task, and the memory regions the API reads. */
extern const struct rtos_cfg ev3api_cfg;

#endif /* EV3API_H */
