/*
 * test_kernel_timeline.c — the VCD's task and interrupt timeline
 * (host_sim/src/core/kernel_timeline.c): a known configuration's task
 * switches appear in the file in the order the kernel makes them, each
 * task's state follows its service calls, a cyclic handler and the tick's
 * line show while they run; a run observed computes what a run without a
 * VCD does.
 *
 * The configuration: HIGH (priority 2) and LOW (5) start at boot.  HIGH
 * sleeps; LOW wakes it (HIGH runs at once), HIGH exits, LOW delays 3 ms and
 * exits; a cyclic handler runs every 2 ms.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tap.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define HIGH_ID 1
#define LOW_ID  2
#define CYC_ID  1

/* VCD codes of a task's state (host_sim/src/core/core_parts.h). */
enum { DORMANT, READY, RUNNING, WAITING, SUSPENDED, WAITING_SUSPENDED };

static unsigned cyc_runs;
static uint64_t low_end_ns;

static void high_task(intptr_t x)
{
	(void)x;
	(void)slp_tsk();
}

static void low_task(intptr_t x)
{
	(void)x;
	(void)wup_tsk(HIGH_ID);
	(void)dly_tsk(3);
	low_end_ns = rtos_host_now();
}

static void cyc_handler(intptr_t x)
{
	(void)x;
	cyc_runs++;
}

static const struct rtos_task_cfg tasks[] = {
	{ HIGH_ID, TA_ACT, 0, high_task, 2, 4096, TDOM_KERNEL, "HIGH" },
	{ LOW_ID, TA_ACT, 0, low_task, 5, 4096, TDOM_KERNEL, "LOW task" },
};
static const struct rtos_cyc_cfg cycs[] = { { CYC_ID, TA_STA, 0, cyc_handler, 2, 1, "CYC" } };
static const struct rtos_cfg cfg = { .name = "timeline", .tasks = RTOS_TABLE(tasks), .cycs = RTOS_TABLE(cycs) };

/* One value change of a signal: time and value (x and z, its value before it is first set, are left out). */
struct change { uint64_t t; long long v; };

/* The changes of scope.name in the VCD text (at most max); -1 if it is not declared. */
static int vcd_changes(const char *vcd, const char *scope, const char *name, struct change *out, int max)
{
	char id[8] = "", cur_scope[64] = "", line[256];
	const char *p = vcd;
	uint64_t t = 0;
	int n = 0;
	bool body = false;

	while (*p != '\0') {
		size_t len = strcspn(p, "\n");
		char var_id[8], var_name[64];
		unsigned width;

		snprintf(line, sizeof(line), "%.*s", (int)len, p);
		p += len + (p[len] == '\n');
		if (!body) {
			if (sscanf(line, "$scope module %63s $end", cur_scope) == 1)
				continue;
			if (sscanf(line, "$var %*s %u %7s %63s $end", &width, var_id, var_name) == 3 &&
			    strcmp(cur_scope, scope) == 0 && strcmp(var_name, name) == 0)
				snprintf(id, sizeof(id), "%s", var_id);
			if (strncmp(line, "$enddefinitions", 15) == 0) {
				if (id[0] == '\0')
					return -1;
				body = true;
			}
			continue;
		}
		if (line[0] == '#') {
			t = strtoull(line + 1, NULL, 10);
			continue;
		}
		if (line[0] == 'b') {
			char *sp = strchr(line, ' ');

			if (sp == NULL || strcmp(sp + 1, id) != 0)
				continue;
			if (n < max && line[1] != 'x' && line[1] != 'z')
				out[n++] = (struct change){ t, strtoll(line + 1, NULL, 2) };
		} else if ((line[0] == '0' || line[0] == '1') && strcmp(line + 1, id) == 0 && n < max) {
			out[n++] = (struct change){ t, line[0] - '0' };
		}
	}
	return id[0] != '\0' ? n : -1;
}

/* Whole file into a malloc'd string (NULL if unreadable). */
static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	char *buf;
	long len;

	if (f == NULL)
		return NULL;
	fseek(f, 0, SEEK_END);
	len = ftell(f);
	rewind(f);
	buf = malloc((size_t)len + 1);
	if (buf != NULL && fread(buf, 1, (size_t)len, f) != (size_t)len) {
		free(buf);
		buf = NULL;
	}
	if (buf != NULL)
		buf[len] = '\0';
	fclose(f);
	return buf;
}

/* Runs the configuration for 10 ms, with a VCD at vcd unless NULL. */
static bool run(const char *vcd)
{
	struct hs_scenario scn = { .rtos = &cfg, .seed = 1, .vcd_path = vcd };

	cyc_runs = 0;
	low_end_ns = 0;
	if (hs_sim_boot(&scn) != E_OK)
		return false;
	hs_sim_run_for(10000000);
	return hs_sim_shutdown() == E_OK;
}

/* True if the first n changes' values are want[0..n). */
static bool values_are(const struct change *c, int n, const long long *want, int nwant)
{
	if (n != nwant)
		return false;
	for (int i = 0; i < n; i++)
		if (c[i].v != want[i])
			return false;
	return true;
}

/* The changes' values as text, for a diagnostic. */
static const char *values_text(const struct change *c, int n)
{
	static char buf[512];
	size_t k = 0;

	buf[0] = '\0';
	for (int i = 0; i < n && k + 24 < sizeof(buf); i++)
		k += (size_t)snprintf(buf + k, sizeof(buf) - k, "%s%lld@%llu", i ? " " : "", c[i].v,
				      (unsigned long long)c[i].t);
	return buf;
}

int main(void)
{
	char path[] = "/tmp/ev3lx_timeline_XXXXXX";
	int fd = mkstemp(path);
	struct change c[64];
	unsigned cyc_plain;
	uint64_t end_plain;
	char *vcd;
	int n;

	tap_plan(9);
	ok(fd >= 0 && run(NULL), "the configuration runs without a VCD");
	cyc_plain = cyc_runs;
	end_plain = low_end_ns;
	ok(fd >= 0 && run(path), "and with one");
	ok(cyc_runs == cyc_plain && low_end_ns == end_plain && low_end_ns > 0,
	   "observed, it computes what it does unobserved (LOW ends at %llu ns both times, %u cyclic runs)",
	   (unsigned long long)low_end_ns, cyc_runs);
	vcd = slurp(path);
	if (vcd == NULL)
		tap_bail_out("cannot read the VCD");

	{
		/* boot: HIGH first, it sleeps; LOW wakes it; HIGH exits; LOW delays; idle; LOW's exit */
		static const long long want[] = { 0, HIGH_ID, LOW_ID, HIGH_ID, LOW_ID, 0, LOW_ID, 0 };

		n = vcd_changes(vcd, "rtos", "running", c, 64);
		ok(values_are(c, n, want, 8), "rtos.running: HIGH, LOW, HIGH (woken), LOW, idle, LOW, idle (%s)",
		   values_text(c, n));
	}
	{
		static const long long want[] = { READY, RUNNING, WAITING, READY, RUNNING, DORMANT };

		n = vcd_changes(vcd, "task", "HIGH", c, 64);
		ok(values_are(c, n, want, 6), "task.HIGH: ready, running, waiting (slp_tsk), ready (woken), running, "
		   "dormant (%s)",
		   values_text(c, n));
	}
	{
		static const long long want[] = { READY, RUNNING, READY, RUNNING, WAITING, READY, RUNNING, DORMANT };

		n = vcd_changes(vcd, "task", "LOW_task", c, 64);
		ok(values_are(c, n, want, 8),
		   "task.LOW_task (a name's space made '_'): ready, running, preempted, running, waiting (dly_tsk), "
		   "ready, running, dormant (%s)", values_text(c, n));
		ok(n == 8 && c[4].t < c[5].t && c[5].t - c[4].t >= 3000000 && c[7].t == low_end_ns,
		   "its wait lasts the 3 ms delay and it ends when the task's own clock says (%llu ns)",
		   (unsigned long long)low_end_ns);
	}
	n = vcd_changes(vcd, "isr", "cyclic_1", c, 64);
	ok(n >= 2 * (int)cyc_runs - 1 && n > 0 && c[0].v == 1 && c[1].v == 0,
	   "isr.cyclic_1 is high while the cyclic handler runs (%d changes, %u runs)", n, cyc_runs);
	n = vcd_changes(vcd, "isr", "line_21", c, 64);
	ok(n >= 2 && c[0].v == 1 && c[1].v == 0, "isr.line_21 (the tick) rises and falls with its service (%d changes)", n);
	free(vcd);
	unlink(path);
	return tap_done();
}
