/*
 * test_reboot.c — the whole stack booted twice in one process behaves like
 * a power cycle: ev3api_cfg (linux_compat, every driver through its hack)
 * on the simulated brick runs the same application (a regulated motor and a
 * UART colour sensor) in both boots with identical results and a
 * byte-identical trace; at each shutdown every module_exit runs (the
 * worker, task context), which leaves no device registered, no interrupt
 * line enabled, no memory region claimed, no GPIO requested, no kmalloc
 * memory in use, no module loaded and no bug report; each boot runs every
 * module_init again.
 */
#include <stdlib.h>
#include <string.h>
#include "api_test.h"
#include <linux/module.h>
#include <linux_compat/devfs.h>
#include <linux_compat/heap.h>
#include <linux_compat/irq.h>
#include <linux_compat/machine.h>
#include <linux/ioport.h>
#include <mach/gpio.h>
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
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
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
	r->config_ercd = ev3lx_motor_config(EV3_PORT_A, LARGE_MOTOR);
	if (r->config_ercd == E_OK)
		r->config_ercd = ev3lx_sensor_config(EV3_PORT_1, COLOR_SENSOR);
	r->speed_ercd = ev3lx_motor_set_speed(EV3_PORT_A, 40);
	r->reflect_ercd = ev3lx_color_sensor_get_reflect(EV3_PORT_1, &pct);
	r->reflect = pct;
	r->reflect_ms = at_now_ms();
	dly_tsk(500);
	ev3lx_motor_get_speed(EV3_PORT_A, &speed);
	ev3lx_motor_get_counts(EV3_PORT_A, &counts);
	r->speed = speed;
	r->counts = counts;
	ev3lx_motor_stop(EV3_PORT_A, false);
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

/*
 * The application's own termination routine: the application is registered
 * first, so it is terminated last, after linux_compat's unload, with the
 * kernel still up - the moment to look at the interrupt lines.
 */
static unsigned lines_left_enabled;

#define COUNT_ENABLED_LINE(intno, isr, exinf) \
	if (rtos_host_irq_enabled(intno)) { tap_diag("line %u still enabled", (unsigned)(intno)); lines_left_enabled++; }

static void app_ter(intptr_t exinf)
{
	(void)exinf;
	lines_left_enabled = 0;
	LX_IRQ_LINES(COUNT_ENABLED_LINE)
}

/* at_run with the termination routine in the application's configuration. */
static bool run_app(void (*attach_fn)(void), void (*body_fn)(void), uint64_t seed, unsigned max_s)
{
	static const struct rtos_task_cfg task = {
		AT_TASK_ID, TA_ACT, 0, at_task, 8, AT_STACK, AT_DOMAIN, "app",
	};
	static const struct rtos_ter_cfg ters[] = { { app_ter, 0 } };
	static const struct rtos_cfg *const includes[] = { &ev3api_cfg, NULL };
	static const struct rtos_cfg cfg = {
		.name = "reboot_test", .tasks = &task, .ntasks = 1, .ters = RTOS_TABLE(ters),
		.includes = includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = seed };

	at_body = body_fn;
	at_done = false;
	lines_left_enabled = ~0U;
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		return false;
	}
	attach_fn();
	for (unsigned i = 0; !at_done && i < max_s * 10U; i++)
		hs_sim_run_for(100 * AT_MS);
	hs_sim_shutdown();
	return at_done;
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
	const struct resource *claim;
	unsigned i, registered = 0, loaded = 0, claims = 0, pins = 0;

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
	is_int(lines_left_enabled, 0, "boot %u: every Linux interrupt line is disabled (free_irq)", n);
	for (claim = iomem_resource.child; claim; claim = claim->sibling) {
		tap_diag("region %s still claimed", claim->name);
		claims++;
	}
	is_int(claims, 0, "boot %u: every memory region is released", n);
	for (i = 0; i < DAVINCI_N_GPIO; i++)
		if (gpio_label(i)) {
			tap_diag("GPIO %u still requested by %s", i, gpio_label(i));
			pins++;
		}
	is_int(pins, 0, "boot %u: every GPIO is freed", n);
	is_int(rtos_host_bug_count(), 0, "boot %u: no bug reported, unload included", n);
}

int main(void)
{
	const char *shutdown;

	tap_plan(BOOTS * 12 + 3);
	rtos_host_trace_set_sink(trace_sink, NULL);
	for (boot = 0; boot < BOOTS; boot++) {
		struct run_result *r = &results[boot];

		ok(run_app(attach, body, 7, 30), "boot %u: the application finished", boot + 1);
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
