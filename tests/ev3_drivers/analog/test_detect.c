/*
 * test_detect.c — d_analog's connection manager identifies every device the
 * simulated EV3 can carry, within the specified time: detection starts 2 s
 * after the module loads, a port is floated for 20 ms, events must hold for
 * 350 ms, then the evaluation rules decide (motors take two more 20 ms
 * re-reads).  Types and connections appear in ANALOG and in /dev/lms_dcm.
 */
#include "analog_test.h"

/* First DCM tick at 2000 ms, idle at 2020, evaluation 350 ms later; motors +20..40 ms. */
#define DETECT_EARLIEST_MS	2360.0
#define DETECT_LATEST_MS	2430.0

static void detect_boot1(void)
{
	const struct ev3_analog_options dumb = { .id_ohms = 4700 };
	const volatile struct lms_analog *shm = analog_shm();
	struct analog_input_state in;
	struct analog_output_state out;
	double t_in[4], t_out[2];
	char dcm[16];
	unsigned p;

	ok(shm != NULL, "ANALOG is mapped");
	if (!shm)
		tap_bail_out("ANALOG is not mapped");
	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	ev3_attach_analog(1, EV3_INPUT_NXT_TOUCH, NULL);
	ev3_attach_analog(2, EV3_INPUT_NXT_LIGHT, NULL);
	ev3_attach_analog(3, EV3_INPUT_DUMB, &dumb);
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(1, HS_MOTOR_MEDIUM, NULL);

	dly_tsk(1990);
	for (p = 0; p < 4; p++)
		if (shm->in_conn[p] != LMS_CONN_NONE || shm->out_conn[p] != LMS_CONN_NONE)
			break;
	is_int(p, 4, "nothing is reported before detection starts at 2 s");

	t_in[0] = wait_in_conn(0, LMS_CONN_INPUT_DUMB, 600);
	t_in[1] = wait_in_conn(1, LMS_CONN_NXT_DUMB, 600);
	t_in[2] = wait_in_conn(2, LMS_CONN_NXT_DUMB, 600);
	t_in[3] = wait_in_conn(3, LMS_CONN_INPUT_DUMB, 600);
	t_out[0] = wait_out_conn(0, LMS_CONN_OUTPUT_TACHO, 600);
	t_out[1] = wait_out_conn(1, LMS_CONN_OUTPUT_TACHO, 600);
	for (p = 0; p < 4; p++)
		in_range(t_in[p], DETECT_EARLIEST_MS, DETECT_LATEST_MS,
			 "input port %u identified at %.1f ms", p + 1, t_in[p]);
	for (p = 0; p < 2; p++)
		in_range(t_out[p], DETECT_EARLIEST_MS, DETECT_LATEST_MS,
			 "output port %c identified at %.1f ms", 'A' + p, t_out[p]);

	is_int(analog_input(0, &in), E_OK, "port 1 state");
	is_int(in.type, LMS_TYPE_UNKNOWN, "EV3 touch: a dumb device, type left to user space");
	in_range(in.pin1_mv, 870, 935, "EV3 touch: its ID resistor reads ~902 mV on pin 1 (%u)",
		 in.pin1_mv);
	is_int(shm->in_dcm[1], LMS_TYPE_NXT_TOUCH, "NXT touch identified");
	is_int(shm->in_dcm[2], LMS_TYPE_NXT_LIGHT, "NXT light identified");
	is_int(analog_input(3, &in), E_OK, "port 4 state");
	in_range(in.pin1_mv, 1560, 1640, "dumb device: 4.7 kohm reads ~1598 mV (%u)", in.pin1_mv);
	is_int(shm->out_dcm[0], LMS_TYPE_TACHO, "large motor on A: TACHO");
	is_int(shm->out_dcm[1], LMS_TYPE_MINITACHO, "medium motor on B: MINITACHO");
	is_int(analog_output(0, &out), E_OK, "port A state");
	ok(out.pin5_mv < 250 || out.pin5_mv > 2600, "large motor pin 5 away from the idle window (%u)",
	   out.pin5_mv);

	dly_tsk(1000);
	ok(shm->out_conn[2] == LMS_CONN_NONE && shm->out_conn[3] == LMS_CONN_NONE &&
	   shm->out_dcm[2] == LMS_TYPE_NONE, "empty output ports stay NONE");
	is_int(analog_dcm_read(dcm, sizeof(dcm)), LMS_DCM_READ_SIZE, "lms_dcm read returns 10 bytes");
	ok(dcm[0] == LMS_TYPE_UNKNOWN && dcm[1] == LMS_TYPE_NXT_TOUCH && dcm[2] == LMS_TYPE_NXT_LIGHT &&
	   dcm[3] == LMS_TYPE_UNKNOWN && dcm[4] == LMS_TYPE_TACHO && dcm[5] == LMS_TYPE_MINITACHO &&
	   dcm[6] == LMS_TYPE_NONE && dcm[7] == LMS_TYPE_NONE && dcm[8] == '\r' && dcm[9] == 0,
	   "lms_dcm read: InDcm[4], OutDcm[4], CR, NUL");
}

static void detect_boot2(void)
{
	const volatile struct lms_analog *shm = analog_shm();
	double t_uart, t_gyro, t_touch;

	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL);
	ev3_attach_analog(1, EV3_INPUT_NXT_TOUCH, NULL);
	ev3_set_touch(1, true);
	ev3_attach_uart_sensor(3, UART_SENSOR_TYPE_GYRO, NULL);
	dly_tsk(1990);

	t_uart = wait_in_conn(0, LMS_CONN_INPUT_UART, 600);
	t_touch = wait_in_conn(1, LMS_CONN_NXT_DUMB, 600);
	t_gyro = wait_in_conn(3, LMS_CONN_INPUT_UART, 600);
	in_range(t_uart, DETECT_EARLIEST_MS, DETECT_LATEST_MS,
		 "colour sensor (handshaking at 2400 baud meanwhile): INPUT_UART at %.1f ms", t_uart);
	in_range(t_gyro, DETECT_EARLIEST_MS, DETECT_LATEST_MS, "gyro sensor: INPUT_UART at %.1f ms",
		 t_gyro);
	in_range(t_touch, DETECT_EARLIEST_MS, DETECT_LATEST_MS + 20,
		 "pressed NXT touch (~900 mV, re-read after 20 ms) at %.1f ms", t_touch);
	is_int(shm->in_dcm[1], LMS_TYPE_NXT_TOUCH, "pressed NXT touch is still a touch sensor");
	is_int(shm->in_dcm[0], LMS_TYPE_UNKNOWN, "UART sensor type is left to d_uart");
	dly_tsk(500);
	is_int(shm->in_conn[2], LMS_CONN_NONE, "empty input port stays NONE");
}

int main(void)
{
	tap_plan(30);
	ok(analog_test_run(detect_boot1, 1, 5000), "boot 1 ran to its end");
	ok(analog_test_run(detect_boot2, 2, 5000), "boot 2 ran to its end");
	return tap_done();
}
