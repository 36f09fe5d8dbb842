/*
 * test_boot.c — configuration checking at boot: every kind of bad row is a
 * boot error naming the configuration, table and row, with the right E_*
 * code; includes are merged (IDs unique across them); ATT_INI runs in
 * order with the CPU locked; a good config boots after a failed one.
 */
#define _POSIX_C_SOURCE 200809L
#include <unistd.h>

#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

static void task_fn(intptr_t x)
{
}

static void handler(intptr_t x)
{
}

static ER_UINT svc_fn(intptr_t a, intptr_t b, intptr_t c, intptr_t d, intptr_t e, ID dom)
{
	return 0;
}

static int ini_order[4];
static int nini;
static bool_t ini_locked, ini_ctx;

static void ini_fn(intptr_t x)
{
	ini_order[nini++] = (int)x;
	ini_locked = sns_loc();
	ini_ctx = sns_ctx();
}

static uint8_t mem_area[64];

#define CFG1(field, arr) { .name = "bad", .field = RTOS_TABLE(arr) }

/* Each bad table, alone in a config named "bad". */
static const struct rtos_task_cfg tsk_id[] = { { 33, 0, 0, task_fn, 5, 1024, TDOM_KERNEL, "big" } };
static const struct rtos_task_cfg tsk_dup[] = {
	{ 3, 0, 0, task_fn, 5, 1024, TDOM_KERNEL, "one" },
	{ 3, 0, 0, task_fn, 5, 1024, TDOM_KERNEL, "two" },
};
static const struct rtos_task_cfg tsk_pri[] = { { 1, 0, 0, task_fn, 17, 1024, TDOM_KERNEL, "pri" } };
static const struct rtos_task_cfg tsk_fn[] = { { 1, 0, 0, NULL, 5, 1024, TDOM_KERNEL, "nofn" } };
static const struct rtos_task_cfg tsk_stk[] = { { 1, 0, 0, task_fn, 5, 0, TDOM_KERNEL, "nostack" } };
static const struct rtos_task_cfg tsk_atr[] = { { 1, 0x40, 0, task_fn, 5, 1024, TDOM_KERNEL, "atr" } };
static const struct rtos_task_cfg tsk_dom[] = { { 1, 0, 0, task_fn, 5, 1024, 9, "dom" } };
static const struct rtos_sem_cfg sem_max[] = { { 1, 0, 3, 2, "over" } };
static const struct rtos_sem_cfg sem_zero[] = { { 1, 0, 0, 0, "zero" } };
static const struct rtos_sem_cfg sem_id[] = { { 0, 0, 0, 1, "id0" } };
static const struct rtos_flg_cfg flg_atr[] = { { 1, 0x80, 0, "atr" } };
static const struct rtos_cyc_cfg cyc_tim[] = { { 1, 0, 0, handler, 0, 0, "zero" } };
static const struct rtos_cyc_cfg cyc_fn[] = { { 1, 0, 0, NULL, 5, 0, "nofn" } };
static const struct rtos_alm_cfg alm_id[] = { { 17, 0, 0, handler, "big" } };
static const struct rtos_int_cfg int_pri[] = { { 30, TA_ENAINT, TMIN_INTPRI - 1 } };
static const struct rtos_int_cfg int_no[] = { { 128, TA_ENAINT, -2 } };
static const struct rtos_int_cfg int_dup[] = { { 30, TA_ENAINT, -2 }, { 30, TA_ENAINT, -3 } };
static const struct rtos_int_cfg int_tick[] = { { INTNO_TICK, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isr_unc[] = { { 0, 0, 31, handler, 1 } };
static const struct rtos_svc_cfg svc_dup[] = { { 4, svc_fn, 256 }, { 4, svc_fn, 256 } };
static const struct rtos_svc_cfg svc_rng[] = { { 0, svc_fn, 256 } };
static const struct rtos_mem_cfg mem_dom[] = { { 0, mem_area, sizeof(mem_area), TPM_READ, "m" } };
static const struct rtos_ini_cfg ini_null[] = { { NULL, 0 } };

struct bad_case {
	struct rtos_cfg cfg;
	ER ercd;
	const char *needle;
};

static const struct bad_case cases[] = {
	{ CFG1(tasks, tsk_id), E_ID, "CRE_TSK[0] \"big\": tskid 33 out of range" },
	{ CFG1(tasks, tsk_dup), E_OBJ, "CRE_TSK[1] \"two\": tskid 3 already used" },
	{ CFG1(tasks, tsk_pri), E_PAR, "itskpri 17 out of range" },
	{ CFG1(tasks, tsk_fn), E_PAR, "NULL task function" },
	{ CFG1(tasks, tsk_stk), E_PAR, "zero stack size" },
	{ CFG1(tasks, tsk_atr), E_RSATR, "unknown attribute bits 0x40" },
	{ CFG1(tasks, tsk_dom), E_ID, "domid 9" },
	{ CFG1(sems, sem_max), E_PAR, "isemcnt 3 > maxsem 2" },
	{ CFG1(sems, sem_zero), E_PAR, "maxsem is 0" },
	{ CFG1(sems, sem_id), E_ID, "semid 0 out of range" },
	{ CFG1(flgs, flg_atr), E_RSATR, "CRE_FLG[0]" },
	{ CFG1(cycs, cyc_tim), E_PAR, "cyctim 0" },
	{ CFG1(cycs, cyc_fn), E_PAR, "NULL handler" },
	{ CFG1(alms, alm_id), E_ID, "almid 17" },
	{ CFG1(ints, int_pri), E_PAR, "intpri -32" },
	{ CFG1(ints, int_no), E_PAR, "intno 128" },
	{ CFG1(ints, int_dup), E_OBJ, "intno 30 configured twice" },
	{ CFG1(ints, int_tick), E_OBJ, "kernel tick" },
	{ CFG1(isrs, isr_unc), E_OBJ, "intno 31 has no CFG_INT" },
	{ CFG1(svcs, svc_dup), E_OBJ, "fncd 4 already defined by config \"bad\"" },
	{ CFG1(svcs, svc_rng), E_PAR, "fncd 0 out of range" },
	{ CFG1(mems, mem_dom), E_ID, "ATT_MEM[0]" },
	{ CFG1(inis, ini_null), E_PAR, "ATT_INI[0]" },
};

/* Includes: a library fragment with its own task near the top of the ID range. */
static const struct rtos_task_cfg lib_tasks[] = { { 32, TA_ACT, 0, task_fn, 2, 1024, TDOM_KERNEL, "worker" } };
static const struct rtos_int_cfg lib_ints[] = { { 40, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg lib_isrs[] = {
	{ 0, 0, INTNO_TICK, handler, 1 },     /* ISR on the tick: allowed without CFG_INT */
	{ 0, 0, 41, handler, 1 },             /* line configured by the application */
};
static const struct rtos_ini_cfg lib_inis[] = { { ini_fn, 2 }, { ini_fn, 3 } };
static const struct rtos_cfg lib_cfg = {
	.name = "lib", .tasks = RTOS_TABLE(lib_tasks), .ints = RTOS_TABLE(lib_ints),
	.isrs = RTOS_TABLE(lib_isrs), .inis = RTOS_TABLE(lib_inis),
};
static const struct rtos_cfg *const app_includes[] = { &lib_cfg, NULL };
static const struct rtos_task_cfg app_tasks[] = { { 1, TA_ACT, 0, task_fn, 5, 1024, TDOM_KERNEL, "app" } };
static const struct rtos_int_cfg app_ints[] = { { 41, TA_NULL, -3 } };
static const struct rtos_ini_cfg app_inis[] = { { ini_fn, 1 } };
static const struct rtos_cfg app_cfg = {
	.name = "app", .tasks = RTOS_TABLE(app_tasks), .ints = RTOS_TABLE(app_ints),
	.inis = RTOS_TABLE(app_inis), .includes = app_includes,
};

/* The same ID in the application and the library. */
static const struct rtos_task_cfg clash_tasks[] = { { 32, 0, 0, task_fn, 5, 1024, TDOM_KERNEL, "mine" } };
static const struct rtos_cfg clash_cfg = { .name = "clash", .tasks = RTOS_TABLE(clash_tasks), .includes = app_includes };

/* An include cycle. */
static const struct rtos_cfg cyc_b;
static const struct rtos_cfg *const cyc_a_inc[] = { &cyc_b, NULL };
static const struct rtos_cfg cyc_a = { .name = "cyc_a", .includes = cyc_a_inc };
static const struct rtos_cfg *const cyc_b_inc[] = { &cyc_a, NULL };
static const struct rtos_cfg cyc_b = { .name = "cyc_b", .includes = cyc_b_inc };

int main(void)
{
	size_t n = sizeof(cases) / sizeof(cases[0]);
	size_t bad_code = 0, bad_text = 0;
	int saved_stderr;
	FILE *devnull;

	tap_plan(11);
	/* The boot errors are expected here: keep them off stderr (stdout still shows them). */
	fflush(stderr);
	saved_stderr = dup(2);
	devnull = fopen("/dev/null", "w");
	if (devnull != NULL)
		dup2(fileno(devnull), 2);
	for (size_t i = 0; i < n; i++) {
		ER ercd = rtos_host_boot(&cases[i].cfg);

		if (ercd != cases[i].ercd) {
			bad_code++;
			tap_diag("case %zu: got %d, expected %d", i, (int)ercd, (int)cases[i].ercd);
		}
		if (strstr(rtos_host_boot_error(), cases[i].needle) == NULL ||
		    strstr(rtos_host_boot_error(), "config \"bad\"") == NULL) {
			bad_text++;
			tap_diag("case %zu: message \"%s\" lacks \"%s\"", i, rtos_host_boot_error(), cases[i].needle);
		}
	}
	fflush(stderr);
	dup2(saved_stderr, 2);
	is_int(bad_code, 0, "each of %zu bad rows fails the boot with its E_* code", n);
	is_int(bad_text, 0, "each boot error names the config, the table, the row and the problem");

	is_int(rtos_host_boot(&app_cfg), E_OK, "an application including a library fragment boots");
	is_str(rtos_host_boot_error(), "", "no boot error after a good boot");
	ok(nini == 3 && ini_order[0] == 1 && ini_order[1] == 2 && ini_order[2] == 3,
	   "ATT_INI routines run once, application first, then the included fragment, in table order");
	ok(ini_locked && ini_ctx, "ATT_INI runs in non-task context with the CPU locked");
	ok(rtos_host_irq_priority(40) == -2 && rtos_host_irq_priority(41) == -3 && !rtos_host_irq_enabled(41),
	   "lines from both configs are configured (TA_ENAINT honoured)");
	rtos_host_run_for(1000000);
	is_u64(rtos_host_now(), 1000000, "the merged system runs");

	if (devnull != NULL)
		dup2(fileno(devnull), 2);
	is_int(rtos_host_boot(&clash_cfg), E_OBJ, "an ID used by the application and the library is E_OBJ");
	ok(strstr(rtos_host_boot_error(), "config \"lib\" CRE_TSK[0] \"worker\": tskid 32 already used by \"mine\" (config \"clash\")") != NULL,
	   "the clash names both rows and configs");
	tap_diag("%s", rtos_host_boot_error());
	ok(rtos_host_boot(&cyc_a) == E_OBJ && strstr(rtos_host_boot_error(), "included twice") != NULL,
	   "an include cycle is a boot error");
	fflush(stderr);
	dup2(saved_stderr, 2);
	if (devnull != NULL)
		fclose(devnull);
	rtos_host_shutdown();
	return tap_done();
}
