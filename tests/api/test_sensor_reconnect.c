/*
 * test_sensor_reconnect.c — a read that is waiting for a mode's data when the
 * sensor reconnects waits the whole handshake's bound again (docs/api.md):
 * the gyro is unplugged 1 ms into a mode switch and plugged in again at
 * 300 ms; its power-up and 2400-baud handshake take well over the 1.5 s a
 * mode switch may take, and the read still returns the new mode's value.
 */
#include "api_test.h"

static void attach(void)
{
	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, NULL);
}

static void unplug(void *arg)
{
	(void)arg;
	ev3_detach_input(1);
}

static void replug(void *arg)
{
	(void)arg;
	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, NULL);
}

static void body(void)
{
	int16_t rate = 1, angle = 1;
	uint64_t start;
	ER ercd;

	is_int(ev3lx_sensor_config(EV3_PORT_2, GYRO_SENSOR), E_OK, "gyro configured");
	is_int(ev3lx_gyro_sensor_get_rate(EV3_PORT_2, &rate), E_OK, "rate read (mode 1)");
	rtos_host_event_at(rtos_host_now() + 1 * AT_MS, unplug, NULL);
	rtos_host_event_at(rtos_host_now() + 300 * AT_MS, replug, NULL);
	start = at_now_ms();
	ercd = ev3lx_gyro_sensor_get_angle(EV3_PORT_2, &angle);
	is_int(ercd, E_OK, "the angle read waited through the reconnection");
	ok(at_now_ms() - start > 1500 && at_now_ms() - start < 4300,
	   "after %llu ms: longer than a mode switch may take, within the handshake's bound",
	   (unsigned long long)(at_now_ms() - start));
	is_int(angle, 0, "the fresh sensor's angle");
}

int main(void)
{
	tap_plan(6);
	ok(at_run(attach, body, 7, 20), "the application finished");
	return tap_done();
}
