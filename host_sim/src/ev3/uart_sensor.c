/*
 * uart_sensor.c — an EV3 UART sensor, device side (LEGO's d_uart_mod.c,
 * pybricks' port_lump.c, ev3dev's ev3_uart_sensor_defs.c).
 *
 * Life cycle: power-up holds pin 6 low for the auto-ID time, then sends the
 * whole handshake at 2400 baud (messages back-to-back, with the small gaps
 * that make the captured durations), ending with ACK.  The host's ACK
 * switches it to its SPEED and starts DATA; no host ACK within the ACK
 * timeout starts the handshake over (colour firmware: 80 ms).  In DATA, each
 * NACK refreshes the keep-alive watchdog (except in modes that ignore it);
 * when the watchdog expires the sensor resets and powers up again.
 *
 * Every byte is one event on the virtual clock, timed at 10 bit-times of the
 * sensor's own baud; the port decides what the host UART makes of it.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/rng.h"
#include "host_sim/devices/uart_sensor.h"

#define TXQ_FRAMES 64U
#define NS_PER_US 1000ULL

struct tx_frame {
	uint8_t bytes[LUMP_MAX_FRAME];
	uint8_t len;
	bool is_ack;                /* our handshake ACK: WAIT_ACK starts when it is out */
	uint32_t gap_ns;            /* idle line before the first byte */
};

struct uart_sensor {
	const struct uart_sensor_def *def;
	struct uart_sensor_options opt;
	struct uart_sensor_link link;
	struct uart_sensor_scene scene;
	enum uart_sensor_state state;
	uint32_t baud;
	unsigned mode;
	struct hs_rng rng;
	struct uart_sensor_stats stats;

	/* transmitter */
	struct tx_frame txq[TXQ_FRAMES];
	unsigned txq_head, txq_count, tx_byte;
	hs_event_t tx_ev;
	uint32_t tx_baud;           /* baud of the byte on the wire */
	uint32_t handshake_gap_ns;

	/* receiver */
	struct lump_parser rx;
	bool rx_break;

	/* timers */
	hs_event_t phase_ev; /* auto-ID end, ACK timeout, first DATA */
	hs_event_t keepalive_ev;
	hs_event_t data_ev;

	/* data */
	uint8_t last_payload[LUMP_MAX_PAYLOAD];
	unsigned last_len;
	bool have_last;
	bool stale_next;            /* next frame repeats last_payload (stale first frame) */
	uint64_t last_si_select_ns;
	bool si_selected;

	/* gyro */
	double angle_deg;
	uint64_t angle_t_ns;
};

static void sensor_power_up(struct uart_sensor *s);
static void sensor_start_handshake(void *arg);
static void sensor_send_data(struct uart_sensor *s);

/* ---- small helpers ---- */

static uint64_t byte_ns(uint32_t baud)
{
	return 10000000000ULL / baud;
}

/* Stores a little-endian 16-bit value. */
static void put16(uint8_t *p, int32_t v)
{
	p[0] = (uint8_t)(v & 0xFF);
	p[1] = (uint8_t)((v >> 8) & 0xFF);
}

/* Stores a little-endian IEEE float. */
static void put_float(uint8_t *p, float f)
{
	uint32_t u;

	memcpy(&u, &f, sizeof(u));
	for (int i = 0; i < 4; i++)
		p[i] = (uint8_t)(u >> (8 * i));
}

/* The current mode description. */
static const struct uart_sensor_mode *cur_mode(const struct uart_sensor *s)
{
	return &s->def->mode[s->mode];
}

/* ---- transmitter ---- */

static void tx_flush(struct uart_sensor *s)
{
	hs_event_cancel(&s->tx_ev);
	s->txq_head = s->txq_count = s->tx_byte = 0;
}

static void tx_kick(struct uart_sensor *s);

/* Event: the byte on the wire is complete. */
static void tx_byte_done(void *arg)
{
	struct uart_sensor *s = arg;
	struct tx_frame *f = &s->txq[s->txq_head];
	uint8_t b = f->bytes[s->tx_byte++];
	bool was_ack = false;

	s->tx_ev = 0;
	if (s->tx_byte >= f->len) {
		was_ack = f->is_ack;
		s->txq_head = (s->txq_head + 1U) % TXQ_FRAMES;
		s->txq_count--;
		s->tx_byte = 0;
	}
	if (s->link.deliver)
		s->link.deliver(s->link.ctx, b, s->tx_baud);
	if (was_ack && s->state == UART_SENSOR_HANDSHAKE) {
		s->state = UART_SENSOR_WAIT_ACK;
		rtos_host_trace("uart_sensor", "type %u: handshake sent, waiting for ACK",
				(unsigned)s->def->type);
		s->phase_ev = hs_event_at(hs_now() + s->def->ack_timeout_us * NS_PER_US,
						 sensor_start_handshake, s);
	}
	tx_kick(s);
}

/* Starts the next byte if the line is free. */
static void tx_kick(struct uart_sensor *s)
{
	uint64_t start = hs_now();

	if (s->tx_ev || !s->txq_count || s->state == UART_SENSOR_OFF)
		return;
	if (s->tx_byte == 0)
		start += s->txq[s->txq_head].gap_ns;
	s->tx_baud = s->baud;
	s->tx_ev = hs_event_at(start + byte_ns(s->baud), tx_byte_done, s);
}

/* Queues one encoded frame; drops it (counted as nothing) when the queue is full. */
static void tx_frame_put(struct uart_sensor *s, const uint8_t *bytes, size_t len, uint32_t gap_ns,
			 bool is_ack)
{
	struct tx_frame *f;

	if (!len || s->txq_count >= TXQ_FRAMES)
		return;
	f = &s->txq[(s->txq_head + s->txq_count) % TXQ_FRAMES];
	memcpy(f->bytes, bytes, len);
	f->len = (uint8_t)len;
	f->gap_ns = gap_ns;
	f->is_ack = is_ack;
	s->txq_count++;
	tx_kick(s);
}

/* ---- handshake ---- */

/* Queues TYPE, MODES, SPEED, INFO per mode (highest first) and ACK. */
static void queue_handshake(struct uart_sensor *s)
{
	const struct uart_sensor_def *d = s->def;
	struct tx_frame tmp[TXQ_FRAMES];
	unsigned n = 0, total_bytes = 0;
	uint8_t p[LUMP_MAX_PAYLOAD];
	uint64_t budget, used;

	tmp[n].len = (uint8_t)lump_encode_cmd(tmp[n].bytes, LUMP_MAX_FRAME, LUMP_CMD_TYPE, &d->type, 1);
	n++;
	p[0] = (uint8_t)(d->modes - 1U);
	p[1] = (uint8_t)(d->views - 1U);
	tmp[n].len = (uint8_t)lump_encode_cmd(tmp[n].bytes, LUMP_MAX_FRAME, LUMP_CMD_MODES, p, 2);
	n++;
	for (int i = 0; i < 4; i++)
		p[i] = (uint8_t)(d->speed >> (8 * i));
	tmp[n].len = (uint8_t)lump_encode_cmd(tmp[n].bytes, LUMP_MAX_FRAME, LUMP_CMD_SPEED, p, 4);
	n++;
	for (int m = d->modes - 1; m >= 0; m--) {
		const struct uart_sensor_mode *md = &d->mode[m];
		size_t nl = strlen(md->name);

		/* names of up to 8 characters use 8 bytes (no NUL when exactly 8), longer ones 16 */
		memset(p, 0, sizeof(p));
		memcpy(p, md->name, nl);
		tmp[n].len = (uint8_t)lump_encode_info(tmp[n].bytes, LUMP_MAX_FRAME, (unsigned)m,
						       LUMP_INFO_NAME, p, nl <= 8 ? 8 : 16);
		n++;
		put_float(p, md->raw_min);
		put_float(p + 4, md->raw_max);
		tmp[n].len = (uint8_t)lump_encode_info(tmp[n].bytes, LUMP_MAX_FRAME, (unsigned)m,
						       LUMP_INFO_RAW, p, 8);
		n++;
		put_float(p, md->si_min);
		put_float(p + 4, md->si_max);
		tmp[n].len = (uint8_t)lump_encode_info(tmp[n].bytes, LUMP_MAX_FRAME, (unsigned)m,
						       LUMP_INFO_SI, p, 8);
		n++;
		if (md->symbol) {
			memset(p, 0, 4);
			memcpy(p, md->symbol, strlen(md->symbol));
			tmp[n].len = (uint8_t)lump_encode_info(tmp[n].bytes, LUMP_MAX_FRAME, (unsigned)m,
							       LUMP_INFO_SYMBOL, p, 4);
			n++;
		} else if (d->missing_symbol_00ff && !s->opt.no_quirks) {
			tmp[n].bytes[0] = 0x00;
			tmp[n].bytes[1] = 0xFF;
			tmp[n].len = 2;
			n++;
		}
		p[0] = md->datasets;
		p[1] = md->format;
		p[2] = md->figures;
		p[3] = md->decimals;
		tmp[n].len = (uint8_t)lump_encode_info(tmp[n].bytes, LUMP_MAX_FRAME, (unsigned)m,
						       LUMP_INFO_FORMAT, p, 4);
		n++;
	}
	tmp[n].bytes[0] = LUMP_SYS_ACK;
	tmp[n].len = 1;
	n++;

	for (unsigned i = 0; i < n; i++)
		total_bytes += tmp[i].len;
	budget = (uint64_t)d->handshake_us * NS_PER_US;
	used = (uint64_t)total_bytes * byte_ns(UART_SENSOR_HANDSHAKE_BAUD);
	s->handshake_gap_ns = budget > used && n > 1 ? (uint32_t)((budget - used) / (n - 1U)) : 0U;
	for (unsigned i = 0; i < n; i++)
		tx_frame_put(s, tmp[i].bytes, tmp[i].len, i ? s->handshake_gap_ns : 0U, i == n - 1U);
}

/* Event (and ACK timeout): sends the handshake from TYPE at 2400 baud. */
static void sensor_start_handshake(void *arg)
{
	struct uart_sensor *s = arg;

	s->phase_ev = 0;
	if (s->state == UART_SENSOR_WAIT_ACK) {
		s->stats.resets++;
		rtos_host_trace("uart_sensor", "type %u: no ACK in time, handshake again",
				(unsigned)s->def->type);
	}
	tx_flush(s);
	s->state = UART_SENSOR_HANDSHAKE;
	s->baud = UART_SENSOR_HANDSHAKE_BAUD;
	s->mode = 0;
	lump_parser_reset(&s->rx);
	if (s->link.line)
		s->link.line(s->link.ctx, true);
	queue_handshake(s);
}

/* ---- values ---- */

static void gyro_integrate(struct uart_sensor *s)
{
	uint64_t now = hs_now();
	double dt = (double)(now - s->angle_t_ns) * 1e-9;

	s->angle_deg += (s->scene.rate_dps + s->opt.gyro_drift_dps) * dt;
	s->angle_t_ns = now;
	if (s->angle_deg > 32767.0 || s->angle_deg < -32768.0) {
		if (s->opt.gyro_angle_wraps)
			s->angle_deg = fmod(s->angle_deg + 32768.0, 65536.0) +
				       (s->angle_deg + 32768.0 < 0 ? 65536.0 : 0.0) - 32768.0;
		else
			s->angle_deg = s->angle_deg > 0 ? 32767.0 : -32768.0;
	}
}

/* Rounds and clamps to [lo, hi]. */
static int32_t clampi(double v, int32_t lo, int32_t hi)
{
	double r = floor(v + 0.5);

	return r < lo ? lo : r > hi ? hi : (int32_t)r;
}

/* Fills the DATA payload of the current mode; returns its length. */
unsigned uart_sensor_payload(struct uart_sensor *s, uint8_t *out)
{
	const struct uart_sensor_scene *sc = &s->scene;
	unsigned m = s->mode;
	uint16_t bg = (uint16_t)(sc->ambient_pct * 4U);

	memset(out, 0, LUMP_MAX_PAYLOAD);
	switch (s->def->type) {
	case UART_SENSOR_TYPE_COLOR:
		switch (m) {
		case 0: out[0] = sc->reflect_pct; return 1;
		case 1: out[0] = sc->ambient_pct; return 1;
		case 2: out[0] = sc->color; return 1;
		case 3: put16(out, bg + sc->reflect_pct * 6); put16(out + 2, bg); return 4;
		case 4: /* four values (R, G, B, background) in 8 bytes for 3 advertised */
			put16(out, sc->rgb[0]); put16(out + 2, sc->rgb[1]);
			put16(out + 4, sc->rgb[2]); put16(out + 6, bg); return 8;
		default: /* factory calibration words: fixed, their meaning is not public */
			put16(out, 0x0190); put16(out + 2, 0x01A4); put16(out + 4, 0x01B8);
			put16(out + 6, 0x0200); return 8;
		}
	case UART_SENSOR_TYPE_ULTRASONIC: {
		int32_t cm10 = clampi((double)sc->distance_mm, 0, 2550);
		int32_t in10 = clampi((double)sc->distance_mm / 2.54, 0, 1000);

		switch (m) {
		case 2: out[0] = sc->other_ultrasonic ? 1U : 0U; return 1;
		case 1: case 4: case 6: put16(out, in10); return 2;
		default: put16(out, cm10); return 2;
		}
	}
	case UART_SENSOR_TYPE_GYRO: {
		double rate = s->scene.rate_dps + s->opt.gyro_drift_dps;

		gyro_integrate(s);
		if (s->opt.gyro_noise_dps > 0)
			rate += s->opt.gyro_noise_dps * hs_rng_gauss(&s->rng);
		switch (m) {
		case 0: put16(out, clampi(s->angle_deg, -32768, 32767)); return 2;
		case 1: put16(out, clampi(rate, -440, 440)); return 2;
		case 2: put16(out, clampi(rate, -2000, 2000)); return 2;
		case 3: put16(out, clampi(s->angle_deg, -32768, 32767));
			put16(out + 2, clampi(rate, -440, 440)); return 4;
		default: return 8;
		}
	}
	default: { /* infrared */
		switch (m) {
		case 0: out[0] = (uint8_t)clampi((double)sc->distance_mm / 7.0, 0, 100); return 1;
		case 1:
			for (int c = 0; c < 4; c++) {
				out[2 * c] = (uint8_t)sc->beacon_heading[c];
				out[2 * c + 1] = (uint8_t)sc->beacon_distance[c];
			}
			return 8;
		case 2: memcpy(out, sc->remote_buttons, 4); return 4;
		case 3: put16(out, sc->remote_buttons[0] | sc->remote_buttons[1] << 4 |
			      sc->remote_buttons[2] << 8 | sc->remote_buttons[3] << 12); return 2;
		case 4: out[0] = (uint8_t)clampi((double)sc->distance_mm / 7.0, 0, 100); return 4;
		default: put16(out, 0x0100); put16(out + 2, 0x0100); return 4;
		}
	}
	}
}

/* ---- data phase ---- */

/* Encodes and queues one DATA frame of the current mode. */
static void sensor_send_data(struct uart_sensor *s)
{
	uint8_t payload[LUMP_MAX_PAYLOAD], frame[LUMP_MAX_FRAME];
	unsigned len = uart_sensor_payload(s, payload);
	size_t n;

	if (s->state != UART_SENSOR_DATA)
		return;
	if (s->txq_count >= 2U)     /* the line is busy: a real sensor skips a sample */
		return;
	if (s->stale_next && s->have_last) {
		memcpy(payload, s->last_payload, len);
		s->stale_next = false;
	} else {
		memcpy(s->last_payload, payload, len);
		s->last_len = len;
		s->have_last = true;
	}
	n = lump_encode_data(frame, sizeof(frame), s->mode, payload, len);
	if (s->def->type == UART_SENSOR_TYPE_COLOR && s->mode == 4 && !s->opt.no_quirks)
		frame[n - 1] ^= 0xDCU ^ 0xD4U;  /* checked as if it were the advertised 3x16-bit frame */
	s->stats.data_frames++;
	tx_frame_put(s, frame, n, 0, false);
}

/* Event: periodic DATA, or change detection for on-change modes. */
static void data_tick(void *arg)
{
	struct uart_sensor *s = arg;
	const struct uart_sensor_mode *md = cur_mode(s);
	uint8_t now_payload[LUMP_MAX_PAYLOAD];
	uint32_t period_us;
	unsigned len;

	s->data_ev = 0;
	if (s->state != UART_SENSOR_DATA)
		return;
	if (md->single_shot)
		return;
	if (md->data_period_us) {
		sensor_send_data(s);
		period_us = md->data_period_us;
	} else {
		len = uart_sensor_payload(s, now_payload);
		if (!s->have_last || len != s->last_len || memcmp(now_payload, s->last_payload, len) != 0)
			sensor_send_data(s);
		period_us = s->def->sample_us;
	}
	s->data_ev = hs_event_at(hs_now() + period_us * NS_PER_US, data_tick, s);
}

/* Event: the first DATA after the host's ACK or a SELECT. */
static void data_start(void *arg)
{
	struct uart_sensor *s = arg;

	s->phase_ev = 0;
	hs_event_cancel(&s->data_ev);
	sensor_send_data(s);
	if (!cur_mode(s)->single_shot) {
		uint32_t p = cur_mode(s)->data_period_us ? cur_mode(s)->data_period_us : s->def->sample_us;

		s->data_ev = hs_event_at(hs_now() + p * NS_PER_US, data_tick, s);
	}
}

/* Event: no NACK within the keep-alive time. */
static void keepalive_expired(void *arg)
{
	struct uart_sensor *s = arg;

	s->keepalive_ev = 0;
	rtos_host_trace("uart_sensor", "type %u: no keep-alive for %u ms, reset",
			(unsigned)s->def->type, (unsigned)(s->def->keepalive_us / 1000U));
	s->stats.resets++;
	sensor_power_up(s);
}

/* Restarts the keep-alive watchdog. */
static void keepalive_arm(struct uart_sensor *s)
{
	hs_event_cancel(&s->keepalive_ev);
	s->keepalive_ev = hs_event_at(hs_now() + s->def->keepalive_us * NS_PER_US,
					     keepalive_expired, s);
}

/* Mode change on SELECT. */
static void sensor_select(struct uart_sensor *s, unsigned mode)
{
	uint64_t now = hs_now();
	bool single = s->def->mode[mode].single_shot;

	s->stats.selects++;
	if (single && !s->opt.no_quirks && s->si_selected &&
	    now - s->last_si_select_ns < 250ULL * 1000000ULL) {
		rtos_host_trace("uart_sensor", "type %u: SI mode reselected within 250 ms, sensor locks up",
				(unsigned)s->def->type);
		s->state = UART_SENSOR_LOCKED;
		tx_flush(s);
		hs_event_cancel(&s->data_ev);
		hs_event_cancel(&s->phase_ev);
		hs_event_cancel(&s->keepalive_ev);
		return;
	}
	if (single) {
		s->si_selected = true;
		s->last_si_select_ns = now;
	}
	if (mode != s->mode)
		s->stale_next = s->opt.stale_first_frame;
	s->mode = mode;
	if (s->def->type == UART_SENSOR_TYPE_GYRO) {
		gyro_integrate(s);
		s->angle_deg = 0;   /* changing mode resets the angle (ev3dev's ev3_uart_sensor_defs.c) */
	}
	hs_event_cancel(&s->data_ev);
	hs_event_cancel(&s->phase_ev);
	s->phase_ev = hs_event_at(now + NS_PER_US * 1000U, data_start, s);
}

/* A complete message from the host. */
static void sensor_host_msg(struct uart_sensor *s, const struct lump_msg *m)
{
	if (!m->check_ok)
		return;
	if (s->state == UART_SENSOR_WAIT_ACK) {
		if (m->header == LUMP_SYS_ACK) {
			hs_event_cancel(&s->phase_ev);
			s->state = UART_SENSOR_DATA;
			s->baud = s->def->speed;
			s->mode = 0;
			rtos_host_trace("uart_sensor", "type %u: host ACK, %u baud",
					(unsigned)s->def->type, (unsigned)s->baud);
			s->phase_ev = hs_event_at(hs_now() + s->def->first_data_us * NS_PER_US,
							 data_start, s);
			keepalive_arm(s);
		}
		return;
	}
	if (s->state != UART_SENSOR_DATA)
		return;
	if (m->header == LUMP_SYS_NACK) {
		s->stats.nacks++;
		if (!cur_mode(s)->ignores_keepalive)
			keepalive_arm(s);
		if (!cur_mode(s)->data_period_us)
			sensor_send_data(s);
	} else if ((m->header & LUMP_CLASS_MASK) == LUMP_CLASS_CMD &&
		   (m->header & 7U) == LUMP_CMD_SELECT) {
		if (m->payload[0] < s->def->modes)
			sensor_select(s, m->payload[0]);
	} else if ((m->header & LUMP_CLASS_MASK) == LUMP_CLASS_CMD &&
		   (m->header & 7U) == LUMP_CMD_WRITE) {
		s->stats.writes++;
		memcpy(s->stats.last_write, m->payload, m->len);
		s->stats.last_write_len = m->len;
		rtos_host_trace("uart_sensor", "type %u: WRITE of %u bytes",
				(unsigned)s->def->type, (unsigned)m->len);
	}
}

/* ---- power ---- */

/* Event: auto-ID low time over. */
static void autoid_done(void *arg)
{
	struct uart_sensor *s = arg;

	s->phase_ev = 0;
	sensor_start_handshake(s);
}

/* Power-up (also the reset path): pin 6 low for the auto-ID time. */
static void sensor_power_up(struct uart_sensor *s)
{
	tx_flush(s);
	hs_event_cancel(&s->phase_ev);
	hs_event_cancel(&s->keepalive_ev);
	hs_event_cancel(&s->data_ev);
	s->state = UART_SENSOR_AUTOID;
	s->baud = UART_SENSOR_HANDSHAKE_BAUD;
	s->mode = 0;
	s->have_last = false;
	s->stale_next = false;
	s->si_selected = false;
	s->angle_deg = 0;
	s->angle_t_ns = hs_now();
	lump_parser_reset(&s->rx);
	if (s->link.line)
		s->link.line(s->link.ctx, false);
	s->phase_ev = hs_event_at(hs_now() + s->def->autoid_low_us * NS_PER_US,
					 autoid_done, s);
}

/* ---- public ---- */

/* Creates a powered-off sensor. */
struct uart_sensor *uart_sensor_create(uint8_t type, const struct uart_sensor_options *opt,
				       const struct uart_sensor_link *link)
{
	const struct uart_sensor_def *def = uart_sensor_def_for_type(type);
	struct uart_sensor *s;

	if (!def)
		return NULL;
	s = calloc(1, sizeof(*s));
	if (!s)
		return NULL;
	s->def = def;
	if (opt)
		s->opt = *opt;
	if (link)
		s->link = *link;
	if (s->opt.seed)
		hs_rng_seed(&s->rng, s->opt.seed);
	else
		hs_rng_stream(&s->rng, s->opt.name ? s->opt.name : def->model);
	s->state = UART_SENSOR_OFF;
	s->baud = UART_SENSOR_HANDSHAKE_BAUD;
	s->scene.distance_mm = 2550;
	for (int c = 0; c < 4; c++)
		s->scene.beacon_distance[c] = -128;
	return s;
}

/* Frees the sensor and its pending events. */
void uart_sensor_destroy(struct uart_sensor *s)
{
	if (!s)
		return;
	uart_sensor_power(s, false);
	free(s);
}

/* Plug in or unplug. */
void uart_sensor_power(struct uart_sensor *s, bool on)
{
	if (on) {
		if (s->state == UART_SENSOR_OFF) {
			s->stats.resets++;
			sensor_power_up(s);
		}
		return;
	}
	tx_flush(s);
	hs_event_cancel(&s->phase_ev);
	hs_event_cancel(&s->keepalive_ev);
	hs_event_cancel(&s->data_ev);
	s->state = UART_SENSOR_OFF;
}

/* A host byte at baud. */
void uart_sensor_host_byte(struct uart_sensor *s, uint8_t byte, uint32_t baud)
{
	struct lump_msg m;
	uint32_t lo = s->baud - s->baud / 25U, hi = s->baud + s->baud / 25U;

	if (s->state == UART_SENSOR_OFF || s->state == UART_SENSOR_LOCKED || s->rx_break)
		return;
	if (baud < lo || baud > hi) {
		s->stats.rx_garbled++;
		lump_parser_reset(&s->rx);
		return;
	}
	if (lump_parser_push(&s->rx, byte, &m))
		sensor_host_msg(s, &m);
}

/* Host break on the sensor's RX line: nothing is received meanwhile. */
void uart_sensor_host_break(struct uart_sensor *s, bool active)
{
	s->rx_break = active;
	lump_parser_reset(&s->rx);
}

/* Changes the scene from now on. */
void uart_sensor_set_scene(struct uart_sensor *s, const struct uart_sensor_scene *scene)
{
	if (s->def->type == UART_SENSOR_TYPE_GYRO)
		gyro_integrate(s);
	s->scene = *scene;
}

/* The scene the sensor observes. */
const struct uart_sensor_scene *uart_sensor_scene(const struct uart_sensor *s)
{
	return &s->scene;
}

/* Protocol state. */
enum uart_sensor_state uart_sensor_get_state(const struct uart_sensor *s)
{
	return s->state;
}

/* The sensor definition. */
const struct uart_sensor_def *uart_sensor_get_def(const struct uart_sensor *s)
{
	return s->def;
}

/* Current mode. */
unsigned uart_sensor_mode(const struct uart_sensor *s)
{
	return s->mode;
}

/* Current baud. */
uint32_t uart_sensor_baud(const struct uart_sensor *s)
{
	return s->baud;
}

/* Counters. */
const struct uart_sensor_stats *uart_sensor_get_stats(const struct uart_sensor *s)
{
	return &s->stats;
}
