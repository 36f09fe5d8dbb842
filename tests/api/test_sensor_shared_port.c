/*
 * test_sensor_shared_port.c — two tasks read one colour sensor in two modes.
 *
 * A line follower often reads reflected light in its control task while
 * another task reads the ambient light or the colour; each read asks the
 * sensor for its own mode.  On EV3RT each call re-selects the mode and
 * returns whatever the newest sample holds.  Here every call must return a
 * value of the mode it asked for, and neither task may time out while the
 * other one's switch is in flight.
 */
#include "api_test.h"

#define OTHER_TASK_ID  2
#define ROUNDS         25

static const struct uart_sensor_scene color_scene = {
	.reflect_pct = 37, .ambient_pct = 12, .color = 5, .rgb = { 300, 200, 100 },
};

struct reader_tally {
	unsigned reads, errors, wrong;
	ER first_error;
	bool done;
};

static struct reader_tally reflect_tally, ambient_tally;

static void attach_color_sensor(void)
{
	ev3_attach_uart_sensor(0, 29, NULL);
	ev3_set_scene(0, &color_scene);
}

/* Records one read's outcome in tally: an error, or a value other than expected. */
static void tally_read(struct reader_tally *tally, ER ercd, uint8_t pct, uint8_t expected)
{
	tally->reads++;
	if (ercd != E_OK) {
		if (tally->errors++ == 0)
			tally->first_error = ercd;
	} else if (pct != expected) {
		tally->wrong++;
	}
}

/* The second task: ambient light, every 7 ms. */
static void ambient_reader(intptr_t exinf)
{
	(void)exinf;
	for (int i = 0; i < ROUNDS; i++) {
		uint8_t pct = 0;
		ER ercd = ev3lx_color_sensor_get_ambient(EV3_PORT_1, &pct);

		tally_read(&ambient_tally, ercd, pct, 12);
		dly_tsk(7);
	}
	ambient_tally.done = true;
}

/* The application task: configures the port, wakes the second reader, then
 * reads reflected light every 5 ms and waits for the other task to finish. */
static void reflect_body(void)
{
	uint8_t pct = 0;

	is_int(ev3lx_sensor_config(EV3_PORT_1, COLOR_SENSOR), E_OK, "config colour on port 1");
	is_int(ev3lx_color_sensor_get_reflect(EV3_PORT_1, &pct), E_OK, "first reflect waits for the handshake");
	is_int(act_tsk(OTHER_TASK_ID), E_OK, "the ambient reader starts");
	for (int i = 0; i < ROUNDS; i++) {
		ER ercd = ev3lx_color_sensor_get_reflect(EV3_PORT_1, &pct);

		tally_read(&reflect_tally, ercd, pct, 37);
		dly_tsk(5);
	}
	while (!ambient_tally.done)
		dly_tsk(10);
}

int main(void)
{
	static const struct rtos_task_cfg other = {
		OTHER_TASK_ID, TA_NULL, 0, ambient_reader, 8, AT_STACK, AT_DOMAIN, "ambient",
	};
	static const struct rtos_cfg extra = { .name = "second_reader", .tasks = &other, .ntasks = 1 };

	tap_plan(10);
	at_include(&extra);
	ok(at_run(attach_color_sensor, reflect_body, 5, 60), "both readers finished");
	is_int(reflect_tally.reads, ROUNDS, "the reflect task read %u times", ROUNDS);
	is_int(reflect_tally.errors, 0, "no reflect read failed (first error %d)", reflect_tally.first_error);
	is_int(reflect_tally.wrong, 0, "every reflect read is the reflected light");
	is_int(ambient_tally.reads, ROUNDS, "the ambient task read %u times", ROUNDS);
	is_int(ambient_tally.errors, 0, "no ambient read failed (first error %d)", ambient_tally.first_error);
	is_int(ambient_tally.wrong, 0, "every ambient read is the ambient light");
	return tap_done();
}
