/*
 * nxt_sensor.c — the NXT I2C sensors of EV3RT's API over d_iic: the
 * HiTechnic accelerometer and colour sensor and LEGO's NXT temperature
 * sensor.
 *
 * Configuring a port hands it to d_iic (which probes the sensor) and gives
 * the driver the sensor's setup and poll strings, so the driver polls it on
 * its own and a reading is the newest answer in the shared memory's raw ring
 * (no service call).  Only before the first answer does a reading wait
 * (1 ms sleeps, bounded by a timeout: E_TMOUT), checking once that the probed
 * identification is the configured sensor's (E_OBJ otherwise).
 *
 * Registers (HiTechnic's sensor documentation; the temperature sensor is an
 * LM75/TMP275-class part at 0x4C): accelerometer at address 0x01, 0x42..0x44
 * the upper 8 bits of X, Y, Z and 0x45..0x47 their lower 2 bits; colour at
 * 0x01, 0x42 the colour number, 0x43..0x45 red, green, blue; temperature at
 * 0x4C, configuration register 1 set to 0x60 (12 bits), register 0 two bytes
 * of 1/16 degree steps.  Answers are kept in bus order (negative read length).
 */
#include <string.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "api_internal.h"
#include "iic_hack.h"

#define FIRST_SAMPLE_TIMEOUT_MS 1000U   /* probe (~30 ms) plus the first poll */
#define POLL_MS                 1U

struct nxt_sensor_def {
	const char *manufacturer;       /* compared without case, first 8 characters */
	const char *sensor_type;        /* prefix of the probed type */
	uint32_t setup, poll;           /* MSB-first strings, address first */
	int8_t setup_lng, poll_lng, read_lng;
	int16_t period_ms;
};

static const struct nxt_sensor_def nxt_defs[TNUM_SENSOR_TYPE] = {
	[HT_NXT_ACCEL_SENSOR] = { "HITECHNC", "Accel", 0, 0x01420000U, 0, 2, -6, 10 },
	[HT_NXT_COLOR_SENSOR] = { "HITECHNC", "Color", 0, 0x01420000U, 0, 2, -4, 10 },
	[NXT_TEMP_SENSOR]     = { "LEGO", "Temp.", 0x4C016000U, 0x4C000000U, 3, 2, -2, 100 },
};

static const struct lms_iic *iic_shm;
static bool verified[TNUM_SENSOR_PORT];

static bool is_iic_type(int type)
{
	return type == HT_NXT_ACCEL_SENSOR || type == HT_NXT_COLOR_SENSOR || type == NXT_TEMP_SENSOR;
}

void api_iic_boot(void)
{
	iic_shm = NULL;
	memset(verified, 0, sizeof(verified));
}

ER api_iic_config(unsigned port, int old_type, int type)
{
	const struct nxt_sensor_def *def;
	struct lms_iic_str s;
	ER ercd;

	if (is_iic_type(old_type) && !is_iic_type(type)) {
		ercd = iic_svc_stop(port);
		if (ercd != E_OK)
			return ercd;
	}
	if (!is_iic_type(type))
		return E_OK;
	if (iic_shm == NULL) {
		const struct lms_iic *map = NULL;

		ercd = iic_svc_map(&map);
		if (ercd != E_OK)
			return ercd;
		iic_shm = map;
	}
	def = &nxt_defs[type];
	memset(&s, 0, sizeof(s));
	s.port = (int8_t)port;
	s.time = def->period_ms;
	s.setup_string = def->setup;
	s.setup_lng = def->setup_lng;
	s.poll_string = def->poll;
	s.poll_lng = def->poll_lng;
	s.read_lng = def->read_lng;
	verified[port] = false;
	/* stop first: a new type on a running port is probed again from scratch */
	ercd = iic_svc_stop(port);
	if (ercd == E_OK)
		ercd = iic_svc_start(port, 0);
	if (ercd == E_OK)
		ercd = iic_svc_set(&s);
	return ercd;
}

/* Whether the probed strings are those of the configured sensor. */
static bool identity_matches(const struct lms_iic_str *s, const struct nxt_sensor_def *def)
{
	for (unsigned i = 0; def->manufacturer[i]; i++) {
		char c = s->manufacturer[i];

		if (c >= 'a' && c <= 'z')
			c = (char)(c - 'a' + 'A');
		if (c != def->manufacturer[i])
			return false;
	}
	return strncmp(s->sensor_type, def->sensor_type, strlen(def->sensor_type)) == 0;
}

/* The first answer: waits for the probe and the first poll. */
static ER wait_first_sample(unsigned port, int type, const int8_t **p_sample)
{
	RELTIM waited = 0;
	ER ercd = api_may_wait();

	if (ercd != E_OK)
		return ercd;
	for (;;) {
		ER_UINT state = iic_svc_state(port);

		if (state < 0)
			return (ER)state;
		if (state == LMS_IIC_STATE_IDLE)
			return E_OBJ;           /* stopped underneath (a reboot of the driver) */
		if (!verified[port] && state >= LMS_IIC_STATE_SETUP_WAIT && state <= LMS_IIC_STATE_REPEAT) {
			struct lms_iic_str s;

			memset(&s, 0, sizeof(s));
			ercd = iic_svc_type_info(port, &s);
			if (ercd != E_OK)
				return ercd;
			if (!identity_matches(&s, &nxt_defs[type]))
				return E_OBJ;   /* another sensor, or none that identifies itself */
			verified[port] = true;
		}
		if (verified[port]) {
			*p_sample = lms_iic_sample(iic_shm, port);
			if (*p_sample != NULL)
				return E_OK;
		}
		if (waited >= FIRST_SAMPLE_TIMEOUT_MS)
			return E_TMOUT;
		dly_tsk(POLL_MS);
		waited += POLL_MS;
	}
}

/* Copies the first size bytes of the newest answer of an I2C sensor of type into out. */
static ER read_iic(sensor_port_t port, int type, uint8_t *out, SIZE size, ER out_check)
{
	const int8_t *sample = NULL;
	ER ercd = api_sensor_check((unsigned)port, type, out_check);

	if (ercd != E_OK)
		return ercd;
	if (verified[port])
		sample = lms_iic_sample(iic_shm, (unsigned)port);
	if (sample == NULL) {
		ercd = wait_first_sample((unsigned)port, type, &sample);
		if (ercd != E_OK)
			return ercd;
	}
	memcpy(out, sample, size);
	return E_OK;
}

ER ev3lx_ht_nxt_accel_sensor_measure(sensor_port_t port, int16_t axes[3])
{
	uint8_t raw[6];
	ER ercd = read_iic(port, HT_NXT_ACCEL_SENSOR, raw, sizeof(raw),
			   api_check_out(axes, 3 * sizeof(int16_t), __alignof__(int16_t)));

	if (ercd != E_OK)
		return ercd;
	/* 10-bit signed: the upper 8 bits, then the lower 2 */
	for (unsigned i = 0; i < 3; i++)
		axes[i] = (int16_t)((int8_t)raw[i] * 4 + (raw[3 + i] & 3));
	return E_OK;
}

ER ev3lx_ht_nxt_color_sensor_measure_color(sensor_port_t port, uint8_t *p_color)
{
	return read_iic(port, HT_NXT_COLOR_SENSOR, p_color, 1, API_CHECK_OUT(p_color));
}

ER ev3lx_ht_nxt_color_sensor_measure_rgb(sensor_port_t port, rgb_raw_t *p_rgb)
{
	uint8_t raw[4];
	ER ercd = read_iic(port, HT_NXT_COLOR_SENSOR, raw, sizeof(raw), API_CHECK_OUT(p_rgb));

	if (ercd != E_OK)
		return ercd;
	p_rgb->r = raw[1];
	p_rgb->g = raw[2];
	p_rgb->b = raw[3];
	return E_OK;
}

ER ev3lx_nxt_temp_sensor_measure(sensor_port_t port, float *p_temp)
{
	uint8_t raw[2];
	ER ercd = read_iic(port, NXT_TEMP_SENSOR, raw, sizeof(raw), API_CHECK_OUT(p_temp));

	if (ercd != E_OK)
		return ercd;
	/* signed degrees in the first byte, sixteenths in the high nibble of the second */
	*p_temp = (float)((int8_t)raw[0] * 16 + (raw[1] >> 4)) * 0.0625f;
	return E_OK;
}

/* ---- EV3RT's forms: true when measured; false and a warning otherwise ---- */

static bool_t measured(const char *call, sensor_port_t port, ER ercd)
{
	if (ercd != E_OK) {
		api_warn(call, (int)port, ercd);
		return false;
	}
	return true;
}

bool_t ht_nxt_accel_sensor_measure(sensor_port_t port, int16_t axes[3])
{
	return measured(__func__, port, ev3lx_ht_nxt_accel_sensor_measure(port, axes));
}

bool_t ht_nxt_color_sensor_measure_color(sensor_port_t port, uint8_t *color)
{
	return measured(__func__, port, ev3lx_ht_nxt_color_sensor_measure_color(port, color));
}

bool_t ht_nxt_color_sensor_measure_rgb(sensor_port_t port, rgb_raw_t *val)
{
	return measured(__func__, port, ev3lx_ht_nxt_color_sensor_measure_rgb(port, val));
}

bool_t nxt_temp_sensor_measure(sensor_port_t port, float *temp)
{
	return measured(__func__, port, ev3lx_nxt_temp_sensor_measure(port, temp));
}
