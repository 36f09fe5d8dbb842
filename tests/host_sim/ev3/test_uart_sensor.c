/*
 * test_uart_sensor.c — each EV3 UART sensor's power-up as the host UART
 * receives it, checked against the protocol (LEGO's d_uart_mod.c, pybricks' port_lump.c) and the sensors' captures: pin 6 held low
 * ~500 ms (a break on the UART), TYPE, MODES, SPEED 57600, INFO per mode
 * highest first (NAME, RAW, SI, SYMBOL only with a unit, FORMAT; no PCT),
 * ACK, header bits, lengths, check bytes and the captured durations; then
 * the host's ACK, DATA at 57600 at the sensor's rate, keep-alive.
 * One sensor per port so all four UARTs (two stand-ins) are exercised.
 */
#include <string.h>
#include "uarttest.h"

struct expect {
	uint8_t type, modes, views;
	unsigned port;
	double duration_s;
	const char *name[8];
	const char *symbol[8];      /* NULL: none */
	uint8_t fmt[8][4];
};

static const struct expect sensors[] = {
	{ 29, 6, 3, 0, 1.30,
	  { "COL-REFLECT", "COL-AMBIENT", "COL-COLOR", "REF-RAW", "RGB-RAW", "COL-CAL" },
	  { "pct", "pct", "col", NULL, NULL, NULL },
	  { { 1, 0, 3, 0 }, { 1, 0, 3, 0 }, { 1, 0, 2, 0 }, { 2, 1, 4, 0 }, { 3, 1, 4, 0 }, { 4, 1, 5, 0 } } },
	{ 32, 5, 2, 1, 1.02,
	  { "GYRO-ANG", "GYRO-RATE", "GYRO-FAS", "GYRO-G&A", "GYRO-CAL" },
	  { "deg", "d/s", NULL, NULL, NULL },
	  { { 1, 1, 4, 0 }, { 1, 1, 3, 0 }, { 1, 1, 4, 0 }, { 2, 1, 5, 0 }, { 4, 1, 5, 0 } } },
	{ 30, 7, 3, 2, 1.60,
	  { "US-DIST-CM", "US-DIST-IN", "US-LISTEN", "US-SI-CM", "US-SI-IN", "US-DC-CM", "US-DC-IN" },
	  { "cm", "inch", NULL, "cm", "inch", "cm", "inch" },
	  { { 1, 1, 5, 1 }, { 1, 1, 5, 1 }, { 1, 0, 1, 0 }, { 1, 1, 5, 1 }, { 1, 1, 5, 1 }, { 1, 1, 5, 1 },
	    { 1, 1, 5, 1 } } },
	{ 33, 6, 3, 3, 1.29,
	  { "IR-PROX", "IR-SEEK", "IR-REMOTE", "IR-REM-A", "IR-S-ALT", "IR-CAL" },
	  { "pct", "pct", "btn", NULL, "pct", NULL },
	  { { 1, 0, 3, 0 }, { 8, 0, 3, 0 }, { 4, 0, 3, 0 }, { 1, 1, 6, 0 }, { 4, 0, 3, 0 }, { 2, 1, 5, 0 } } },
};

static struct host h;

/* A message at h.rx[*i]: checks framing and returns its header, payload and
 * length (info byte in *info); advances *i.  false if malformed. */
static bool take_msg(unsigned *i, uint8_t *hdr, uint8_t *info, uint8_t *payload, unsigned *len)
{
	uint8_t f[40];
	unsigned n = 0, need, pos = *i;

	if (pos >= h.n)
		return false;
	f[n++] = h.rx[pos++].b;
	*hdr = f[0];
	if ((f[0] & 0xC0) == 0x00) {
		*info = 0;	/* SYS: no INFO byte, no payload */
		*len = 0;
		*i = pos;
		return true;
	}
	*len = hdr_len(f[0]);
	need = 1 + ((f[0] & 0xC0) == 0x80 ? 1 : 0) + *len + 1;
	while (n < need && pos < h.n)
		f[n++] = h.rx[pos++].b;
	if (n < need || chk(f, n - 1) != f[n - 1])
		return false;
	*info = (f[0] & 0xC0) == 0x80 ? f[1] : 0;
	memcpy(payload, f + need - 1 - *len, *len);
	*i = pos;
	return true;
}

static float get_f32(const uint8_t *p)
{
	uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
	float f;

	memcpy(&f, &u, 4);
	return f;
}

/* The whole handshake of one sensor; returns the number of failed checks. */
static void check_handshake(const struct expect *e)
{
	unsigned i = 0, len, bad = 0, msgs = 0;
	uint8_t hdr, info, p[32] = { 0 };
	uint64_t t_type, t_ack;
	bool pin6_low;
	uint64_t t0 = hs_now();

	host_init(&h, e->port);
	ev3_attach_uart_sensor(e->port, e->type, NULL);
	host_run(&h, 250 * MS);
	pin6_low = !gpio_in(ev3_input_pins[e->port].pin6);
	host_run(&h, 2000 * MS);
	ok(pin6_low, "type %u: pin 6 low during the auto-ID time", e->type);

	/* the line held low shows as one break character */
	ok(h.n > 0 && h.rx[0].b == 0 && (h.rx[0].lsr & 0x10), "type %u: break (LSR.BI) from the low pin 6", e->type);
	while (i < h.n && (h.rx[i].lsr & 0x10))
		i++;
	ok(i < h.n && h.rx[i].t - t0 >= 504 * MS && h.rx[i].t - t0 <= 520 * MS,
	   "type %u: first byte ends ~500 ms + one byte after power-up (%.1f ms)", e->type,
	   i < h.n ? (h.rx[i].t - t0) / 1e6 : 0.0);
	t_type = i < h.n ? h.rx[i].t : 0;

	ok(take_msg(&i, &hdr, &info, p, &len) && hdr == 0x40 && p[0] == e->type,
	   "type %u: TYPE 0x40 [%u] with its check byte", e->type, e->type);
	ok(take_msg(&i, &hdr, &info, p, &len) && hdr == 0x49 && p[0] == e->modes - 1 && p[1] == e->views - 1,
	   "type %u: MODES 0x49 [%u, %u]", e->type, e->modes - 1, e->views - 1);
	ok(take_msg(&i, &hdr, &info, p, &len) && hdr == 0x52 && len == 4 &&
	   (p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24) == 57600U, "type %u: SPEED 0x52 57600", e->type);
	for (int m = e->modes - 1; m >= 0; m--) {
		size_t nl = strlen(e->name[m]);

		if (!take_msg(&i, &hdr, &info, p, &len) || hdr != (0x80 | (nl <= 8 ? 3 : 4) << 3 | m) ||
		    info != 0x00 || memcmp(p, e->name[m], nl) != 0 || (nl < len && p[nl] != 0))
			bad++, tap_diag("mode %d NAME wrong (hdr 0x%02x)", m, hdr);
		if (!take_msg(&i, &hdr, &info, p, &len) || hdr != (0x98 | m) || info != 0x01)
			bad++, tap_diag("mode %d RAW wrong", m);
		if (!take_msg(&i, &hdr, &info, p, &len) || hdr != (0x98 | m) || info != 0x03 ||
		    !(get_f32(p + 4) > get_f32(p)))
			bad++, tap_diag("mode %d SI wrong", m);
		if (e->symbol[m]) {
			if (!take_msg(&i, &hdr, &info, p, &len) || hdr != (0x90 | m) || info != 0x04 ||
			    strncmp((char *)p, e->symbol[m], 4) != 0)
				bad++, tap_diag("mode %d SYMBOL wrong", m);
		} else if (e->type == 33) {
			/* the IR sensor's 00 FF where the symbol is missing */
			if (i + 1 >= h.n || h.rx[i].b != 0x00 || h.rx[i + 1].b != 0xFF)
				bad++, tap_diag("mode %d: no 00 FF", m);
			i += 2;
		}
		if (!take_msg(&i, &hdr, &info, p, &len) || hdr != (0x90 | m) || info != 0x80 ||
		    memcmp(p, e->fmt[m], 4) != 0)
			bad++, tap_diag("mode %d FORMAT wrong", m);
		msgs++;
	}
	is_int(bad, 0, "type %u: INFO for %u modes, highest first, NAME/RAW/SI/SYMBOL/FORMAT, no PCT, checks ok",
	       e->type, msgs);
	t_ack = i < h.n ? h.rx[i].t : 0;
	ok(take_msg(&i, &hdr, &info, p, &len) && hdr == 0x04, "type %u: ends with ACK 0x04", e->type);
	in_range((t_ack - t_type) / 1e9 + 2 * 4.17e-3, e->duration_s * 0.97, e->duration_s * 1.03,
		 "type %u: sequence lasts as captured (%.3f s)", e->type, (t_ack - t_type) / 1e9);
	/* no ACK from us: the colour sensor starts over within 80 ms, the others too */
	ok(i < h.n && h.rx[i].b == 0x40 && h.rx[i].t - t_ack < 100 * MS,
	   "type %u: without the host's ACK the handshake restarts (TYPE again after %.1f ms)", e->type,
	   i < h.n ? (h.rx[i].t - t_ack) / 1e6 : -1.0);
}

/* Waits for the sensor's ACK, answers it and switches to 57600; returns false if none came. */
static bool accept_sensor(const struct expect *e)
{
	uint8_t ack = 0x04;
	unsigned start = h.n;

	for (int tries = 0; tries < 4000; tries++) {
		host_run(&h, MS / 2);
		for (unsigned k = start; k < h.n; k++)
			if (h.rx[k].b == 0x04 && k > 0 && h.rx[k - 1].b != 0x00 && uart_sensor_get_state(ev3_input_uart_sensor(e->port)) == UART_SENSOR_WAIT_ACK) {
				host_send(&h, &ack, 1);
				host_baud(&h, 57600);
				h.n = 0;
				return true;
			}
		start = h.n;
	}
	return false;
}

/* Counts valid DATA frames of mode in h.rx. */
static unsigned count_data(unsigned mode, unsigned *other_mode, unsigned *bad_check)
{
	unsigned i = 0, len, n = 0;
	uint8_t hdr, info, p[32];

	*other_mode = *bad_check = 0;
	while (i < h.n) {
		unsigned save = i;

		if ((h.rx[i].b & 0xC0) != 0xC0) {
			i++;
			continue;
		}
		if (!take_msg(&i, &hdr, &info, p, &len)) {
			(*bad_check)++;
			i = save + 1;
			continue;
		}
		if ((hdr & 7) == mode)
			n++;
		else
			(*other_mode)++;
	}
	return n;
}

static void nack_for(uint64_t ns)
{
	uint8_t nack = 0x02;

	for (uint64_t t = 0; t < ns; t += 100 * MS) {
		host_send(&h, &nack, 1);
		host_run(&h, 100 * MS - 200000);
	}
}

int main(void)
{
	unsigned n, other, bad;

	tap_plan(4 * 10 + 14);
	devtest_boot(11, NULL);
	for (unsigned s = 0; s < 4; s++) {
		check_handshake(&sensors[s]);
		ev3_detach_input(sensors[s].port);
	}

	/* gyro on port 2 (UART0): ACK, 57600, DATA at ~330 frames/s while NACKed */
	ev3_attach_uart_sensor(1, 32, NULL);
	host_init(&h, 1);
	ok(accept_sensor(&sensors[1]), "gyro: host ACK sent after the sensor's ACK");
	nack_for(1000 * MS);
	n = count_data(0, &other, &bad);
	in_range(n, 280, 345, "gyro: GYRO-ANG DATA at ~330 frames/s (%u in 1 s)", n);
	is_int(bad, 0, "gyro: every DATA frame has a good check byte");
	ok(uart_sensor_baud(ev3_input_uart_sensor(1)) == 57600, "gyro now at 57600 baud");
	{
		struct uart_sensor_scene sc = *uart_sensor_scene(ev3_input_uart_sensor(1));
		int16_t ang;

		sc.rate_dps = 90.0;
		ev3_set_scene(1, &sc);
		h.n = 0;
		nack_for(1000 * MS);
		/* last frame's angle */
		ang = (int16_t)(h.rx[h.n - 2].b << 8 | h.rx[h.n - 3].b);
		in_range(ang, 85, 95, "gyro angle integrates 90 deg/s over 1 s (%d)", ang);
	}

	/* SELECT changes the stream */
	{
		uint8_t mode = 1;

		host_cmd(&h, 3, &mode, 1);
		h.n = 0;
		nack_for(500 * MS);
		n = count_data(1, &other, &bad);
		ok(n > 100 && other <= 1, "SELECT 1: GYRO-RATE frames now (%u, %u of mode 0)", n, other);
		is_int(uart_sensor_mode(ev3_input_uart_sensor(1)), 1, "sensor reports mode 1");
	}

	/* WRITE reaches the sensor */
	{
		uint8_t data[3] = { 0x11, 0x22, 0x33 };
		const struct uart_sensor_stats *st = uart_sensor_get_stats(ev3_input_uart_sensor(1));

		host_cmd(&h, 4, data, 3);
		ok(st->writes == 1 && st->last_write_len == 4 && !memcmp(st->last_write, data, 3),
		   "WRITE of 3 bytes arrives padded to 4");
	}

	/* keep-alive loss: no NACK for > 1 s -> sensor resets, data stops */
	{
		unsigned resets = uart_sensor_get_stats(ev3_input_uart_sensor(1))->resets;
		unsigned late;

		h.n = 0;
		host_run(&h, 1100 * MS);
		late = 0;
		for (unsigned k = 0; k < h.n; k++)
			if (h.rx[k].t > hs_now() - 50 * MS && (h.rx[k].b & 0xC0) == 0xC0 && !(h.rx[k].lsr & 0x18))
				late++;
		ok(uart_sensor_get_stats(ev3_input_uart_sensor(1))->resets == resets + 1,
		   "no keep-alive for 1 s: the sensor reset");
		is_int(late, 0, "no DATA after the reset");
		is_int(uart_sensor_get_state(ev3_input_uart_sensor(1)), UART_SENSOR_AUTOID,
		       "it holds pin 6 low again (power-up)");
	}

	/* colour: one frame per NACK while the value is steady, another when it changes */
	ev3_attach_uart_sensor(0, 29, NULL);
	host_init(&h, 0);
	ok(accept_sensor(&sensors[0]), "colour: ACKed");
	nack_for(1000 * MS);
	n = count_data(0, &other, &bad);
	in_range(n, 9, 13, "colour: steady value, one frame per NACK (%u in 1 s)", n);
	{
		struct uart_sensor_scene sc = *uart_sensor_scene(ev3_input_uart_sensor(0));

		sc.reflect_pct = 42;
		ev3_set_scene(0, &sc);
		h.n = 0;
		host_run(&h, 50 * MS);
		n = count_data(0, &other, &bad);
		ok(n == 1 && h.rx[1].b == 42, "colour: a change is sent at once (%u frame, value %u)", n,
		   h.n > 1 ? h.rx[1].b : 0);
	}
	hs_sim_shutdown();
	return tap_done();
}
