/*
 * test_busy_poll.c — an application busy-polling the touch sensor in EV3
 * style, `while (!pressed) ev3_touch_sensor_is_pressed(...)`, through the
 * whole stack: every round's service calls cost virtual time, so the drivers'
 * sampling goes on and the press the simulated hand makes at 200 ms reaches
 * the loop.
 */
#include "api_test.h"

static unsigned long rounds;
static uint64_t pressed_at_ms;

static void press(void *arg)
{
	(void)arg;
	ev3_set_touch(0, true);
}

static void attach_touch(void)
{
	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
}

static void poll_body(void)
{
	uint64_t start_ms;

	is_int(ev3_sensor_config(EV3_PORT_1, TOUCH_SENSOR), E_OK, "config touch on port 1");
	dly_tsk(10);
	start_ms = at_now_ms();
	rtos_host_event_at(rtos_host_now() + 200 * AT_MS, press, NULL);
	while (!ev3_touch_sensor_is_pressed(EV3_PORT_1))	/* EV3RT's idiom */
		rounds++;
	pressed_at_ms = at_now_ms() - start_ms;
}

int main(void)
{
	tap_plan(4);
	ok(at_run(attach_touch, poll_body, 4, 10), "the polling application finished");
	ok(pressed_at_ms >= 200 && pressed_at_ms <= 215, "the loop saw the press made at 200 ms (after %llu ms)",
	   (unsigned long long)pressed_at_ms);
	ok(rounds > 100000, "in %lu rounds, each costing virtual time", rounds);
	return tap_done();
}
