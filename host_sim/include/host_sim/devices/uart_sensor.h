/*
 * uart_sensor.h — the EV3 UART sensors (colour 29, ultrasonic 30, gyro 32,
 * infrared 33), modelled from the device side of the LEGO UART protocol
 * (LEGO's d_uart_mod.c, pybricks' port_lump.c, ev3dev's
 * ev3_uart_sensor_defs.c; docs/host-sim-devices.md): auto-ID low period on pin 6,
 * TYPE/MODES/SPEED and per-mode INFO at 2400 baud, ACK, the switch to
 * 57600 baud after the host's ACK, DATA at each sensor's rate, the 1 s
 * keep-alive reset, SELECT and WRITE.  Values come from the scenario.
 *
 * A sensor talks to its input port through a link: it times each byte on
 * the wire itself and hands the completed byte (with the baud it was sent
 * at) to link.deliver; its TX line level (pin 6) goes to link.line.  Bytes
 * the host sends arrive through uart_sensor_host_byte.  Host only.
 */
#ifndef HOST_SIM_DEVICES_UART_SENSOR_H
#define HOST_SIM_DEVICES_UART_SENSOR_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/devices/lump.h"

#define UART_SENSOR_TYPE_COLOR       29U
#define UART_SENSOR_TYPE_ULTRASONIC  30U
#define UART_SENSOR_TYPE_GYRO        32U
#define UART_SENSOR_TYPE_IR          33U

#define UART_SENSOR_HANDSHAKE_BAUD   2400U
#define UART_SENSOR_MAX_MODES        8U

/* What one mode advertises (ev3dev's ev3_uart_sensor_defs.c); PCT is never sent (0-100 implied). */
struct uart_sensor_mode {
	const char *name;           /* <= 11 characters */
	float raw_min, raw_max;
	float si_min, si_max;
	const char *symbol;         /* NULL: no SYMBOL message */
	uint8_t datasets;
	uint8_t format;             /* LUMP_DATA8 .. LUMP_DATAF */
	uint8_t figures, decimals;
	uint32_t data_period_us;    /* DATA every this long; 0: on change and after each NACK */
	bool ignores_keepalive;     /* NACK does not refresh the watchdog (COL-CAL, IR-S-ALT) */
	bool single_shot;           /* one reading per SELECT, repeated after NACK (US-SI-*) */
};

/* One sensor model's constant description. */
struct uart_sensor_def {
	const char *model;          /* "EV3 colour sensor 45506" ... */
	uint8_t type;
	uint8_t modes, views;
	uint32_t speed;             /* advertised SPEED, used after the host's ACK */
	uint32_t autoid_low_us;     /* pin 6 held low at power-up (502-506 ms in logic-analyser captures of real sensors) */
	uint32_t handshake_us;      /* TYPE .. ACK as captured (gaps between messages fill it) */
	uint32_t first_data_us;     /* host ACK -> first DATA frame (captures: ~7 ms) */
	uint32_t ack_timeout_us;    /* no host ACK this long after ours: start the handshake over */
	uint32_t keepalive_us;      /* no NACK this long: reset (power-up again) */
	uint32_t sample_us;         /* change detection period of on-change modes */
	bool missing_symbol_00ff;   /* IR: sends 00 FF where a SYMBOL is missing */
	const struct uart_sensor_mode *mode;
};

/* The built-in definition for a type (29, 30, 32, 33), or NULL. */
const struct uart_sensor_def *uart_sensor_def_for_type(uint8_t type);

/* Sensor states. */
enum uart_sensor_state {
	UART_SENSOR_OFF,            /* unplugged */
	UART_SENSOR_AUTOID,         /* holding pin 6 low */
	UART_SENSOR_HANDSHAKE,      /* sending TYPE .. ACK at 2400 baud */
	UART_SENSOR_WAIT_ACK,       /* waiting for the host's ACK */
	UART_SENSOR_DATA,           /* streaming at the advertised speed */
	UART_SENSOR_LOCKED,         /* hung (US-SI reselected too fast): silent until unplugged */
};

/* How the sensor reaches its port. */
struct uart_sensor_link {
	/* A byte finished on the sensor's TX line at baud (bits/s). */
	void (*deliver)(void *ctx, uint8_t byte, uint32_t baud);
	/* The TX line (pin 6) is now held low (false) or idle high (true). */
	void (*line)(void *ctx, bool high);
	void *ctx;
};

/* The scene a sensor observes; the scenario changes it at any time. */
struct uart_sensor_scene {
	uint8_t reflect_pct;        /* colour: reflected light of the surface, 0-100 */
	uint8_t ambient_pct;        /* colour: ambient light, 0-100 */
	uint8_t color;              /* colour: 0 none, 1 black, 2 blue, 3 green, 4 yellow, 5 red, 6 white, 7 brown */
	uint16_t rgb[3];            /* colour: raw R, G, B, 0-1020 */
	uint32_t distance_mm;       /* ultrasonic and IR proximity: distance to the nearest object */
	bool other_ultrasonic;      /* ultrasonic US-LISTEN: another sensor is heard */
	double rate_dps;            /* gyro: the body's rotation rate, degrees per second */
	int8_t beacon_heading[4];   /* IR seek: per channel, -25..25 */
	int8_t beacon_distance[4];  /* IR seek: per channel, 0..100, -128 none */
	uint8_t remote_buttons[4];  /* IR remote: per channel, 0..11 */
};

/* Behaviour options (all off/zero is a perfect sensor with the real quirks of
 * its firmware left on, see .no_quirks). */
/*
 * An EV3 gyro at rest: its rate (GYRO-RATE, whole deg/s) reads a steady 0,
 * now and then one count off ("reads 0 continually, occasionally -1",
 * microsoft/pxt-ev3 issue 865), steady enough that LEGO's Gyro Boy program
 * takes 200 readings 4 ms apart as its offset only when they span less than
 * 2 deg/s (EV3RT's port of it: ev3rt-git/ev3rt-hrp2-sdk, workspace/gyroboy,
 * calibrate_gyro_sensor).  White noise of 0.15 deg/s before the rounding
 * gives that: a reading one count off about once in 1200 (|noise| >= 0.5 is
 * 3.3 sigma), and 200 readings spanning 2 counts (one +1 and one -1) in
 * fewer than 1 calibration in 100.  ev3sim's default for a robot's gyro.
 */
#define UART_SENSOR_GYRO_NOISE_AT_REST_DPS 0.15

struct uart_sensor_options {
	const char *name;           /* random stream name (hs_rng_stream), e.g. "in1.gyro"; NULL: the model */
	uint64_t seed;              /* non-zero: seed the noise with this instead of the scenario stream */
	bool no_quirks;             /* no IR 00 FF, no RGB-RAW bad check, no US-SI lock-up */
	bool stale_first_frame;     /* first DATA after SELECT carries the old value (ev3dev #1401) */
	double gyro_noise_dps;      /* gyro: white noise on each rate sample (standard deviation) */
	double gyro_drift_dps;      /* gyro: constant rate bias, integrated into the angle */
	bool gyro_angle_wraps;      /* gyro: angle wraps at +-32768 (else sticks at the limit) */
};

struct uart_sensor;

/* Creates a sensor of a built-in type (powered off); NULL for an unknown type. */
struct uart_sensor *uart_sensor_create(uint8_t type, const struct uart_sensor_options *opt,
				       const struct uart_sensor_link *link);
/* Stops its events and frees it. */
void uart_sensor_destroy(struct uart_sensor *s);

/* Plugs in (power-up at the current virtual time) or unplugs. */
void uart_sensor_power(struct uart_sensor *s, bool on);

/* A byte the host sent, arriving at baud; the sensor ignores it if its own
 * receiver runs at another speed (a framing error on its side). */
void uart_sensor_host_byte(struct uart_sensor *s, uint8_t byte, uint32_t baud);

/* The host holds the sensor's RX line low (break) or releases it. */
void uart_sensor_host_break(struct uart_sensor *s, bool active);

/* Scene access: changes apply from the current virtual time (gyro rate changes
 * integrate the angle up to now first). */
void uart_sensor_set_scene(struct uart_sensor *s, const struct uart_sensor_scene *scene);
const struct uart_sensor_scene *uart_sensor_scene(const struct uart_sensor *s);

enum uart_sensor_state uart_sensor_get_state(const struct uart_sensor *s);
const struct uart_sensor_def *uart_sensor_get_def(const struct uart_sensor *s);
unsigned uart_sensor_mode(const struct uart_sensor *s);
/* Current TX/RX baud of the sensor. */
uint32_t uart_sensor_baud(const struct uart_sensor *s);
/* Counters for tests and traces. */
struct uart_sensor_stats {
	uint32_t resets;            /* power-ups, keep-alive resets and handshake restarts */
	uint32_t data_frames;
	uint32_t nacks;
	uint32_t selects;
	uint32_t writes;
	uint32_t rx_garbled;        /* host bytes at the wrong speed */
	uint8_t last_write[LUMP_MAX_PAYLOAD];
	uint8_t last_write_len;
};
const struct uart_sensor_stats *uart_sensor_get_stats(const struct uart_sensor *s);

/* The payload of the current mode's DATA message for the current scene
 * (what the next frame will carry); returns its length. */
unsigned uart_sensor_payload(struct uart_sensor *s, uint8_t *out);

#endif /* HOST_SIM_DEVICES_UART_SENSOR_H */
