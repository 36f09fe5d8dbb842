/*
 * test_sensor_empty_port.c — a UART sensor configured on a port with nothing
 * plugged in: the first read waits for it once (the handshake's bound, 4 s)
 * and fails with E_TMOUT; later reads fail at once instead of each waiting
 * again (EV3RT's reads, which wait for data with no bound, would hang); the
 * EV3RT form returns 0 as promptly.  Configuring the port again gives it
 * its one wait back.
 */
#include "api_test.h"

static void body(void)
{
	uint8_t pct = 1;
	uint64_t t0, slowest = 0;
	ER ercd = E_OK;

	is_int(ev3lx_sensor_config(EV3_PORT_3, COLOR_SENSOR), E_OK, "colour sensor configured on empty port 3");
	t0 = at_now_ms();
	is_int(ev3lx_color_sensor_get_reflect(EV3_PORT_3, &pct), E_TMOUT, "the first read times out");
	in_range((double)(at_now_ms() - t0), 4000, 4010, "after the handshake's bound (%llu ms)",
		 (unsigned long long)(at_now_ms() - t0));
	for (int i = 0; i < 100; i++) {
		t0 = rtos_host_now();
		ercd = ev3lx_color_sensor_get_reflect(EV3_PORT_3, &pct);
		if (ercd != E_TMOUT)
			break;
		if (rtos_host_now() - t0 > slowest)
			slowest = rtos_host_now() - t0;
		dly_tsk(4);
	}
	is_int(ercd, E_TMOUT, "100 more reads still fail");
	ok(slowest < AT_MS / 10, "each at once (the slowest took %llu us)", (unsigned long long)(slowest / 1000));
	t0 = rtos_host_now();
	is_int(ev3_color_sensor_get_reflect(EV3_PORT_3), 0, "EV3RT's form returns 0");
	ok(rtos_host_now() - t0 < AT_MS / 10, "as promptly");

	/* configuring a silent port again waits once more */
	is_int(ev3lx_sensor_config(EV3_PORT_4, COLOR_SENSOR), E_OK, "colour sensor configured on empty port 4");
	is_int(ev3lx_color_sensor_get_ambient(EV3_PORT_4, &pct), E_TMOUT, "its first read times out");
	is_int(ev3lx_sensor_config(EV3_PORT_4, COLOR_SENSOR), E_OK, "configured again");
	t0 = at_now_ms();
	is_int(ev3lx_color_sensor_get_ambient(EV3_PORT_4, &pct), E_TMOUT, "its next read waits again");
	ok(at_now_ms() - t0 >= 3900, "the whole bound (%llu ms)", (unsigned long long)(at_now_ms() - t0));
}

int main(void)
{
	tap_plan(13);
	ok(at_run(NULL, body, 3, 30), "the application finished");
	return tap_done();
}
