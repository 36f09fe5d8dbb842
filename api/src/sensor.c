/*
 * sensor.c — the EV3 sensor API: UART sensors over d_uart, the touch sensor
 * over d_analog (the NXT I2C sensors over d_iic are in nxt_sensor.c).
 *
 * A value is read from the drivers' shared memory with no service call when
 * the newest sample is valid data of the wanted mode (lms_uart_sample).  Only
 * when it is not — the sensor is still shaking hands, the mode must change,
 * or d_uart waits for its new description to be accepted — does the call
 * take the slow path: service calls and 1 ms sleeps, bounded by a timeout
 * (E_TMOUT), so an unplugged sensor never blocks a task for good.
 */
#include <string.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "api_internal.h"
#include "analog_hack.h"
#include "uart_hack.h"

/* How long a read may wait for a sensor that is still starting (handshake at
 * 2400 baud takes up to ~1.6 s after the 0.5 s power-up) and for the first
 * sample after a mode change (the IR sensor needs 1.1 s). */
#define START_TIMEOUT_MS   4000U
#define MODE_TIMEOUT_MS    1500U
#define POLL_MS            1U

/* The touch sensor's pin 6 is high while pressed: half the ADC scale decides. */
#define TOUCH_PRESSED_RAW  (LMS_ADC_MAX / 2U)

/* LEGO device types of the UART sensors. */
#define LMS_TYPE_COLOR       29
#define LMS_TYPE_ULTRASONIC  30
#define LMS_TYPE_GYRO        32
#define LMS_TYPE_INFRARED    33

/* Sensor modes used by the API. */
enum {
	COLOR_MODE_REFLECT = 0, COLOR_MODE_AMBIENT = 1, COLOR_MODE_COLOR = 2, COLOR_MODE_RGB_RAW = 4,
	US_MODE_DIST_CM = 0,
	US_MODE_LISTEN = 2,
	GYRO_MODE_ANGLE = 0, GYRO_MODE_RATE = 1, GYRO_MODE_CAL = 4,
	IR_MODE_PROX = 0, IR_MODE_SEEK = 1, IR_MODE_REMOTE = 2,
};

/*
 * IR-REMOTE reports per channel a code of the buttons held (LEGO's EV3
 * infrared sensor documentation): 0 none, 1..4 one of red up, red down,
 * blue up, blue down, 5..8 a red with a blue button, 9 the beacon button,
 * 10 both red, 11 both blue.  The API gives them as bit masks.
 */
static const uint8_t remote_buttons_of[] = {
	[0] = 0,
	[1] = IR_RED_UP_BUTTON, [2] = IR_RED_DOWN_BUTTON,
	[3] = IR_BLUE_UP_BUTTON, [4] = IR_BLUE_DOWN_BUTTON,
	[5] = IR_RED_UP_BUTTON | IR_BLUE_UP_BUTTON, [6] = IR_RED_UP_BUTTON | IR_BLUE_DOWN_BUTTON,
	[7] = IR_RED_DOWN_BUTTON | IR_BLUE_UP_BUTTON, [8] = IR_RED_DOWN_BUTTON | IR_BLUE_DOWN_BUTTON,
	[9] = IR_BEACON_BUTTON,
	[10] = IR_RED_UP_BUTTON | IR_RED_DOWN_BUTTON, [11] = IR_BLUE_UP_BUTTON | IR_BLUE_DOWN_BUTTON,
};

static sensor_type_t sensor_type[TNUM_SENSOR_PORT];
/*
 * Ports whose sensor never answered within a read's wait (START_TIMEOUT_MS):
 * nothing is plugged in, or what is does not speak.  Their reads fail at once
 * (E_TMOUT) while d_uart still hears nothing, instead of each waiting the
 * whole bound again; a sensor that starts its handshake is waited for anew.
 */
static bool silent[TNUM_SENSOR_PORT];
/*
 * A mode switch in flight per port: the mode a read selected and is still waiting
 * for, and when it selected it.  A read of another mode waits for that read's
 * sample instead of switching back — two tasks reading one sensor in two modes
 * would otherwise undo each other's switch until both time out.  A switch older
 * than MODE_TIMEOUT_MS is abandoned (its reader gave up) and may be overridden.
 */
#define NO_MODE  (-1)
static int switching_mode[TNUM_SENSOR_PORT];
static SYSTIM switching_since[TNUM_SENSOR_PORT];
static const struct lms_uart_shm *uart_shm;
static const struct lms_analog *analog_shm;

/* The LEGO type a UART sensor type must report, 0 for analog sensors. */
static int lms_type_of(sensor_type_t type)
{
	switch (type) {
	case ULTRASONIC_SENSOR: return LMS_TYPE_ULTRASONIC;
	case GYRO_SENSOR:       return LMS_TYPE_GYRO;
	case COLOR_SENSOR:      return LMS_TYPE_COLOR;
	case INFRARED_SENSOR:   return LMS_TYPE_INFRARED;
	default:                return 0;
	}
}

/* Maps the drivers' shared memory once. */
static ER map_shared_memory(void)
{
	ER ercd = E_OK;

	if (uart_shm == NULL) {
		const struct lms_uart_shm *map = NULL;

		ercd = uart_svc_map(&map);
		if (ercd == E_OK)
			uart_shm = map;
	}
	if (ercd == E_OK && analog_shm == NULL) {
		const struct lms_analog *map = NULL;

		ercd = analog_map(&map);
		if (ercd == E_OK)
			analog_shm = map;
	}
	return ercd;
}

void api_sensor_boot(void)
{
	memset(sensor_type, 0, sizeof(sensor_type));
	memset(silent, 0, sizeof(silent));
	for (unsigned i = 0; i < TNUM_SENSOR_PORT; i++)
		switching_mode[i] = NO_MODE;
	uart_shm = NULL;
	analog_shm = NULL;
	api_iic_boot();
}

ER ev3lx_sensor_config(sensor_port_t port, sensor_type_t type)
{
	sensor_type_t old;
	ER ercd = api_may_wait();

	if (ercd != E_OK)
		return ercd;
	if ((unsigned)port >= TNUM_SENSOR_PORT)
		return E_ID;
	if ((unsigned)type >= TNUM_SENSOR_TYPE)
		return E_PAR;
	ercd = map_shared_memory();
	if (ercd != E_OK)
		return ercd;
	old = sensor_type[port];
	/* The driver leaving the port first: d_uart and d_iic both drive its TX buffer. */
	if (lms_type_of(old) != 0 && lms_type_of(type) == 0) {
		ercd = uart_svc_stop((uint_t)port);
		if (ercd != E_OK)
			return ercd;
	}
	ercd = api_iic_config((unsigned)port, (int)old, (int)type);
	if (ercd != E_OK)
		return ercd;
	if (lms_type_of(type) != 0) {
		/* Mode 0 first; the readers select what they need. */
		ercd = uart_svc_set_mode((uint_t)port, 0);
		if (ercd != E_OK)
			return ercd;
	}
	sensor_type[port] = type;
	silent[port] = false;
	return E_OK;
}

ER ev3lx_sensor_get_type(sensor_port_t port, sensor_type_t *p_type)
{
	ER ercd = api_may_read();

	if (ercd != E_OK)
		return ercd;
	if ((unsigned)port >= TNUM_SENSOR_PORT)
		return E_ID;
	ercd = API_CHECK_OUT(p_type);
	if (ercd != E_OK)
		return ercd;
	*p_type = sensor_type[port];
	return E_OK;
}

/* E_OK if a reading may be made here, port is valid and configured as type, and out
 * (out_check: its API_CHECK_OUT) may take the value. */
static ER check_sensor(sensor_port_t port, sensor_type_t type, ER out_check)
{
	return api_sensor_check((unsigned)port, (int)type, out_check);
}

ER api_sensor_check(unsigned port, int type, ER out_check)
{
	ER ercd = api_may_read();

	if (ercd != E_OK)
		return ercd;
	if (port >= TNUM_SENSOR_PORT)
		return E_ID;
	if ((int)sensor_type[port] != type)
		return E_OBJ;
	return out_check;
}

/* Whether d_uart hears no sensor on a port in state: nothing started a handshake
 * (IDLE, SYNC), or the handshakes failed and the port fell back to raw bytes (TERMINAL). */
static bool hears_nothing(uint8_t state)
{
	return state <= LMS_UART_STATE_SYNC || state == LMS_UART_STATE_TERMINAL;
}

/* Whether another read's switch to a mode other than mode is still awaiting its sample on port. */
static bool other_switch_in_flight(sensor_port_t port, int mode, SYSTIM now)
{
	return switching_mode[port] != NO_MODE && switching_mode[port] != mode &&
	       now - switching_since[port] < MODE_TIMEOUT_MS;
}

/*
 * The slow path of a UART read: brings the port to valid data of mode and
 * returns the sample, selecting the mode and accepting a new description as
 * needed; E_OBJ if another kind of sensor answered, E_TMOUT on timeout.
 */
static ER wait_sample(sensor_port_t port, int mode, const int8_t **p_sample)
{
	const struct lms_uart_port_ext *ext = &uart_shm->ext.port[port];
	int expected = lms_type_of(sensor_type[port]);
	RELTIM waited = 0, limit = START_TIMEOUT_MS;
	SYSTIM since, now;          /* the wait's bounds are virtual time, polls and calls included */
	bool in_data = false;
	ER ercd = api_may_wait();

	if (ercd != E_OK)
		return ercd;
	get_tim(&since);
	now = since;
	for (;;) {
		uint8_t state = *(const volatile uint8_t *)&ext->state;
		int8_t status = *(const volatile int8_t *)&uart_shm->lms.status[port];
		const int8_t *sample;

		/* still nothing from a port that was waited for once: no second wait */
		if (silent[port] && hears_nothing(state))
			return E_TMOUT;
		silent[port] = false;

		/* the description is published when the host's ACK goes out (state SPEED) */
		if (state >= LMS_UART_STATE_SPEED && state != LMS_UART_STATE_TERMINAL &&
		    uart_shm->lms.types[port][0].type != expected)
			return E_OBJ;
		if (status & LMS_UART_PORT_CHANGED)
			(void)uart_svc_clear_changed((uint_t)port);
		if (state == LMS_UART_STATE_DATA && !in_data) {
			/* the handshake is done: from now on, the wait for a mode's data */
			in_data = true;
			since = now;
			waited = 0;
			limit = MODE_TIMEOUT_MS;
		} else if (state != LMS_UART_STATE_DATA && in_data) {
			/* the sensor reconnects: a whole handshake's bound again */
			in_data = false;
			since = now;
			waited = 0;
			limit = START_TIMEOUT_MS;
		}
		if (state == LMS_UART_STATE_DATA &&
		    *(const volatile int8_t *)&ext->mode != mode) {
			if (other_switch_in_flight(port, mode, now)) {
				/* our bound starts when that read has its sample */
				since = now;
				waited = 0;
			} else {
				switching_mode[port] = mode;
				switching_since[port] = now;
				ercd = uart_svc_set_mode((uint_t)port, (uint_t)mode);
				if (ercd != E_OK) {
					switching_mode[port] = NO_MODE;
					return ercd;
				}
			}
		}
		sample = lms_uart_sample(uart_shm, (unsigned)port, mode);
		if (sample != NULL) {
			if (switching_mode[port] == mode)
				switching_mode[port] = NO_MODE;
			*p_sample = sample;
			return E_OK;
		}
		if (waited >= limit) {
			if (switching_mode[port] == mode)
				switching_mode[port] = NO_MODE;
			/* nothing heard for a whole handshake's bound: the port is silent */
			if (!in_data && hears_nothing(state))
				silent[port] = true;
			return E_TMOUT;
		}
		dly_tsk(POLL_MS);
		get_tim(&now);
		waited = (RELTIM)(now - since);
	}
}

/* Copies size bytes of the newest sample of mode into out (fast path first); out_check is
 * the API_CHECK_OUT of the caller's pointer the value goes to. */
static ER read_uart(sensor_port_t port, sensor_type_t type, int mode, void *out, SIZE size,
		    ER out_check)
{
	const int8_t *sample;
	ER ercd = check_sensor(port, type, out_check);

	if (ercd != E_OK)
		return ercd;
	sample = lms_uart_sample(uart_shm, (unsigned)port, mode);
	if (sample == NULL) {
		ercd = wait_sample(port, mode, &sample);
		if (ercd != E_OK)
			return ercd;
	}
	memcpy(out, sample, size);
	return E_OK;
}

/* A little-endian 16-bit value from a sample. */
static int16_t le16(const uint8_t *p)
{
	return (int16_t)(uint16_t)(p[0] | (uint16_t)p[1] << 8);
}

/* A 16-bit reading of mode, divided by divisor, into out. */
static ER read_s16(sensor_port_t port, sensor_type_t type, int mode, int16_t divisor, int16_t *out)
{
	uint8_t raw[2];
	ER ercd;

	ercd = read_uart(port, type, mode, raw, sizeof(raw), API_CHECK_OUT(out));
	if (ercd == E_OK)
		*out = (int16_t)(le16(raw) / divisor);
	return ercd;
}

ER ev3lx_gyro_sensor_get_angle(sensor_port_t port, int16_t *p_angle)
{
	return read_s16(port, GYRO_SENSOR, GYRO_MODE_ANGLE, 1, p_angle);
}

ER ev3lx_gyro_sensor_get_rate(sensor_port_t port, int16_t *p_rate)
{
	return read_s16(port, GYRO_SENSOR, GYRO_MODE_RATE, 1, p_rate);
}

ER ev3lx_gyro_sensor_reset(sensor_port_t port)
{
	uint8_t raw[2];
	ER ercd;

	/* GYRO-CAL recalibrates; any mode change restarts the angle at 0. */
	ercd = api_may_wait();
	if (ercd == E_OK)
		ercd = read_uart(port, GYRO_SENSOR, GYRO_MODE_CAL, raw, sizeof(raw), E_OK);
	if (ercd == E_OK)
		ercd = read_uart(port, GYRO_SENSOR, GYRO_MODE_ANGLE, raw, sizeof(raw), E_OK);
	return ercd;
}

ER ev3lx_ultrasonic_sensor_get_distance(sensor_port_t port, int16_t *p_cm)
{
	/* the sensor reports tenths of a cm */
	return read_s16(port, ULTRASONIC_SENSOR, US_MODE_DIST_CM, 10, p_cm);
}

ER ev3lx_ultrasonic_sensor_listen(sensor_port_t port, bool *p_heard)
{
	uint8_t raw;
	ER ercd;

	ercd = read_uart(port, ULTRASONIC_SENSOR, US_MODE_LISTEN, &raw, 1, API_CHECK_OUT(p_heard));
	if (ercd == E_OK)
		*p_heard = raw != 0;
	return ercd;
}

ER ev3lx_touch_sensor_is_pressed(sensor_port_t port, bool *p_pressed)
{
	ER ercd = check_sensor(port, TOUCH_SENSOR, API_CHECK_OUT(p_pressed));

	if (ercd != E_OK)
		return ercd;
	/*
	 * The touch sensor is an EV3 analog device (InConn INPUT_DUMB) whose switch drives pin 6.
	 * Before detection has run (d_analog starts it 2 s after loading) and on an empty port the
	 * connection is NONE: pin 6 is read live all the same, and an empty port's pin 6 is low,
	 * so an unplugged sensor reads as not pressed, never as a frozen value.  Any other device
	 * detected on the port is E_OBJ.
	 */
	switch (*(const volatile int8_t *)&analog_shm->in_conn[port]) {
	case LMS_CONN_INPUT_DUMB:
	case LMS_CONN_NONE:
		*p_pressed = *(const volatile uint16_t *)&analog_shm->in_pin6[port] > TOUCH_PRESSED_RAW;
		return E_OK;
	default:
		return E_OBJ;
	}
}

ER ev3lx_color_sensor_get_color(sensor_port_t port, colorid_t *p_color)
{
	uint8_t raw;
	ER ercd;

	ercd = read_uart(port, COLOR_SENSOR, COLOR_MODE_COLOR, &raw, 1, API_CHECK_OUT(p_color));
	if (ercd == E_OK)
		*p_color = raw < TNUM_COLOR ? (colorid_t)raw : COLOR_NONE;
	return ercd;
}

ER ev3lx_color_sensor_get_reflect(sensor_port_t port, uint8_t *p_pct)
{
	return read_uart(port, COLOR_SENSOR, COLOR_MODE_REFLECT, p_pct, 1, API_CHECK_OUT(p_pct));
}

ER ev3lx_color_sensor_get_ambient(sensor_port_t port, uint8_t *p_pct)
{
	return read_uart(port, COLOR_SENSOR, COLOR_MODE_AMBIENT, p_pct, 1, API_CHECK_OUT(p_pct));
}

ER ev3lx_color_sensor_get_rgb_raw(sensor_port_t port, rgb_raw_t *p_rgb)
{
	uint8_t raw[6];
	ER ercd;

	ercd = read_uart(port, COLOR_SENSOR, COLOR_MODE_RGB_RAW, raw, sizeof(raw), API_CHECK_OUT(p_rgb));
	if (ercd == E_OK) {
		p_rgb->r = (uint16_t)le16(&raw[0]);
		p_rgb->g = (uint16_t)le16(&raw[2]);
		p_rgb->b = (uint16_t)le16(&raw[4]);
	}
	return ercd;
}

ER ev3lx_infrared_sensor_get_distance(sensor_port_t port, int8_t *p_pct)
{
	return read_uart(port, INFRARED_SENSOR, IR_MODE_PROX, p_pct, 1, API_CHECK_OUT(p_pct));
}

ER ev3lx_infrared_sensor_seek(sensor_port_t port, ir_seek_t *p_seek)
{
	int8_t raw[8];
	ER ercd;

	ercd = read_uart(port, INFRARED_SENSOR, IR_MODE_SEEK, raw, sizeof(raw), API_CHECK_OUT(p_seek));
	if (ercd == E_OK) {
		/* the sample is heading, distance of channel 1, then of 2, 3, 4 */
		for (unsigned c = 0; c < 4; c++) {
			p_seek->heading[c] = raw[2 * c];
			p_seek->distance[c] = raw[2 * c + 1];
		}
	}
	return ercd;
}

ER ev3lx_infrared_sensor_get_remote(sensor_port_t port, ir_remote_t *p_remote)
{
	uint8_t raw[4];
	ER ercd;

	ercd = read_uart(port, INFRARED_SENSOR, IR_MODE_REMOTE, raw, sizeof(raw), API_CHECK_OUT(p_remote));
	if (ercd == E_OK) {
		for (unsigned c = 0; c < 4; c++)
			p_remote->channel[c] = raw[c] < sizeof(remote_buttons_of) ? remote_buttons_of[raw[c]] : 0U;
	}
	return ercd;
}

ER ev3lx_uart_sensor_get_raw(sensor_port_t port, void *buf, uint_t size)
{
	const int8_t *sample;
	int mode;
	bool_t in_task = !sns_ctx();       /* asked once for both checks */
	ER ercd;

	if (in_task && sns_loc())          /* api_may_read */
		return E_CTX;
	if ((unsigned)port >= TNUM_SENSOR_PORT)
		return E_ID;
	if (lms_type_of(sensor_type[port]) == 0)
		return E_OBJ;
	if (size == 0 || size > LMS_UART_DATA_SIZE)
		return E_PAR;
	ercd = api_check_out_in(buf, size, 1, in_task);
	if (ercd != E_OK)
		return ercd;
	mode = (int)*(const volatile int8_t *)&uart_shm->ext.port[port].mode;	/* signed: -1 is none */
	sample = lms_uart_sample(uart_shm, (unsigned)port, mode);
	if (sample == NULL) {
		ercd = wait_sample(port, mode < 0 ? 0 : mode, &sample);
		if (ercd != E_OK)
			return ercd;
	}
	memcpy(buf, sample, size);
	return E_OK;
}
