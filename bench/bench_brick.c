/*
 * bench_brick.c — the benchmarks' simulated brick (bench_brick.h).
 */
#include "bench_brick.h"
#include "lms_pwm.h"
#include "lms_uart.h"
#include "rtos_host.h"
#include "ev3api_cfg.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"

#define BENCH_TASK_ID   1
#define BENCH_DOMAIN    1
#define BENCH_STACK     (64 * 1024)
#define MS_NS           1000000ULL

/* How long prepare waits for the four handshakes (the slowest sensor needs
 * about 2.1 s after power-up), polling every POLL_MS. */
#define STREAM_TIMEOUT_MS  5000U
#define POLL_MS            10U

static void (*bench_body)(void);
static bool bench_done;
static enum bench_brick_kind bench_kind;

static const struct uart_sensor_scene color_scene = {
	.reflect_pct = 37, .ambient_pct = 12, .color = 5, .rgb = { 300, 200, 100 },
};
static const struct uart_sensor_scene gyro_scene = { .rate_dps = 90.0 };
static const struct uart_sensor_scene us_scene = { .distance_mm = 500 };
static const struct uart_sensor_scene ir_scene = { .distance_mm = 350 };

/* The application task: the benchmark body, then the end flag. */
static void bench_task(intptr_t exinf)
{
	(void)exinf;
	bench_body();
	bench_done = true;
}

/* Everything plugged in at power-on. */
static void attach_devices(void)
{
	if (bench_kind == BENCH_BRICK_LIGHT) {
		ev3_attach_motor(BENCH_MOTOR_PORT, HS_MOTOR_LARGE, NULL);
		ev3_attach_uart_sensor(BENCH_SENSOR_PORT, UART_SENSOR_TYPE_GYRO, NULL);
		ev3_set_scene(BENCH_SENSOR_PORT, &gyro_scene);
		return;
	}
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(1, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(2, HS_MOTOR_MEDIUM, NULL);
	ev3_attach_motor(3, HS_MOTOR_MEDIUM, NULL);
	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL);
	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, NULL);
	ev3_attach_uart_sensor(2, UART_SENSOR_TYPE_ULTRASONIC, NULL);
	ev3_attach_uart_sensor(3, UART_SENSOR_TYPE_IR, NULL);
	ev3_set_scene(0, &color_scene);
	ev3_set_scene(1, &gyro_scene);
	ev3_set_scene(2, &us_scene);
	ev3_set_scene(3, &ir_scene);
}

bool bench_brick_run(enum bench_brick_kind kind, void (*body)(void), uint64_t seed,
		     unsigned max_virtual_s)
{
	static const struct rtos_task_cfg task = {
		BENCH_TASK_ID, TA_ACT, 0, bench_task, 8, BENCH_STACK, BENCH_DOMAIN, "bench",
	};
	static const struct rtos_cfg *const includes[] = { &ev3api_cfg, NULL };
	static const struct rtos_cfg cfg = {
		.name = "bench", .tasks = &task, .ntasks = 1, .includes = includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = seed };
	/* The calls' CPU time in virtual time is simulation: the bench measures the
	 * code itself, and a call that let virtual time pass took a slow path. */
	static const struct rtos_host_cpu_cost free_calls = { 0, 0, false, 0 };
	struct rtos_host_cpu_cost cost;
	bool done;

	rtos_host_get_cpu_cost(&cost);
	rtos_host_set_cpu_cost(&free_calls);
	bench_body = body;
	bench_done = false;
	bench_kind = kind;
	if (hs_sim_boot(&scn) != E_OK) {
		rtos_host_set_cpu_cost(&cost);
		return false;
	}
	attach_devices();
	for (unsigned i = 0; !bench_done && i < max_virtual_s * 10U; i++)
		hs_sim_run_for(100 * MS_NS);
	hs_sim_shutdown();
	done = bench_done;
	rtos_host_set_cpu_cost(&cost);
	return done;
}

/* Waits until the sensor on port delivers a sample through the fast path. */
static ER wait_streaming(sensor_port_t port)
{
	uint8_t raw[LMS_UART_DATA_SIZE];
	ER ercd = E_TMOUT;

	for (unsigned waited = 0; waited < STREAM_TIMEOUT_MS; waited += POLL_MS) {
		ercd = ev3lx_uart_sensor_get_raw(port, raw, sizeof(raw));
		if (ercd == E_OK)
			return E_OK;
		dly_tsk(POLL_MS);
	}
	return ercd;
}

ER bench_brick_prepare(void)
{
	static const motor_type_t motors[TNUM_MOTOR_PORT] = {
		LARGE_MOTOR, LARGE_MOTOR, MEDIUM_MOTOR, MEDIUM_MOTOR,
	};
	static const sensor_type_t sensors[TNUM_SENSOR_PORT] = {
		COLOR_SENSOR, GYRO_SENSOR, ULTRASONIC_SENSOR, INFRARED_SENSOR,
	};
	bool light = bench_kind == BENCH_BRICK_LIGHT;
	ER ercd;

	for (unsigned p = 0; p < TNUM_MOTOR_PORT; p++) {
		if (light && p != BENCH_MOTOR_PORT)
			continue;
		ercd = ev3lx_motor_config((motor_port_t)p, motors[p]);
		if (ercd == E_OK)
			ercd = ev3lx_motor_set_speed((motor_port_t)p, 40);
		if (ercd != E_OK)
			return ercd;
	}
	for (unsigned p = 0; p < TNUM_SENSOR_PORT; p++) {
		if (light && p != BENCH_SENSOR_PORT)
			continue;
		ercd = ev3lx_sensor_config((sensor_port_t)p, sensors[p]);
		if (ercd != E_OK)
			return ercd;
	}
	for (unsigned p = 0; p < TNUM_SENSOR_PORT; p++) {
		if (light && p != BENCH_SENSOR_PORT)
			continue;
		ercd = wait_streaming((sensor_port_t)p);
		if (ercd != E_OK)
			return ercd;
	}
	return E_OK;
}

int bench_speed_for(unsigned i)
{
	return (i & 1U) ? 50 : 60;
}

void bench_speed_command(int speed, uint8_t *cmd, unsigned *len)
{
	cmd[0] = LMS_PWM_OUTPUT_SPEED;
	cmd[1] = (uint8_t)(1U << (unsigned)BENCH_MOTOR_PORT);
	cmd[2] = (uint8_t)(int8_t)speed;
	*len = 3;
}
