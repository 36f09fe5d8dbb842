/*
 * test_fncd_ranges.c — function codes as modules own them: every hack's
 * configuration declares its range (FIRST/COUNT in its header), the ranges
 * are disjoint and inside 1..TNUM_FNCD, a new module takes a free range and
 * boots beside all of them with no edit to theirs, and boot rejects a range
 * that overlaps another module's naming both, a DEF_SVC row outside its own
 * range, a range beyond TNUM_FNCD, and a code defined twice naming its owner.
 * By default every range is clear of the codes EV3RT's own drivers and
 * system services define, 1..42 (ev3rt-git/ev3rt-hrp2's .cfg files), so the
 * library configures beside them.
 */
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "tap.h"
#include "kernel.h"
#include "rtos_cfg.h"
#include "rtos_host.h"
#include "pwm_hack.h"
#include "analog_hack.h"
#include "uart_hack.h"
#include "ui_hack.h"
#include "power_hack.h"
#include "sound_hack.h"
#include "iic_hack.h"

/* The highest function code EV3RT's own configuration defines. */
#define EV3RT_FNCD_LAST 42

/* A new module, as a user adds one: its own header's range, nothing else touched. */
#define NEWDRV_FN_FIRST (EV3LX_FNCD_BASE + 127)
#define NEWDRV_FN_COUNT 8
#define NEWDRV_FN_ECHO  (NEWDRV_FN_FIRST + 0)

static ER_UINT svc_echo(intptr_t a, intptr_t b, intptr_t c, intptr_t d, intptr_t e, ID cdmid)
{
	(void)b, (void)c, (void)d, (void)e, (void)cdmid;
	return (ER_UINT)a;
}

static const struct rtos_svc_cfg newdrv_svcs[] = { { NEWDRV_FN_ECHO, svc_echo, 1024 } };
static const struct rtos_cfg newdrv_cfg = {
	.name = "newdrv", .svcs = RTOS_TABLE(newdrv_svcs),
	.svc_first = NEWDRV_FN_FIRST, .svc_count = NEWDRV_FN_COUNT,
};

static const struct rtos_cfg *const modules[] = {
	&pwm_hack_cfg, &analog_hack_cfg, &uart_hack_cfg, &ui_hack_cfg, &power_hack_cfg, &sound_hack_cfg,
	&iic_hack_cfg,
	&newdrv_cfg, NULL,
};

static ER_UINT echo_result;

static void app_task(intptr_t exinf)
{
	(void)exinf;
	echo_result = cal_svc(NEWDRV_FN_ECHO, 4242, 0, 0, 0, 0);
}

static const struct rtos_task_cfg app_tasks[] = { { 1, TA_ACT, 0, app_task, 5, 4096, TDOM_KERNEL, "app" } };
static const struct rtos_cfg app_cfg = { .name = "app", .tasks = RTOS_TABLE(app_tasks), .includes = modules };

/* Bad modules, each booted beside the project's. */
#define OVERLAP_FIRST (ANALOG_FN_FIRST + 4)
static const struct rtos_svc_cfg overlap_svcs[] = { { OVERLAP_FIRST, svc_echo, 1024 } };
static const struct rtos_cfg overlap_cfg = {
	.name = "overlapper", .svcs = RTOS_TABLE(overlap_svcs), .svc_first = OVERLAP_FIRST, .svc_count = 4,
};
#define OUTSIDE_ROW (NEWDRV_FN_FIRST + 10)
static const struct rtos_svc_cfg outside_svcs[] = { { OUTSIDE_ROW, svc_echo, 1024 } };
static const struct rtos_cfg outside_cfg = {
	.name = "outsider", .svcs = RTOS_TABLE(outside_svcs), .svc_first = NEWDRV_FN_FIRST, .svc_count = 8,
};
static const struct rtos_cfg beyond_cfg = { .name = "beyond", .svc_first = TNUM_FNCD, .svc_count = 2 };
static const struct rtos_svc_cfg squatter_svcs[] = { { PWM_FN_COMMAND, svc_echo, 1024 } };
static const struct rtos_cfg squatter_cfg = { .name = "squatter", .svcs = RTOS_TABLE(squatter_svcs) };

/* Boots the project's hack configurations plus bad; returns the boot's code. */
static ER boot_with(const struct rtos_cfg *bad)
{
	static const struct rtos_cfg *includes[9];
	static struct rtos_cfg cfg = { .name = "app" };
	unsigned int i;

	for (i = 0; i < 6; i++)
		includes[i] = modules[i];
	includes[6] = bad;
	includes[7] = NULL;
	cfg.includes = includes;
	return rtos_host_boot(&cfg);
}

int main(void)
{
	unsigned int i, j;
	bool disjoint = true, inside = true, clear_of_ev3rt = true;
	char want[64];
	int saved_stderr;
	FILE *devnull;

	tap_plan(14);
	for (i = 0; modules[i] != NULL; i++) {
		const struct rtos_cfg *a = modules[i];

		if (a->svc_count == 0 || a->svc_first < 1 || a->svc_first + (FN)a->svc_count - 1 > TNUM_FNCD)
			inside = false;
		if (a != &newdrv_cfg && a->svc_first <= EV3RT_FNCD_LAST)
			clear_of_ev3rt = false;
		for (j = 0; j < i; j++) {
			const struct rtos_cfg *b = modules[j];

			if (a->svc_first < b->svc_first + (FN)b->svc_count && b->svc_first < a->svc_first + (FN)a->svc_count)
				disjoint = false;
		}
	}
	ok(inside, "every module declares its range, inside 1..TNUM_FNCD (%d)", TNUM_FNCD);
	ok(disjoint, "the ranges are disjoint");
	ok(clear_of_ev3rt, "the library's ranges start at %d, clear of EV3RT's codes 1..%d",
	   EV3LX_FNCD_BASE, EV3RT_FNCD_LAST);
	is_int(PWM_FN_COMMAND, PWM_FN_FIRST, "a module's codes count from its FIRST");

	is_int(rtos_host_boot(&app_cfg), E_OK, "a new module at %d..%d boots beside the six, none edited",
	       NEWDRV_FN_FIRST, NEWDRV_FN_FIRST + NEWDRV_FN_COUNT - 1);
	rtos_host_run_for(1000000);
	is_int((int)echo_result, 4242, "and its service call works");
	rtos_host_shutdown();

	fflush(stderr);
	saved_stderr = dup(2);
	devnull = fopen("/dev/null", "w");
	if (devnull != NULL)
		dup2(fileno(devnull), 2);
	is_int(boot_with(&overlap_cfg), E_OBJ, "a range overlapping another module's fails the boot");
	(void)snprintf(want, sizeof(want), "%d..%d", ANALOG_FN_FIRST, ANALOG_FN_LAST);
	ok(strstr(rtos_host_boot_error(), "\"overlapper\"") && strstr(rtos_host_boot_error(), "\"analog_hack\"") &&
	   strstr(rtos_host_boot_error(), want),
	   "naming both modules and ranges: %s", rtos_host_boot_error());
	is_int(boot_with(&outside_cfg), E_PAR, "a DEF_SVC row outside its module's range fails");
	(void)snprintf(want, sizeof(want), "fncd %d outside", OUTSIDE_ROW);
	ok(strstr(rtos_host_boot_error(), want) != NULL, "%s", rtos_host_boot_error());
	is_int(boot_with(&beyond_cfg), E_PAR, "a range beyond TNUM_FNCD fails");
	ok(strstr(rtos_host_boot_error(), "TNUM_FNCD") != NULL, "%s", rtos_host_boot_error());
	is_int(boot_with(&squatter_cfg), E_OBJ, "a code another module defined fails");
	ok(strstr(rtos_host_boot_error(), "already defined by config \"pwm_hack\"") != NULL, "naming the owner: %s",
	   rtos_host_boot_error());
	fflush(stderr);
	dup2(saved_stderr, 2);
	return tap_done();
}
