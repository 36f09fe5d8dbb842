/*
 * test_iic.c — d_iic through its service calls on the simulated brick, with
 * d_analog detecting the sensors: an NXT I2C sensor is reported as LEGO's
 * firmware does (type 123, connection 120); starting the port probes it
 * (the HiTechnic strings at 0x08/0x10 of address 0x01; the NXT temperature
 * sensor by its configuration register at 0x4C, left at 12 bits); IIC_SET
 * polls it into the raw ring (byte order by the sign of the read length,
 * sample age in repeat[]); IIC_SETUP runs raw transactions (FAIL when
 * nobody answers); unplug and replug; argument errors; and the waveform as
 * the slave saw it (no aborted bytes, no contention, LEGO's turnaround
 * rather than repeated STARTs).
 */
#include "iic_test.h"

static void test_detect_and_probe(void)
{
	struct nxt_iic_scene accel = { .accel = { 100, -200, 300 } };
	struct lms_iic_str s;
	uint64_t t0;

	ok(ev3_attach_nxt_iic(0, NXT_IIC_HT_ACCEL, &accel) == E_OK, "HiTechnic accelerometer on port 1");
	ok(it_wait_conn(0, LMS_CONN_NXT_IIC, 3000), "d_analog: connection NXT I2C (120) (detection starts at 2 s)");
	is_int(it_analog->in_dcm[0], LMS_TYPE_NXT_IIC, "d_analog: type NXT I2C (123)");
	t0 = rtos_host_now();
	ok(iic_svc_start(0, 0) == E_OK, "port 1 started");
	ok(it_wait_state(0, LMS_IIC_STATE_SETUP_WAIT, 500), "probed: waiting for setup");
	in_range((rtos_host_now() - t0) / IT_MS, 10, 100, "probe took %.1f ms (temperature try, then 0x01)",
		 (double)(rtos_host_now() - t0) / (double)IT_MS);
	ok(it_shm->changed[0] == 1 && (it_shm->status[0] & LMS_IIC_PORT_CHANGED), "changed flagged");
	memset(&s, 0, sizeof(s));
	ok(iic_svc_type_info(0, &s) == E_OK, "type info");
	is_str(s.manufacturer, "HITECHNC", "manufacturer");
	is_str(s.sensor_type, "Accel.  ", "sensor type (trailing blanks as sent)");
	is_int(it_shm->changed[0], 0, "changed cleared by READ_TYPE_INFO");
}

static void test_poll(void)
{
	struct lms_iic_str s = it_poll(0, 0, 0, 0x01420000U, 2, -6, 100);
	struct nxt_iic_scene accel = { .accel = { -5, 7, 255 } };
	const int8_t *v;
	uint16_t first;

	ok(iic_svc_set(&s) == E_OK, "poll 01 42, 6 bytes in bus order, every 100 ms");
	v = it_wait_sample(0, 300);
	ok(v != NULL, "a sample arrived");
	if (!v)
		return;
	is_int(v[0] * 4 + (v[3] & 3), 100, "X");
	is_int(v[1] * 4 + (v[4] & 3), -200, "Y");
	is_int(v[2] * 4 + (v[5] & 3), 300, "Z");
	{
		/* one poll's bus time: its first START to its second STOP (write, turnaround, read) */
		struct nxt_iic_stats st0, st1;
		uint64_t t_start = 0, t_stop = 0;

		ev3_nxt_iic_stats(0, &st0);
		while (!t_stop) {
			ev3_nxt_iic_stats(0, &st1);
			if (!t_start && st1.starts > st0.starts)
				t_start = rtos_host_now();
			if (t_start && st1.stops >= st0.stops + 2)
				t_stop = rtos_host_now();
			dly_tsk(1);
		}
		in_range((t_stop - t_start) / 100000U, 80, 130, "a poll of 6 bytes takes %.1f ms on the bus (1 ms steps)",
			 (double)(t_stop - t_start) / (double)IT_MS);
	}
	first = it_shm->actual[0];
	ev3_set_nxt_iic_scene(0, &accel);
	dly_tsk(250);
	v = lms_iic_sample(it_shm, 0);
	ok(v && v[0] * 4 + (v[3] & 3) == -5 && v[1] * 4 + (v[4] & 3) == 7 && v[2] * 4 + (v[5] & 3) == 255,
	   "new values polled");
	in_range((it_shm->actual[0] + LMS_IIC_LOG_SIZE - first) % LMS_IIC_LOG_SIZE, 2, 3,
		 "2..3 polls in 250 ms (100 ms period plus the transaction)");
	in_range(it_shm->repeat[0][it_shm->actual[0]], 0, 110, "age of the newest sample in ms");
	is_int(iic_svc_state(0) == LMS_IIC_STATE_REPEAT || iic_svc_state(0) == LMS_IIC_STATE_READING ||
	       iic_svc_state(0) == LMS_IIC_STATE_WRITING, 1, "port polling");
}

static void test_temperature(void)
{
	struct nxt_iic_scene temp = { .temp_c = 21.75 };
	struct lms_iic_str s;
	const int8_t *v;

	ok(ev3_attach_nxt_iic(1, NXT_IIC_TEMP, &temp) == E_OK, "NXT temperature sensor on port 2");
	ok(it_wait_conn(1, LMS_CONN_NXT_IIC, 1000), "detected as NXT I2C");
	ok(iic_svc_start(1, 0) == E_OK && it_wait_state(1, LMS_IIC_STATE_SETUP_WAIT, 200), "probed");
	memset(&s, 0, sizeof(s));
	ok(iic_svc_type_info(1, &s) == E_OK, "type info");
	is_str(s.manufacturer, "LEGO", "manufacturer LEGO");
	is_str(s.sensor_type, "Temp.", "type Temp.");
	is_int(ev3_nxt_iic_register(1, 1), 0x60, "probe left the sensor at 12 bits");
	s = it_poll(1, 0x4C016000U, 3, 0x4C000000U, 2, 2, 100);
	ok(iic_svc_set(&s) == E_OK, "setup 4C 01 60, poll 4C 00, 2 bytes reversed");
	v = it_wait_sample(1, 300);
	ok(v != NULL, "a sample");
	if (v)
		is_int((int16_t)((uint8_t)v[0] | (uint8_t)v[1] << 8), (int)(21.75 * 256), "raw int16 / 256 = 21.75 C");
}

/* An IIC_SETUP request on port 1: write register reg to address 0x01, then
 * read 8 bytes (rd_lng < 0: in bus order). */
static void read8_request(struct lms_iic_dat *d, uint8_t reg)
{
	memset(d, 0, sizeof(*d));
	d->port = 0;
	d->repeat = 1;
	d->wr_lng = 2;
	d->wr_data[0] = 0x01;
	d->wr_data[1] = reg;
	d->rd_lng = -8;
}

static void test_setup(void)
{
	struct lms_iic_dat d;

	read8_request(&d, 0x10);
	is_int(it_setup(&d, 500), LMS_IIC_OK, "IIC_SETUP: 8 bytes from 0x10");
	ok(!memcmp(d.rd_data, "Accel.  ", 8), "in bus order");
	d.rd_lng = 2;
	d.wr_data[1] = 0x42;
	is_int(it_setup(&d, 500), LMS_IIC_OK, "IIC_SETUP: 2 bytes from 0x42, reversed");
	ok((int8_t)d.rd_data[1] == -2 && (int8_t)d.rd_data[0] == 1, "Y upper then X upper (reversed)");
	d.wr_data[0] = 0x22;
	is_int(it_setup(&d, 500), LMS_IIC_FAIL, "nobody at 0x22: FAIL");
	/* a request on the bus when IIC_SET restarts the port's setup is sent again */
	d.wr_data[0] = 0x01;
	d.wr_data[1] = 0x08;
	d.rd_lng = -8;
	ok(iic_svc_setup(&d) == E_OK && d.result == LMS_IIC_BUSY, "request latched");
	dly_tsk(4);
	{
		struct lms_iic_str s = it_poll(0, 0, 0, 0x01420000U, 2, -6, 100);

		ok(iic_svc_set(&s) == E_OK, "IIC_SET while the request is under way");
	}
	is_int(it_setup(&d, 500), LMS_IIC_OK, "the request still completes");
	ok(!memcmp(d.rd_data, "HITECHNC", 8), "with its answer");
}

static void test_errors(void)
{
	struct lms_iic_str s = it_poll(0, 0, 0, 0x01420000U, 5, 6, 100);
	struct lms_iic_dat d;

	is_int(iic_svc_start(4, 0), E_ID, "port 5: E_ID");
	is_int(iic_svc_set(&s), E_PAR, "poll string of 5 bytes: E_PAR");
	s = it_poll(0, 0, 0, 0x01420000U, 2, 33, 100);
	is_int(iic_svc_set(&s), E_PAR, "read length 33: E_PAR");
	s = it_poll(7, 0, 0, 0x01420000U, 2, 6, 100);
	is_int(iic_svc_set(&s), E_ID, "IIC_SET on port 8: E_ID");
	is_int(iic_svc_type_info(2, &s), E_OBJ, "type info of a port not started: E_OBJ");
	memset(&d, 0, sizeof(d));
	d.port = 0;
	d.wr_lng = 0;
	is_int(iic_svc_setup(&d), E_PAR, "IIC_SETUP without an address: E_PAR");
	is_int(iic_svc_set(NULL), E_MACV, "NULL IICSTR: E_MACV");
}

static void test_unplug(void)
{
	struct nxt_iic_stats st, before;
	struct lms_iic_str s;
	const int8_t *v;

	ok(ev3_detach_input(0) == E_OK, "port 1 unplugged");
	ok(it_wait_conn(0, 126, 1000), "d_analog: connection none");
	ok(iic_svc_stop(0) == E_OK && it_wait_state(0, LMS_IIC_STATE_IDLE, 10), "port stopped");
	ok(ev3_attach_nxt_iic(0, NXT_IIC_HT_COLOR, &(struct nxt_iic_scene){ .color_number = 9, .rgb = { 1, 2, 3 } }) == E_OK,
	   "a HiTechnic colour sensor plugged in instead");
	ok(it_wait_conn(0, LMS_CONN_NXT_IIC, 1000), "detected again");
	{
		struct lms_iic_dat d;

		read8_request(&d, 0x08);
		ok(iic_svc_start(0, 0) == E_OK && iic_svc_setup(&d) == E_OK && d.result == LMS_IIC_BUSY,
		   "started, a request latched at once");
		ok(iic_svc_stop(0) == E_OK && iic_svc_start(0, 0) == E_OK, "stopped and started again");
		is_int(it_setup(&d, 500), LMS_IIC_OK, "a new request after the restart completes (the old one forgotten)");
		ok(!memcmp(d.rd_data, "HiTechnc", 8), "read from the new sensor");
	}
	dly_tsk(5);
	ok(iic_svc_state(0) == LMS_IIC_STATE_WAITING, "probed, then the request ran (state WAITING)");
	memset(&s, 0, sizeof(s));
	iic_svc_type_info(0, &s);
	is_str(s.manufacturer, "HiTechnc", "manufacturer HiTechnc");
	is_str(s.sensor_type, "Color   ", "type Color");
	s = it_poll(0, 0, 0, 0x01420000U, 2, -4, 50);
	ok(iic_svc_set(&s) == E_OK, "poll 01 42, 4 bytes");
	v = it_wait_sample(0, 300);
	ok(v && v[0] == 9 && v[1] == 1 && v[2] == 2 && v[3] == 3, "colour number and RGB");
	ok(ev3_nxt_iic_stats(0, &before) == E_OK, "slave counters");
	dly_tsk(500);
	ev3_nxt_iic_stats(0, &st);
	is_int(st.aborted_bytes - before.aborted_bytes, 0, "polling: no START/STOP inside a byte");
	is_int(st.contention, 0, "no contention on SDA");
	is_int(st.repeated_starts, 0, "write->read by LEGO's STOP/START turnaround");
	in_range(st.address_acks - before.address_acks, 16, 20, "two addresses per poll, 8..10 polls in 500 ms");
	is_int(st.stops - before.stops, st.starts - before.starts, "every START ended by a STOP");
}

/* Probed but not taken by user space within 1 s: the port is reset and probed again. */
static void test_setup_wait_restart(void)
{
	struct nxt_iic_stats a, b;
	bool restarted = false;

	ok(ev3_attach_nxt_iic(2, NXT_IIC_HT_COLOR_V2, NULL) == E_OK && iic_svc_start(2, 0) == E_OK &&
	   it_wait_state(2, LMS_IIC_STATE_SETUP_WAIT, 200), "port 3 probed, nobody reacts");
	ev3_nxt_iic_stats(2, &a);
	for (unsigned ms = 0; ms < 1100 && !restarted; ms++) {
		restarted = iic_svc_state(2) == LMS_IIC_STATE_RESTART;
		dly_tsk(1);
	}
	ok(restarted, "reset after 1 s (RESTART)");
	ok(it_wait_state(2, LMS_IIC_STATE_SETUP_WAIT, 200), "probed again");
	ev3_nxt_iic_stats(2, &b);
	in_range(b.address_acks - a.address_acks, 4, 8, "the ID strings were read again (%u addresses ACKed)",
		 b.address_acks - a.address_acks);
	ok(iic_svc_stop(2) == E_OK, "port 3 stopped");
}

/* Nothing on the port (pin 6 pulled down, no pull-up): every probe fails at its START. */
static void test_empty_port(void)
{
	struct lms_iic_str s;
	uint64_t t0 = rtos_host_now();

	ok(iic_svc_start(3, 0) == E_OK, "port 4 started with nothing plugged in");
	ok(it_wait_state(3, LMS_IIC_STATE_WAITING, 2000), "three scan rounds, no ID: waiting");
	in_range((rtos_host_now() - t0) / IT_MS, 200, 2000, "the scan took %.0f ms",
		 (double)(rtos_host_now() - t0) / (double)IT_MS);
	memset(&s, 0x55, sizeof(s));
	s.port = 3;
	ok(iic_svc_type_info(3, &s) == E_OK && s.manufacturer[0] == 0 && s.sensor_type[0] == 0,
	   "no strings (no phantom \"LEGO\"/\"Store\" from a floating SDA)");
	is_int(it_shm->status[3] & LMS_IIC_DATA_READY, 0, "no data");
	ok(iic_svc_stop(3) == E_OK, "port 4 stopped");
}

static void body(void)
{
	test_detect_and_probe();
	test_poll();
	test_temperature();
	test_setup();
	test_errors();
	test_setup_wait_restart();
	test_empty_port();
	test_unplug();
}

int main(void)
{
	tap_plan(79);
	ok(it_run(body, 1), "test body finished");
	return tap_done();
}
