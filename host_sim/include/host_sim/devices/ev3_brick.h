/*
 * ev3_brick.h — the EV3 around the AM1808: what is plugged into each port,
 * the electrical level of every port pin, the battery, and seeded fault
 * injection.  A scenario boots the board with ev3_board_devices, then
 * attaches devices per port (at any virtual time: attaching is plugging
 * in).  Host only.  docs/host-sim-devices.md describes every model.
 *
 *   struct hs_board_cfg board = { .devices = ev3_board_devices };
 *   struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 7 };
 *   hs_sim_boot(&scn);
 *   ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);              port A
 *   ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_GYRO, NULL);  port 1
 */
#ifndef HOST_SIM_DEVICES_EV3_BRICK_H
#define HOST_SIM_DEVICES_EV3_BRICK_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"
#include "host_sim/board.h"
#include "host_sim/devices/ev3_motor.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/uart_sensor.h"

/* Every EV3 peripheral model (eHRPWM1, eCAP0/1, SPI0 + ADC, the four port
 * UARTs, the ports, the brick buttons and LEDs of ev3_ui.h, the battery and
 * power pins of ev3_power.h), NULL-terminated,
 * for hs_board_cfg.devices. */
extern const struct hs_device *const ev3_board_devices[];
/* The ports' model (input pins, sensor links, motors, faults), one of them. */
extern const struct hs_device ev3_ports_device;

/* Battery EMF (open-circuit voltage) in mV (default EV3_BATTERY_MV_DEFAULT): the motors run
 * from it; the ADC sees the terminal voltage, which sags with the current (ev3_power.h). */
#define EV3_BATTERY_MV_DEFAULT	9000U
uint32_t ev3_battery_mv(void);
void ev3_set_battery_mv(uint32_t mv);
/* Records the voltage without telling anyone (the ports model does the telling). */
void ev3_battery_store(uint32_t mv);
/* Sum of the motors' currents now, amperes (the battery model of ev3_power.h adds the brick's draw). */
double ev3_motors_current_a(void);

/* ---- input ports (0..3 = ports 1..4) ---- */

enum ev3_input_kind {
	EV3_INPUT_NONE = 0,
	EV3_INPUT_EV3_TOUCH,        /* EV3 touch 45507: ID resistor on pin 1, state on pin 6 */
	EV3_INPUT_NXT_TOUCH,        /* NXT touch: pin 2 grounded, switch on pin 1 */
	EV3_INPUT_NXT_LIGHT,        /* NXT light: pin 2 grounded, pin 5 pulled low, light on pin 1 */
	EV3_INPUT_DUMB,             /* any device with an ID resistor on pin 1 */
	EV3_INPUT_UART,             /* an EV3 UART sensor */
	EV3_INPUT_NXT_IIC,          /* an NXT I2C sensor (nxt_iic.h): pin 2 grounded, bus on pins 5/6 */
};

/* Options of an analog device. */
struct ev3_analog_options {
	uint32_t id_ohms;           /* EV3_INPUT_DUMB: ID resistor pin 1 -> ground */
	uint32_t bounce_us;         /* touch sensors: contact bounce after each change (0: none) */
};

/* Plugs an analog device into an input port (replacing what was there).
 * Returns E_OK, E_ID for a bad port, E_PAR for a bad kind, E_OBJ without a board. */
ER ev3_attach_analog(unsigned port, enum ev3_input_kind kind, const struct ev3_analog_options *opt);
/* Plugs a UART sensor (type 29, 30, 32, 33) in; it powers up at once. */
ER ev3_attach_uart_sensor(unsigned port, uint8_t type, const struct uart_sensor_options *opt);
/* Unplugs whatever is on the input port. */
ER ev3_detach_input(unsigned port);
/* What is on the port. */
enum ev3_input_kind ev3_input_kind_of(unsigned port);
/* The UART sensor on the port, or NULL. */
struct uart_sensor *ev3_input_uart_sensor(unsigned port);

/* Touch state (EV3 or NXT touch), with bounce if configured. */
ER ev3_set_touch(unsigned port, bool pressed);
/* NXT light sensor reading 0..100 % (brighter = lower voltage). */
ER ev3_set_light(unsigned port, unsigned pct);
/* Scene of a UART sensor (see uart_sensor_scene). */
ER ev3_set_scene(unsigned port, const struct uart_sensor_scene *scene);

/* Voltage of an input port pin (1, 2, 5, 6) in mV as the ADC/GPIO see it now. */
uint32_t ev3_input_pin_mv(unsigned port, unsigned pin);

/* ---- output ports (0..3 = A..D) ---- */

/* Plugs a motor into an output port; E_ID, E_PAR, E_OBJ as above. */
ER ev3_attach_motor(unsigned port, enum hs_motor_kind kind, const struct hs_motor_options *opt);
ER ev3_detach_output(unsigned port);
/* The motor on the port, or NULL. */
struct hs_motor *ev3_output_motor(unsigned port);
/* Voltage of output pin 5 in mV now. */
uint32_t ev3_output_pin5_mv(unsigned port);

/* ---- ADC inputs ---- */

/* Voltage (mV, 0..5000) on ADC channel ch (0..15) now, before ADC noise. */
uint32_t ev3_adc_channel_mv(unsigned ch);

/* What an ADC channel measures: its ev3_adc_channel_mv is mv(arg).  The
 * converter asks once per channel, then calls mv on every frame (ten
 * thousand per second) without ev3_adc_channel_mv's dispatch. */
struct ev3_adc_source {
	uint32_t (*mv)(unsigned arg);
	unsigned arg;
};
struct ev3_adc_source ev3_adc_channel_source(unsigned ch);

/* ---- faults (seeded, at scenario times) ---- */

enum ev3_fault_kind {
	EV3_FAULT_UART_BIT_ERRORS,  /* input port: value = probability a sensor byte gets one bit flipped */
	EV3_FAULT_UART_DROP,        /* input port: value = probability a sensor byte is lost */
	EV3_FAULT_UART_DUPLICATE,   /* input port: value = probability a sensor byte arrives twice */
	EV3_FAULT_UNPLUG,           /* input port: unplug; replug after duration (0: stays out) */
	EV3_FAULT_MOTOR_UNPLUG,     /* output port: unplug the motor; replug after duration */
	EV3_FAULT_ENCODER_STUCK,    /* output port: tacho outputs frozen for duration */
	EV3_FAULT_ENCODER_NOISE,    /* output port: value = glitches per second, for duration */
	EV3_FAULT_MOTOR_STALL,      /* output port: shaft locked for duration */
	EV3_FAULT_ADC_NOISE,        /* port ignored: value = noise standard deviation in mV */
};

struct ev3_fault {
	enum ev3_fault_kind kind;
	unsigned port;
	double value;
	uint64_t duration_ns;       /* 0: until the end of the run */
};

/* Schedules a fault at absolute virtual time t_ns.  E_PAR/E_ID on bad fields. */
ER ev3_fault_at(uint64_t t_ns, const struct ev3_fault *f);

/* One entry of the fault log: what started or ended, and when. */
struct ev3_fault_record {
	uint64_t t_ns;
	enum ev3_fault_kind kind;
	unsigned port;
	bool start;
};
/* Number of log entries so far, and entry i. */
unsigned ev3_fault_log_count(void);
const struct ev3_fault_record *ev3_fault_log(unsigned i);
/* Bytes the UART faults changed so far on an input port: flipped, dropped, duplicated. */
void ev3_fault_uart_counts(unsigned port, uint32_t *flipped, uint32_t *dropped, uint32_t *duplicated);
/* Current ADC noise standard deviation (mV) and the generator it draws from. */
double ev3_adc_noise_mv(void);
/* Where ev3_adc_noise_mv is kept: the converter reads it on every frame without a call. */
const double *ev3_adc_noise_mv_ref(void);
double ev3_adc_noise_sample(void);

#endif /* HOST_SIM_DEVICES_EV3_BRICK_H */
