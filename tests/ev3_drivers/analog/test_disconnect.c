/*
 * test_disconnect.c — unplugging is seen within 100 ms of the last event
 * plus one 10 ms DCM period (output ports add up to 8 ms for the next pin 5
 * conversion); the port is floated again and a device plugged in later is
 * identified from scratch (20 ms settle + 350 ms stable); a scheduled unplug
 * fault of a UART sensor is handled the same way.
 */
#include "analog_test.h"

static void disconnect_body(void)
{
	const struct ev3_fault unplug = { EV3_FAULT_UNPLUG, 3, 0, 300 * MS };
	const volatile struct lms_analog *shm = analog_shm();
	double t0, t;

	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	ev3_attach_uart_sensor(3, UART_SENSOR_TYPE_IR, NULL);
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ok(wait_in_conn(0, LMS_CONN_INPUT_DUMB, 3000) > 0, "EV3 touch detected");
	ok(wait_in_conn(3, LMS_CONN_INPUT_UART, 100) > 0, "IR sensor detected");
	ok(wait_out_conn(0, LMS_CONN_OUTPUT_TACHO, 100) > 0, "large motor detected");
	dly_tsk(100);

	t0 = now_ms();
	ev3_detach_input(0);
	t = wait_in_conn(0, LMS_CONN_NONE, 300) - t0;
	in_range(t, 90, 111, "EV3 touch unplug seen after %.1f ms (100 ms + one period)", t);
	is_int(shm->in_dcm[0], LMS_TYPE_NONE, "its type is NONE again");

	t0 = now_ms();
	ev3_detach_output(0);
	t = wait_out_conn(0, LMS_CONN_NONE, 300) - t0;
	in_range(t, 90, 119, "motor unplug seen after %.1f ms (+ up to 8 ms to convert pin 5)", t);
	is_int(shm->out_dcm[0], LMS_TYPE_NONE, "output type is NONE again");

	dly_tsk(50);
	t0 = now_ms();
	ev3_attach_analog(0, EV3_INPUT_NXT_LIGHT, NULL);
	ev3_attach_motor(0, HS_MOTOR_MEDIUM, NULL);
	t = wait_in_conn(0, LMS_CONN_NXT_DUMB, 600) - t0;
	in_range(t, 350, 391, "a new device on the port is identified after %.1f ms", t);
	is_int(shm->in_dcm[0], LMS_TYPE_NXT_LIGHT, "and it is the new one (NXT light)");
	t = wait_out_conn(0, LMS_CONN_OUTPUT_TACHO, 600) - t0;
	in_range(t, 350, 440, "a medium motor on the emptied output port after %.1f ms", t);
	is_int(shm->out_dcm[0], LMS_TYPE_MINITACHO, "identified as MINITACHO");

	t0 = now_ms();
	ok(ev3_fault_at(rtos_host_now() + 10 * MS, &unplug) == E_OK, "unplug fault scheduled");
	t = wait_in_conn(3, LMS_CONN_NONE, 300) - t0;
	in_range(t, 100, 121, "UART sensor unplug fault seen after %.1f ms (fault at 10 ms)", t);
	t = wait_in_conn(3, LMS_CONN_INPUT_UART, 1500) - t0;
	ok(t > 310 + 350, "replugged sensor identified again after it held still (%.1f ms)", t);
}

int main(void)
{
	tap_plan(15);
	ok(analog_test_run(disconnect_body, 4, 8000), "the test body ran to its end");
	return tap_done();
}
