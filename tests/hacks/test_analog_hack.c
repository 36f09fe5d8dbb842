/*
 * test_analog_hack.c — every d_analog service call refuses bad arguments
 * with a TOPPERS code and changes nothing: port numbers (E_ID), lengths and
 * pin commands (E_PAR, E_NOSPT), buffers outside the caller's protection
 * domain (E_MACV, from a user-domain task that may touch only its stack),
 * non-task context (E_CTX), and a driver that failed to load (E_OBJ).
 */
#include "analog_test.h"
#include <linux/moduleparam.h>
#include "host_sim/gpio.h"
#include <linux_compat/modparam.h>

#define IN1_PIN5	HS_GPIO(0, 2)

static struct analog_input_state kernel_state;	/* outside the user domain */
static char kernel_buf[64];
static const struct lms_analog *kernel_ptr;
static ER ctx_ercd;

/* Runs in the hardware's context: a service call from non-task context. */
static void call_from_event(void *arg)
{
	struct analog_output_state st;

	(void)arg;
	ctx_ercd = analog_output(0, &st);
}

static void user_body(void)
{
	struct analog_input_state in;
	struct analog_output_state out;
	const struct lms_analog *map;
	char buf[64];
	char cmd[LMS_DCM_WRITE_SIZE] = { '7', '-', '-', '-' };
	bool level;

	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	is_int(analog_input(0, &in), E_OK, "analog_input with a stack buffer");
	is_int(analog_input(4, &in), E_ID, "analog_input: port 4 is E_ID");
	is_int(analog_input((uint_t)-1, &in), E_ID, "analog_input: port -1 is E_ID");
	is_int(analog_output(4, &out), E_ID, "analog_output: port 4 is E_ID");
	is_int(analog_input(0, NULL), E_MACV, "analog_input: NULL is E_MACV");
	is_int(analog_input(0, &kernel_state), E_MACV, "analog_input: memory outside the domain");
	is_int(analog_output(0, (struct analog_output_state *)kernel_buf), E_MACV,
	       "analog_output: memory outside the domain");
	is_int(analog_map(NULL), E_MACV, "analog_map: NULL is E_MACV");
	is_int(analog_map(&kernel_ptr), E_MACV, "analog_map: memory outside the domain");
	is_int(analog_map(&map), E_OK, "analog_map into the stack");

	is_int(analog_dcm_read(buf, LMS_DCM_READ_SIZE - 1), E_PAR, "dcm read: 9 bytes is E_PAR");
	is_int(analog_dcm_read(kernel_buf, sizeof(kernel_buf)), E_MACV, "dcm read: foreign buffer");
	is_int(analog_dcm_read(NULL, LMS_DCM_READ_SIZE), E_MACV, "dcm read: NULL");
	is_int(analog_dcm_read(buf, sizeof(buf)), LMS_DCM_READ_SIZE, "dcm read: 10 bytes");
	is_int(analog_text(buf, 5), 5, "text: count honoured");
	is_int(analog_text(buf, 0), 0, "text: zero bytes");
	is_int(analog_text(kernel_buf, sizeof(kernel_buf)), E_MACV, "text: foreign buffer");
	is_int(analog_text(buf, (uint_t)-1), E_PAR, "text: a length beyond the result range is E_PAR");

	dly_tsk(2500);
	is_int(analog_dcm_write(cmd, 3), E_PAR, "dcm write: 3 bytes is E_PAR");
	is_int(analog_dcm_write(cmd, 5), E_PAR, "dcm write: 5 bytes is E_PAR");
	is_int(analog_dcm_write(kernel_buf, LMS_DCM_WRITE_SIZE), E_MACV, "dcm write: foreign buffer");
	is_int(analog_dcm_write(NULL, LMS_DCM_WRITE_SIZE), E_MACV, "dcm write: NULL");
	cmd[3] = 'z';
	is_int(analog_dcm_write(cmd, LMS_DCM_WRITE_SIZE), E_PAR, "dcm write: bad character is E_PAR");
	ok(!hs_gpio_soc_output(IN1_PIN5, &level), "and port 1's pins were left alone");
	cmd[3] = 0x0D;
	is_int(analog_dcm_write(cmd, LMS_DCM_WRITE_SIZE), E_NOSPT, "dcm write: NXT colour is E_NOSPT");
	is_int(analog_set_pins(4, LMS_DCM_FLOAT), E_ID, "set_pins: port 4 is E_ID");
	is_int(analog_set_pins(0, '8'), E_PAR, "set_pins: '8' is E_PAR");
	is_int(analog_set_pins(0, LMS_DCM_PINS(LMS_DCM_PIN5_HIGH)), E_OK, "set_pins: pin 5 high");
	ok(hs_gpio_soc_output(IN1_PIN5, &level) && level, "port 1 pin 5 driven high");

	hs_sim_at(rtos_host_now() + 1000, call_from_event, NULL);
	dly_tsk(1);
	is_int(ctx_ercd, E_CTX, "a call from non-task context is E_CTX");
}

static void unloaded_body(void)
{
	struct analog_input_state in;
	char buf[16];

	is_int(analog_input(0, &in), E_OBJ, "driver not loaded: analog_input is E_OBJ");
	is_int(analog_map(&kernel_ptr), E_OBJ, "analog_map is E_OBJ");
	is_int(analog_dcm_read(buf, sizeof(buf)), E_OBJ, "dcm read is E_OBJ");
	is_int(analog_set_pins(0, LMS_DCM_FLOAT), E_OBJ, "dcm write is E_OBJ");
}

int main(void)
{
	tap_plan(37);
	ok(analog_test_run_in(user_body, 7, 5000, 1), "user-domain body ran to its end");
	is_int(lx_module_param_set("d_analog", "dcm_start_ms", "-5"), E_OK, "dcm_start_ms = -5");
	ok(analog_test_run(unloaded_body, 8, 1000), "the body ran with d_analog refusing to load");
	return tap_done();
}
