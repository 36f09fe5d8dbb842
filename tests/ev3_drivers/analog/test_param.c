/*
 * test_param.c — the dcm_start_ms module parameter moves the start of
 * detection (LEGO's fixed 2 s): with 500 ms, a device is identified 500 +
 * 20 + 350 ms after boot; nothing before.
 */
#include "analog_test.h"
#include <linux/moduleparam.h>
#include <linux_compat/modparam.h>

static void param_body(void)
{
	const volatile struct lms_analog *shm = analog_shm();
	double t;

	ev3_attach_analog(2, EV3_INPUT_EV3_TOUCH, NULL);
	ev3_attach_motor(3, HS_MOTOR_LARGE, NULL);
	dly_tsk(490);
	ok(shm->in_conn[2] == LMS_CONN_NONE && shm->out_conn[3] == LMS_CONN_NONE,
	   "nothing reported before 500 ms");
	t = wait_in_conn(2, LMS_CONN_INPUT_DUMB, 600);
	in_range(t, 860, 930, "EV3 touch identified at %.1f ms", t);
	t = wait_out_conn(3, LMS_CONN_OUTPUT_TACHO, 600);
	in_range(t, 860, 930, "large motor identified at %.1f ms", t);
}

int main(void)
{
	tap_plan(5);
	is_int(lx_module_param_set("d_analog", "dcm_start_ms", "500"), E_OK, "dcm_start_ms = 500");
	ok(analog_test_run(param_body, 9, 3000), "the test body ran to its end");
	return tap_done();
}
