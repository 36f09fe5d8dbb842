/*
 * motor_app.c — `ev3sim motor`: one motor run through the EV3 API (apps.h).
 */
#include <stdlib.h>
#include <string.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "rtos_host.h"
#include "ev3api_cfg.h"
#include "t_syslog.h"
#include "host_sim/scenario.h"
#include "ev3sim/apps.h"

#define MOTOR_TSKID  1
#define APP_DOMAIN   1

static struct {
	struct ev3sim_motor_opts o;
	FILE *out;
	bool done;
	int32_t counts;
	int speed;
	unsigned api_errors;
} run;

static ER check(ER ercd)
{
	if (ercd != E_OK) {
		if (run.api_errors++ < 3)
			fprintf(run.out, "# API call failed: %d at %.3f s\n", (int)ercd, rtos_host_now() * 1e-9);
	}
	return ercd;
}

/* The application: start the motor, print a row every every_ms, stop it. */
static void motor_task(intptr_t exinf)
{
	motor_port_t port = (motor_port_t)run.o.port;
	uint64_t rows = (uint64_t)(run.o.seconds * 1000.0) / run.o.every_ms;
	SYSTIM t0 = 0, now = 0;
	int32_t counts = 0;         /* out-parameters live on the task's stack (its domain) */
	int speed = 0;

	(void)exinf;
	check(ev3lx_motor_config(port, run.o.kind == HS_MOTOR_MEDIUM ? MEDIUM_MOTOR : LARGE_MOTOR));
	fprintf(run.out, "# motor %c (%s), %s %d for %g s\n# t_s  speed_pct  counts_deg\n",
		'A' + run.o.port, run.o.kind == HS_MOTOR_MEDIUM ? "medium" : "large",
		run.o.power_mode ? "power" : "speed", run.o.value, run.o.seconds);
	get_tim(&t0);
	if (run.o.power_mode)
		check(ev3lx_motor_set_power(port, run.o.value));
	else
		check(ev3lx_motor_set_speed(port, run.o.value));
	for (uint64_t k = 1; k <= rows; k++) {
		SYSTIM target = t0 + (SYSTIM)(k * run.o.every_ms);

		get_tim(&now);
		if (target > now)
			dly_tsk((RELTIM)(target - now));
		check(ev3lx_motor_get_speed(port, &speed));
		check(ev3lx_motor_get_counts(port, &counts));
		fprintf(run.out, "%7.3f  %4d  %8ld\n", (double)(k * run.o.every_ms) / 1000.0, speed,
			(long)counts);
	}
	get_tim(&now);
	if (now < t0 + (SYSTIM)(run.o.seconds * 1000.0))
		dly_tsk((RELTIM)(t0 + (SYSTIM)(run.o.seconds * 1000.0) - now));
	check(ev3lx_motor_get_speed(port, &speed));
	check(ev3lx_motor_get_counts(port, &counts));
	check(ev3lx_motor_stop(port, true));
	run.speed = speed;
	run.counts = counts;
	run.done = true;
}

static void motor_boot(intptr_t exinf)
{
	(void)exinf;
	ev3sim_quiet_console();
}

static const struct rtos_task_cfg motor_tasks[] = {
	{ MOTOR_TSKID, TA_ACT, 0, motor_task, 8, 16 * 1024, APP_DOMAIN, "motor" },
};
static const struct rtos_ini_cfg motor_inis[] = { { motor_boot, 0 } };
static const struct rtos_cfg *const motor_includes[] = { &ev3api_cfg, NULL };
static const struct rtos_cfg motor_cfg = {
	.name = "ev3sim_motor",
	.tasks = RTOS_TABLE(motor_tasks),
	.inis = RTOS_TABLE(motor_inis),
	.includes = motor_includes,
};

ER ev3sim_motor_app(const struct ev3sim_motor_opts *o, FILE *out, char *err, size_t errlen)
{
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &motor_cfg, .board = &board };
	uint64_t limit;
	double wall0, wall;

	if (o->port > 3 || o->value < -100 || o->value > 100 || !(o->seconds > 0) ||
	    o->seconds > 3600 || o->every_ms == 0 ||
	    (o->kind != HS_MOTOR_LARGE && o->kind != HS_MOTOR_MEDIUM)) {
		snprintf(err, errlen, "bad motor options");
		return E_PAR;
	}
	memset(&run, 0, sizeof(run));
	run.o = *o;
	run.out = out;
	scn.seed = o->seed;
	scn.vcd_path = o->trace_path;
	wall0 = ev3sim_wall_seconds();
	if (hs_sim_boot(&scn) != E_OK) {
		snprintf(err, errlen, "boot failed: %s", rtos_host_boot_error());
		return E_SYS;
	}
	if (ev3_attach_motor(o->port, o->kind, NULL) != E_OK) {
		hs_sim_shutdown();
		snprintf(err, errlen, "cannot attach the motor");
		return E_SYS;
	}
	limit = (uint64_t)(o->seconds * 1e9) + 2000000000ULL;
	while (!run.done && rtos_host_now() < limit && !rtos_host_exited())
		hs_sim_run_for(10000000ULL);
	wall = ev3sim_wall_seconds() - wall0;
	fprintf(out, "port=%c kind=%s mode=%s value=%d seconds=%g counts=%ld final_speed_pct=%d "
		"mean_speed_dps=%.1f api_errors=%u bugs=%u sim_speed=%.0fx\n",
		'A' + o->port, o->kind == HS_MOTOR_MEDIUM ? "medium" : "large",
		o->power_mode ? "power" : "speed", o->value, o->seconds, (long)run.counts, run.speed,
		run.counts / o->seconds, run.api_errors, rtos_host_bug_count(),
		wall > 0 ? rtos_host_now() * 1e-9 / wall : 0.0);
	if (hs_sim_shutdown() != E_OK) {
		snprintf(err, errlen, "cannot write %s completely", o->trace_path);
		return E_SYS;
	}
	if (!run.done) {
		snprintf(err, errlen, "the application did not finish");
		return E_SYS;
	}
	return E_OK;
}
