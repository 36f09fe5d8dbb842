/*
 * test_reboot.c — the whole stack booted twice in one process behaves like
 * a power cycle: ev3api_cfg (linux_compat, every driver through its hack)
 * on the simulated brick runs the same application (a regulated motor and a
 * UART colour sensor) in both boots with identical results and a
 * byte-identical trace; at each shutdown every module_exit runs (the
 * worker, task context), which leaves no device registered, no kmalloc
 * memory in use, no module loaded and no bug report; each boot runs every
 * module_init again.
 */
#include <stdlib.h>
#include <string.h>
#include "api/api_test.h"
#include <linux/module.h>
#include <linux_compat/devfs.h>
#include <linux_compat/heap.h>
#include "lms_pwm.h"
#include "lms_analog.h"
#include "lms_uart.h"
#include "lms_ui.h"

#define BOOTS 2

static const struct uart_sensor_scene scene = { .reflect_pct = 42 };

struct run_result {
	ER config_ercd, speed_ercd, reflect_ercd;
	int speed;
	int32_t counts;
	uint8_t reflect;
	uint64_t reflect_ms;      /* when the first reflected-light value arrived */
	int pwm_state;            /* d_pwm's module state while the application runs */
};

static struct run_result results[BOOTS];
static unsigned boot;

/* The trace of each boot, kept whole so that a difference can be shown. */
static struct {
	char *text;
	size_t len, cap;
	unsigned lines;
} traces[BOOTS];

static void trace_sink(const char *line, void *ctx)
{
	size_t n = strlen(line) + 1;
	(void)ctx;

	if (traces[boot].len + n > traces[boot].cap) {
		size_t cap = traces[boot].cap ? traces[boot].cap * 2 : 1 << 20;

		while (cap < traces[boot].len + n)
			cap *= 2;
		traces[boot].text = realloc(traces[boot].text, cap);
		if (!traces[boot].text)
			tap_bail_out("out of memory for the trace");
		traces[boot].cap = cap;
	}
	memcpy(traces[boot].text + traces[boot].len, line, n - 1);
	traces[boot].text[traces[boot].len + n - 1] = '\n';
	traces[boot].len += n;
	traces[boot].lines++;
}

static void attach(void)
{
	ev3_attach_motor(0, EV3_MOTOR_LARGE, NULL);
	ev3_attach_uart_sensor(0, 29, NULL);
	ev3_set_scene(0, &scene);
}

/* The application: out-parameters on its stack (its domain), results copied out. */
static void body(void)
{
	struct run_result *r = &results[boot];
	int speed = 0;
	int32_t counts = 0;
	uint8_t pct = 0;

	r->pwm_state = (int)lx_module_find("d_pwm")->state;
	r->config_ercd = ev3_motor_config(EV3_PORT_A, LARGE_MOTOR);
	if (r->config_ercd == E_OK)
		r->config_ercd = ev3_sensor_config(EV3_PORT_1, COLOR_SENSOR);
	r->speed_ercd = ev3_motor_set_speed(EV3_PORT_A, 40);
	r->reflect_ercd = ev3_color_sensor_get_reflect(EV3_PORT_1, &pct);
	r->reflect = pct;
	r->reflect_ms = at_now_ms();
	dly_tsk(500);
	ev3_motor_get_speed(EV3_PORT_A, &speed);
	ev3_motor_get_counts(EV3_PORT_A, &counts);
	r->speed = speed;
	r->counts = counts;
	ev3_motor_stop(EV3_PORT_A, false);
}

/* The first line where the two traces differ, for the diagnostic. */
static void show_first_difference(void)
{
	const char *a = traces[0].text, *b = traces[1].text;
	size_t i = 0, line_start = 0;
	size_t n = traces[0].len < traces[1].len ? traces[0].len : traces[1].len;

	while (i < n && a[i] == b[i]) {
		if (a[i] == '\n')
			line_start = i + 1;
		i++;
	}
	tap_diag("boot 1: %.120s", a + line_start);
	tap_diag("boot 2: %.120s", b + line_start);
}

/* After a shutdown: nothing of the drivers is left. */
static void check_unloaded(unsigned n)
{
	static const char *const devices[] = {
		LMS_PWM_DEVICE_NAME, LMS_MOTOR_DEVICE_NAME, LMS_ANALOG_DEVICE_NAME,
		LMS_DCM_DEVICE_NAME, LMS_UART_DEVICE_NAME, LMS_UI_DEVICE_NAME,
	};
	static const char *const modules[] = { "d_pwm", "d_analog", "d_uart", "d_ui" };
	struct lx_heap_stats stats;
	unsigned i, registered = 0, loaded = 0;

	lx_heap_get_stats(&stats);
	is_int(stats.in_use, 0, "boot %u: the kmalloc pool is empty after the unload", n);
	for (i = 0; i < ARRAY_SIZE(devices); i++)
		if (lx_dev_exists(devices[i])) {
			tap_diag("/dev/%s is still registered", devices[i]);
			registered++;
		}
	is_int(registered, 0, "boot %u: no device is registered any more", n);
	for (i = 0; i < ARRAY_SIZE(modules); i++) {
		struct module *mod = lx_module_find(modules[i]);

		if (!mod || mod->state != MODULE_STATE_UNFORMED) {
			tap_diag("module %s: %s", modules[i], mod ? "still loaded" : "not linked");
			loaded++;
		}
	}
	is_int(loaded, 0, "boot %u: every driver module is unloaded", n);
	is_int(rtos_host_bug_count(), 0, "boot %u: no bug reported, unload included", n);
}

int main(void)
{
	const char *shutdown;

	tap_plan(BOOTS * 9 + 3);
	rtos_host_trace_set_sink(trace_sink, NULL);
	for (boot = 0; boot < BOOTS; boot++) {
		struct run_result *r = &results[boot];

		ok(at_run(attach, body, 7, 30), "boot %u: the application finished", boot + 1);
		is_int(r->pwm_state, MODULE_STATE_LIVE, "boot %u: d_pwm was loaded again", boot + 1);
		ok(r->config_ercd == E_OK && r->speed_ercd == E_OK && r->reflect_ercd == E_OK,
		   "boot %u: config, set_speed and reflect succeed (%d %d %d)", boot + 1,
		   r->config_ercd, r->speed_ercd, r->reflect_ercd);
		is_int(r->reflect, 42, "boot %u: the sensor's reflected light", boot + 1);
		in_range(r->speed, 36, 44, "boot %u: regulated speed about 40", boot + 1);
		check_unloaded(boot + 1);
	}
	rtos_host_trace_set_sink(NULL, NULL);

	ok(memcmp(&results[0], &results[1], sizeof(results[0])) == 0,
	   "identical results (speed %d/%d, counts %d/%d, first value at %llu/%llu ms)",
	   results[0].speed, results[1].speed, (int)results[0].counts, (int)results[1].counts,
	   (unsigned long long)results[0].reflect_ms, (unsigned long long)results[1].reflect_ms);
	shutdown = strstr(traces[0].text, "kernel shutdown");
	ok(traces[0].lines > 1000 && shutdown && strstr(shutdown, "kernel dispatch lx_worker"),
	   "the trace covers the run and the shutdown, where the worker runs the exits (%u lines)",
	   traces[0].lines);
	ok(traces[0].len == traces[1].len && memcmp(traces[0].text, traces[1].text, traces[0].len) == 0,
	   "byte-identical traces across the reboot (%u and %u lines)", traces[0].lines, traces[1].lines);
	if (traces[0].len != traces[1].len || memcmp(traces[0].text, traces[1].text, traces[0].len) != 0)
		show_first_difference();
	free(traces[0].text);
	free(traces[1].text);
	return tap_done();
}
