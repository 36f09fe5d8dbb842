/*
 * test_pwm_protocol.c — d_pwm's entry points against bad input, and the
 * protocol details around them: unknown opcodes, short and oversized
 * buffers for every opcode, bad port masks and values, bad pointers from a
 * kernel-domain and from a user-domain task; the "R T " busy report,
 * /dev/lms_motor's write and mmap, polarity, PROGRAM_STOP/START, SET_TYPE,
 * RESET and OUTPUT_POWER.  Every rejected call must leave the driver as it
 * was (and the sanitizer build watches the memory).
 */
#include <linux/fcntl.h>
#include <linux/mm.h>
#include <linux_compat/devfs.h>

#include "pwm_test.h"

#define USER_TASK_ID 2
#define USER_DOMAIN  1

/* Opcode, minimum and maximum length, and a valid command of maximum length. */
struct opcode_case {
	uint8_t op;
	uint8_t min, max;
	uint8_t valid[LMS_PWM_CMD_MAX];
};

static const struct opcode_case opcodes[] = {
	{ LMS_PWM_PROGRAM_STOP, 1, 1, { LMS_PWM_PROGRAM_STOP } },
	{ LMS_PWM_PROGRAM_START, 1, 1, { LMS_PWM_PROGRAM_START } },
	{ LMS_PWM_OUTPUT_SET_TYPE, 5, 5, { LMS_PWM_OUTPUT_SET_TYPE, 7, 8, 7, 7 } },
	{ LMS_PWM_OUTPUT_RESET, 2, 2, { LMS_PWM_OUTPUT_RESET, 0x0F } },
	{ LMS_PWM_OUTPUT_STOP, 3, 3, { LMS_PWM_OUTPUT_STOP, 0x0F, 0 } },
	{ LMS_PWM_OUTPUT_POWER, 3, 3, { LMS_PWM_OUTPUT_POWER, 0x01, 0 } },
	{ LMS_PWM_OUTPUT_SPEED, 3, 3, { LMS_PWM_OUTPUT_SPEED, 0x01, 0 } },
	{ LMS_PWM_OUTPUT_START, 2, 2, { LMS_PWM_OUTPUT_START, 0x01 } },
	{ LMS_PWM_OUTPUT_POLARITY, 3, 3, { LMS_PWM_OUTPUT_POLARITY, 0x01, 1 } },
	{ LMS_PWM_OUTPUT_STEP_POWER, 17, 20, { LMS_PWM_OUTPUT_STEP_POWER, 0x01, 10, 0, 0, 0, 0, 0, 1 } },
	{ LMS_PWM_OUTPUT_TIME_POWER, 17, 20, { LMS_PWM_OUTPUT_TIME_POWER, 0x01, 10, 0, 0, 0, 0, 0, 1 } },
	{ LMS_PWM_OUTPUT_STEP_SPEED, 17, 20, { LMS_PWM_OUTPUT_STEP_SPEED, 0x01, 10, 0, 0, 0, 0, 0, 1 } },
	{ LMS_PWM_OUTPUT_TIME_SPEED, 17, 20, { LMS_PWM_OUTPUT_TIME_SPEED, 0x01, 10, 0, 0, 0, 0, 0, 1 } },
	{ LMS_PWM_OUTPUT_STEP_SYNC, 13, 16, { LMS_PWM_OUTPUT_STEP_SYNC, 0x03, 10, 0, 0, 0, 0, 0, 1 } },
	{ LMS_PWM_OUTPUT_TIME_SYNC, 13, 16, { LMS_PWM_OUTPUT_TIME_SYNC, 0x03, 10, 0, 0, 0, 0, 0, 1 } },
	{ LMS_PWM_OUTPUT_CLR_COUNT, 2, 2, { LMS_PWM_OUTPUT_CLR_COUNT, 0x0F } },
	{ LMS_PWM_OUTPUT_GET_TYPE, 1, 20, { LMS_PWM_OUTPUT_GET_TYPE } },
	{ LMS_PWM_OUTPUT_READ, 1, 20, { LMS_PWM_OUTPUT_READ } },
	{ LMS_PWM_OUTPUT_TEST, 1, 20, { LMS_PWM_OUTPUT_TEST } },
	{ LMS_PWM_OUTPUT_READY, 1, 20, { LMS_PWM_OUTPUT_READY } },
	{ LMS_PWM_OUTPUT_POSITION, 1, 20, { LMS_PWM_OUTPUT_POSITION } },
	{ LMS_PWM_OUTPUT_PRG_STOP, 1, 20, { LMS_PWM_OUTPUT_PRG_STOP } },
	{ LMS_PWM_OUTPUT_GET_COUNT, 1, 20, { LMS_PWM_OUTPUT_GET_COUNT } },
};
#define NOPCODES (sizeof(opcodes) / sizeof(opcodes[0]))

/* Bytes no check may touch: a command buffer with guard bytes on both sides. */
static uint8_t guarded[4 + LMS_PWM_CMD_MAX + 8 + 4];

static void stop_all(void)
{
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x0F, 0);
}

static void status(char out[5])
{
	memset(out, 0, 5);
	pwm_read_status(out, 4);
}

/* Every opcode: too short and too long are E_PAR, its full length is accepted. */
static void test_lengths(void)
{
	int bad_short = 0, bad_long = 0, good = 0;

	for (unsigned i = 0; i < NOPCODES; i++) {
		const struct opcode_case *c = &opcodes[i];
		uint8_t *b = guarded + 4;

		memset(guarded, 0xA5, sizeof(guarded));
		memcpy(b, c->valid, c->max);
		if (pwm_command(b, c->min - 1U) == E_PAR)
			bad_short++;
		else
			tap_diag("opcode 0x%02X: %u bytes not rejected", c->op, c->min - 1U);
		if (pwm_command(b, c->max + 1U) == E_PAR)
			bad_long++;
		else
			tap_diag("opcode 0x%02X: %u bytes not rejected", c->op, c->max + 1U);
		if (pwm_command(b, c->max) == E_OK && pwm_command(b, c->min) == E_OK)
			good++;
		else
			tap_diag("opcode 0x%02X: valid command rejected", c->op);
		stop_all();
	}
	is_int(bad_short, NOPCODES, "every opcode rejects a short buffer with E_PAR");
	is_int(bad_long, NOPCODES, "every opcode rejects an oversized buffer with E_PAR");
	is_int(good, NOPCODES, "every opcode accepts its minimum and full length");
	ok(guarded[0] == 0xA5 && guarded[3] == 0xA5 && guarded[sizeof(guarded) - 1] == 0xA5,
	   "guard bytes untouched");
	ok(pwm_command(guarded + 4, 0) == E_PAR, "length 0: E_PAR");
	ok(pwm_command(guarded + 4, LMS_PWM_CMD_MAX + 1) == E_PAR, "length 21: E_PAR");
	ok(pwm_command(guarded + 4, (uint_t)-1) == E_PAR, "length -1: E_PAR");
	ok(pwm_command(guarded + 4, 1U << 30) == E_PAR, "length 1 GiB: E_PAR");
}

static void test_opcodes(void)
{
	static const uint8_t unknown[] = { 0x00, 0x01, 0x04, 0x9F, 0xAC - 0x10, 0xB5, 0xC0, 0xFF };
	int rejected = 0;

	for (unsigned i = 0; i < sizeof(unknown); i++) {
		uint8_t b[3] = { unknown[i], 0x01, 0 };

		if (pwm_command(b, 3) == E_PAR && pwm_command(b, 1) == E_PAR)
			rejected++;
	}
	is_int(rejected, sizeof(unknown), "unknown opcodes: E_PAR");
}

static void test_masks_and_values(void)
{
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x00, 10) == E_PAR, "SPEED with no port: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x10, 10) == E_PAR, "SPEED port bit 4: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POWER, 0xFF, 10) == E_PAR, "POWER mask 0xFF: E_PAR");
	ok(pwm_cmd(LMS_PWM_OUTPUT_START, 0x80) == E_PAR, "START mask 0x80: E_PAR");
	ok(pwm_cmd(LMS_PWM_OUTPUT_RESET, 0) == E_PAR, "RESET mask 0: E_PAR");
	ok(pwm_cmd(LMS_PWM_OUTPUT_CLR_COUNT, 0x30) == E_PAR, "CLR_COUNT mask 0x30: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x20, 1) == E_PAR, "STOP mask 0x20: E_PAR");
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 0x00, 10, 0, 10, 0, 0) == E_PAR, "STEP with no port: E_PAR");
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_TIME_POWER, 0x40, 10, 0, 10, 0, 0) == E_PAR, "TIME mask 0x40: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, 0x01, 10, 0, 10, 0) == E_PAR, "SYNC with one port: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, 0x07, 10, 0, 10, 0) == E_PAR, "SYNC with three ports: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_TIME_SYNC, 0x30, 10, 0, 10, 0) == E_PAR, "SYNC on ports 4, 5: E_PAR");

	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x01, 101) == E_PAR, "SPEED 101: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x01, -101) == E_PAR, "SPEED -101: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POWER, 0x01, 127) == E_PAR, "POWER 127: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POWER, 0x01, -128) == E_PAR, "POWER -128: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x01, 2) == E_PAR, "STOP brake 2: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POLARITY, 0x01, 2) == E_PAR, "POLARITY 2: E_PAR");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POLARITY, 0x01, -2) == E_PAR, "POLARITY -2: E_PAR");
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 0x01, 101, 0, 10, 0, 0) == E_PAR, "STEP speed 101: E_PAR");
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_STEP_POWER, 0x01, 10, 0, 10, 0, 2) == E_PAR, "STEP brake 2: E_PAR");
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_TIME_SPEED, 0x01, 10, 0, -10, 0, 0) == E_PAR, "TIME -10 ms: E_PAR");
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 0x01, 10, INT32_MIN, 0, 0, 0) == E_PAR, "STEP INT32_MIN: E_PAR");
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 0x01, 10, INT32_MAX, 1, 0, 0) == E_PAR,
	   "STEP lengths summing past INT32_MAX: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, 0x03, 10, 201, 10, 0) == E_PAR, "SYNC turn 201: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, 0x03, 10, -201, 10, 0) == E_PAR, "SYNC turn -201: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, 0x03, -101, 0, 10, 0) == E_PAR, "SYNC speed -101: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_TIME_SYNC, 0x03, 10, 0, -5, 0) == E_PAR, "TIME_SYNC -5 ms: E_PAR");
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, 0x03, 10, 0, 10, 3) == E_PAR, "SYNC brake 3: E_PAR");
	ok(pwm_set_busy(0x10) == E_PAR, "set_busy mask 0x10: E_PAR");
}

static void test_pointers(void)
{
	uint8_t start[2] = { LMS_PWM_OUTPUT_START, 0x01 };
	struct lms_motor_data md;

	ok(pwm_command(NULL, 3) == E_MACV, "command from NULL: E_MACV");
	ok(pwm_command2(start, 2, NULL, 2) == E_MACV, "second command from NULL: E_MACV");
	ok(pwm_command2(NULL, 2, start, 2) == E_MACV, "first command from NULL: E_MACV");
	ok(pwm_read_status(NULL, 4) == E_MACV, "status into NULL: E_MACV");
	ok(pwm_read_status((char *)start, (uint_t)-1) == E_PAR, "status of length -1: E_PAR");
	ok(pwm_motor_data(4, &md) == E_ID, "motor data of port 4: E_ID");
	ok(pwm_motor_data((uint_t)-1, &md) == E_ID, "motor data of port -1: E_ID");
	ok(pwm_motor_data(0, NULL) == E_MACV, "motor data into NULL: E_MACV");
	ok(pwm_motor_map(NULL) == E_MACV, "motor map into NULL: E_MACV");
}

static void test_status_and_map(void)
{
	char st[5];
	const struct lms_motor_data *map = NULL;
	struct lms_motor_data md;

	status(st);
	ok(strcmp(st, "0 0 ") == 0, "status \"%s\": nothing busy", st);
	ok(pwm_set_busy(0x05) == E_OK, "/dev/lms_motor write 0x05");
	status(st);
	ok(strcmp(st, "5 5 ") == 0, "status \"%s\" after it", st);
	ok(pwm_read_status(st, 2) == 2 && st[0] == '5' && st[1] == ' ', "a 2-byte read gets 2 bytes");
	ok(pwm_busy() == 5, "busy mask 5");
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x05, 0) == E_OK, "STOP clears the busy bits");
	status(st);
	ok(strcmp(st, "0 0 ") == 0, "status \"%s\"", st);
	ok(pwm_cmd_step(LMS_PWM_OUTPUT_TIME_POWER, 0x0A, 30, 0, 100, 0, 0) == E_OK, "TIME_POWER on B, D");
	status(st);
	ok(strcmp(st, "A A ") == 0, "status \"%s\" while running", st);
	dly_tsk(150);
	status(st);
	ok(strcmp(st, "0 0 ") == 0, "status \"%s\" after the time", st);

	ok(pwm_motor_map(&map) == E_OK && map != NULL, "MOTORDATA mapped");
	ok(pwm_motor_data(3, &md) == E_OK && map && memcmp(&md, &map[3], sizeof(md)) == 0,
	   "copy and map agree");
	ok(sizeof(struct lms_motor_data) == 12 && LMS_MOTOR_DATA_SIZE == 48, "MOTORDATA is 4 x 12 bytes");
}

/* The file operations as Linux calls them, without the service calls' own checks. */
static void test_file_operations(void)
{
	struct file *pwm = NULL, *motor = NULL;
	uint8_t buf[32] = { LMS_PWM_OUTPUT_START, 0x01 };
	void *addr = NULL;

	ok(lx_dev_open("/dev/lms_pwm", O_RDWR, &pwm) == 0, "open /dev/lms_pwm");
	ok(lx_dev_open("/dev/lms_motor", O_RDWR, &motor) == 0, "open /dev/lms_motor");
	is_int(lx_dev_write(pwm, (const char __user *)buf, 0, NULL), -EINVAL, "write of 0 bytes: -EINVAL");
	is_int(lx_dev_write(pwm, (const char __user *)buf, 21, NULL), -EINVAL, "write of 21 bytes: -EINVAL");
	is_int(lx_dev_write(pwm, (const char __user *)buf, 2, NULL), 2, "a good write returns its count");
	is_int(lx_dev_write(pwm, NULL, 2, NULL), -EFAULT, "write from NULL: -EFAULT");
	is_int(lx_dev_read(pwm, (char __user *)buf, 32, NULL), 4, "read returns the 4 status bytes");
	is_int(lx_dev_write(motor, (const char __user *)buf, 2, NULL), -EINVAL, "lms_motor write of 2 bytes: -EINVAL");
	is_int(lx_dev_read(motor, (char __user *)buf, 32, NULL), 0, "lms_motor read: 0");
	ok(lx_dev_mmap(motor, PAGE_SIZE + 1, &addr) != 0, "mapping more than a page is refused");
	ok(lx_dev_mmap(motor, LMS_MOTOR_DATA_SIZE, &addr) == 0 && addr != NULL, "mapping MOTORDATA works");
	ok(lx_dev_mmap(pwm, 48, &addr) != 0, "lms_pwm has no mmap");
	lx_dev_close(pwm);
	lx_dev_close(motor);
	stop_all();
}

static void test_semantics(void)
{
	double a0, t0;
	struct lms_motor_data md;
	struct hbridge_drive d;

	/* polarity */
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POLARITY, 0x01, -1) == E_OK, "POLARITY -1 on A");
	a0 = motor_angle(0);
	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x01, 40);
	pwm_cmd(LMS_PWM_OUTPUT_START, 0x01);
	dly_tsk(300);
	ok(motor_angle(0) < a0 - 50, "SPEED 40 turns it backwards (%.0f deg)", motor_angle(0) - a0);
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POLARITY, 0x01, 0) == E_OK, "POLARITY 0 toggles");
	dly_tsk(300);
	ok(motor_dps(0) > 300, "the running motor turns forwards at once (%.0f deg/s)", motor_dps(0));

	/* PROGRAM_STOP: braked ports brake 100 ms, then coast; PROGRAM_START restores polarity */
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x01, 1);
	pwm_cmd_value(LMS_PWM_OUTPUT_POLARITY, 0x02, -1);
	dly_tsk(200);
	ok(pwm_cmd(LMS_PWM_PROGRAM_STOP, 0) == E_PAR, "PROGRAM_STOP takes no arguments");
	{
		uint8_t b = LMS_PWM_PROGRAM_STOP;

		ok(pwm_command(&b, 1) == E_OK, "PROGRAM_STOP");
	}
	t0 = now_ms();
	dly_tsk(50);
	d = hs_motor_drive(ev3_output_motor(0));
	ok(d.brake > 0.99, "braked port still braking at +50 ms");
	dly_tsk(100);
	d = hs_motor_drive(ev3_output_motor(0));
	ok(d.brake == 0 && d.fwd == 0 && d.rev == 0, "coasting at +%.0f ms", now_ms() - t0);
	a0 = motor_angle(1);
	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x02, 40);
	pwm_cmd(LMS_PWM_OUTPUT_START, 0x02);
	dly_tsk(300);
	ok(motor_angle(1) > a0 + 50, "polarity back to +1 after PROGRAM_STOP/START");
	stop_all();

	/* OUTPUT_POWER: unregulated, then SET_TYPE to a non-motor type coasts */
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_POWER, 0x04, 60) == E_OK &&
	   pwm_cmd(LMS_PWM_OUTPUT_START, 0x04) == E_OK, "POWER 60 on C");
	dly_tsk(400);
	ok(motor_dps(2) > 400, "runs unregulated (%.0f deg/s)", motor_dps(2));
	md = motor_data_of(2);
	ok(md.tacho_counts == 0 && md.tacho_sensor > 100, "TachoCounts 0 while unlimited, sensor %d",
	   md.tacho_sensor);
	ok(pwm_set_types(7, 8, LMS_PWM_TYPE_NONE, 7) == E_OK, "SET_TYPE C := none");
	dly_tsk(4);
	d = hs_motor_drive(ev3_output_motor(2));
	ok(d.fwd == 0 && d.rev == 0 && d.brake == 0, "C coasts");
	ok(motor_data_of(2).tacho_sensor <= 2, "and its counters restart (%d)", motor_data_of(2).tacho_sensor);
	pwm_set_types(7, 8, 7, 7);
	dly_tsk(1000);

	/* RESET zeroes TachoCounts, not TachoSensor */
	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 0x08, 30, 0, 0, 0, 0);   /* forever */
	dly_tsk(300);
	md = motor_data_of(3);
	ok(md.tacho_counts > 50 && md.tacho_sensor >= md.tacho_counts, "a step command counts (%d of %d)",
	   md.tacho_counts, md.tacho_sensor);
	ok(pwm_cmd(LMS_PWM_OUTPUT_RESET, 0x08) == E_OK, "RESET D");
	dly_tsk(2);
	md = motor_data_of(3);
	ok(md.tacho_counts < 5 && md.tacho_sensor > 50, "TachoCounts %d restarted, TachoSensor %d kept",
	   md.tacho_counts, md.tacho_sensor);
	stop_all();
}

/* PWM_FN_RUN: the values in registers, the two commands run by the driver's handlers. */
static void test_run(void)
{
	double a0;
	struct hbridge_drive d;

	ok(pwm_run(LMS_PWM_OUTPUT_STOP, 0, 10) == E_PAR, "run with STOP: E_PAR (SPEED or POWER only)");
	ok(pwm_run(LMS_PWM_OUTPUT_START, 0, 10) == E_PAR, "run with START: E_PAR");
	ok(pwm_run(LMS_PWM_OUTPUT_SPEED, 4, 10) == E_ID, "run port 4: E_ID");
	ok(pwm_run(LMS_PWM_OUTPUT_SPEED, (uint_t)-1, 10) == E_ID, "run port -1: E_ID");
	ok(pwm_run(LMS_PWM_OUTPUT_SPEED, 0, 101) == E_PAR, "run SPEED 101: E_PAR (the driver's check)");
	ok(pwm_run(LMS_PWM_OUTPUT_POWER, 0, -101) == E_PAR, "run POWER -101: E_PAR");
	ok(pwm_run(LMS_PWM_OUTPUT_SPEED, 0, 256 + 10) == E_PAR, "run SPEED 266 (10 as a byte): E_PAR");
	ok(pwm_run(LMS_PWM_OUTPUT_SPEED, 0, -128) == E_PAR, "run SPEED -128: E_PAR");
	dly_tsk(100);
	ok(fabs(motor_dps(0)) < 1, "no rejected run moved motor A");

	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x02, 1);
	dly_tsk(100);
	a0 = motor_angle(1);
	ok(pwm_run(LMS_PWM_OUTPUT_SPEED, 1, -40) == E_OK, "run SPEED -40 on the braked port B");
	dly_tsk(400);
	ok(motor_angle(1) < a0 - 50 && fabs(motor_dps(1) - PWM_MEDIUM_DPS(-40)) < 0.2 * PWM_MEDIUM_DPS(40),
	   "B runs regulated backwards (%.0f deg/s)", motor_dps(1));
	ok(pwm_run(LMS_PWM_OUTPUT_POWER, 1, 30) == E_OK, "run POWER 30 on the running port B");
	dly_tsk(400);
	d = hs_motor_drive(ev3_output_motor(1));
	ok(d.fwd > 0.3 && d.fwd < 0.6 && motor_dps(1) > 0, "B driven unregulated at POWER 30 (duty %.2f)", d.fwd);
	stop_all();
}

static bool user_done;

static void body(void)
{
	test_lengths();
	test_opcodes();
	test_masks_and_values();
	test_pointers();
	ok(pwm_busy() == 0, "no rejected call left a port busy");
	ok(fabs(motor_dps(0)) < 1 && fabs(motor_dps(1)) < 1, "no rejected call moved a motor");
	test_status_and_map();
	test_file_operations();
	test_semantics();
	test_run();
	/* Then the same calls from a task of a user domain. */
	act_tsk(USER_TASK_ID);
	while (!user_done)
		dly_tsk(10);
}

/* ---- a user-domain task: pointers outside its memory ---- */

static uint8_t user_area[64] __attribute__((aligned(16)));
static uint8_t kernel_area[64];

static void user_body(void)
{
	struct lms_motor_data md;
	const struct lms_motor_data *map;
	uint8_t local[3] = { LMS_PWM_OUTPUT_SPEED, 0x01, 10 };

	user_area[0] = LMS_PWM_OUTPUT_START;
	user_area[1] = 0x01;
	kernel_area[0] = LMS_PWM_OUTPUT_START;
	kernel_area[1] = 0x01;
	ok(pwm_command(local, 3) == E_OK, "user task: command from its stack");
	ok(pwm_command(user_area, 2) == E_OK, "user task: command from its memory");
	ok(pwm_command(kernel_area, 2) == E_MACV, "user task: command from kernel memory: E_MACV");
	user_area[62] = LMS_PWM_OUTPUT_STOP;
	user_area[63] = 0x01;
	ok(pwm_command(user_area + 62, 3) == E_MACV, "user task: command straddling its memory's end: E_MACV");
	ok(pwm_read_status((char *)kernel_area, 4) == E_MACV, "user task: status into kernel memory: E_MACV");
	ok(pwm_read_status((char *)user_area, 4) == 4, "user task: status into its memory");
	ok(pwm_motor_data(0, (struct lms_motor_data *)kernel_area) == E_MACV,
	   "user task: motor data into kernel memory: E_MACV");
	ok(pwm_motor_data(0, &md) == E_OK, "user task: motor data onto its stack");
	ok(pwm_motor_map((const struct lms_motor_data **)kernel_area) == E_MACV,
	   "user task: map address into kernel memory: E_MACV");
	ok(pwm_motor_map(&map) == E_OK, "user task: map address onto its stack");
	ok(kernel_area[2] == 0 && kernel_area[8] == 0, "kernel memory untouched");
	ok(pwm_run(LMS_PWM_OUTPUT_SPEED, 0, 10) == E_OK, "user task: run (no memory to probe)");
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x0F, 0);
}

static void user_task(intptr_t exinf)
{
	(void)exinf;
	user_body();
	user_done = true;
}

int main(void)
{
	const int motors[4] = { HS_MOTOR_LARGE, HS_MOTOR_MEDIUM, HS_MOTOR_LARGE, HS_MOTOR_LARGE };
	const struct rtos_task_cfg tasks[] = {
		{ USER_TASK_ID, TA_NULL, 0, user_task, 8, PWM_TEST_STACK, USER_DOMAIN, "pwm_user" },
	};
	const struct rtos_mem_cfg mems[] = {
		{ USER_DOMAIN, user_area, sizeof(user_area), TPM_READ | TPM_WRITE, "user_area" },
	};
	const struct rtos_cfg user_cfg = {
		.name = "pwm_user", .tasks = RTOS_TABLE(tasks), .mems = RTOS_TABLE(mems),
	};

	tap_plan(119);
	ok(pwm_test_run_in(body, motors, TDOM_KERNEL, &user_cfg), "test bodies ran to their end");
	return tap_done();
}
