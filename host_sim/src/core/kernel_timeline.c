/*
 * kernel_timeline.c — the RTOS's task and interrupt timeline in the VCD.
 * Host only.
 *
 * While a VCD is open, the host kernel's scheduler observer
 * (rtos_host_set_sched_observer) turns its dispatches, task state changes
 * and handler entries and exits into signals:
 *   rtos.running      the running task's ID (0: the CPU is idle)
 *   task.<NAME>       each task's state: HS_TASK_DORMANT .. HS_TASK_WAITING_SUSPENDED
 *                     (core_parts.h), declared when it first changes
 *   isr.line_<N>      high while interrupt line N's service runs (nested lines
 *                     overlap), isr.cyclic_<ID> and isr.alarm_<ID> while a cyclic or
 *                     alarm handler runs
 * Without a VCD no observer is installed: the kernel pays one test per event.
 */
#include <stdio.h>
#include <string.h>

#include "kernel.h"
#include "rtos_cfg.h"
#include "rtos_host.h"
#include "host_sim/trace.h"
#include "core_parts.h"

/* Handler signals kept per kind: interrupt lines up to this number, cyclic and alarm IDs below it. */
#define TIMELINE_MAX_IDS 256U

static struct {
	struct hs_signal *running;
	struct hs_signal *task[TNUM_TSKID + 1];
	STAT state[TNUM_TSKID + 1];          /* the kernel's state of each task (TTS_RDY while it runs) */
	ID running_id;
	struct hs_signal *handler[3][TIMELINE_MAX_IDS];
} tl;

/* The VCD code of task id's state. */
static unsigned task_code(ID id)
{
	switch (tl.state[id]) {
	case TTS_RDY: return id == tl.running_id ? HS_TASK_RUNNING : HS_TASK_READY;
	case TTS_WAI: return HS_TASK_WAITING;
	case TTS_SUS: return HS_TASK_SUSPENDED;
	case TTS_WAS: return HS_TASK_WAITING_SUSPENDED;
	default:      return HS_TASK_DORMANT;
	}
}

/* The task's signal, declared at its first use: its name with the characters a
 * VCD identifier may not hold made '_', its ID added if another task has it. */
static struct hs_signal *task_signal(ID id, const char *name)
{
	char sig[64];
	size_t n = 0;

	if (tl.task[id] != NULL)
		return tl.task[id];
	for (const char *c = name != NULL ? name : ""; *c != '\0' && n + 1 < sizeof(sig) - 8; c++, n++)
		sig[n] = (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
			 *c == '_' || *c == '.' ? *c : '_';
	sig[n] = '\0';
	if (n == 0 || hs_trace_find("task", sig) != NULL)
		snprintf(sig + n, sizeof(sig) - n, "%stask%d", n ? "_" : "", (int)id);
	tl.task[id] = hs_trace_signal("task", sig, 3);
	return tl.task[id];
}

/* Observer: task id's state changed. */
static void on_task_state(ID id, const char *name, STAT state)
{
	if (id < 1 || id > TNUM_TSKID)
		return;
	tl.state[id] = state;
	hs_trace_set(task_signal(id, name), task_code(id));
}

/* Observer: task id runs now (0: idle). */
static void on_running(ID id)
{
	ID was = tl.running_id;

	if (id < 0 || id > TNUM_TSKID || id == was)
		return;
	tl.running_id = id;
	if (was != 0 && tl.task[was] != NULL)
		hs_trace_set(tl.task[was], task_code(was));
	if (id != 0 && tl.task[id] != NULL)
		hs_trace_set(tl.task[id], task_code(id));
	hs_trace_set(tl.running, (uint64_t)id);
}

/* Observer: a handler is entered or left. */
static void on_handler(enum rtos_host_handler_kind kind, unsigned id, bool enter)
{
	static const char *const prefix[] = { "line", "cyclic", "alarm" };
	struct hs_signal **s;

	if ((unsigned)kind > RTOS_HOST_HANDLER_ALM || id >= TIMELINE_MAX_IDS)
		return;
	s = &tl.handler[kind][id];
	if (*s == NULL) {
		char name[32];

		snprintf(name, sizeof(name), "%s_%u", prefix[kind], id);
		*s = hs_trace_signal("isr", name, 1);
	}
	hs_trace_set(*s, enter ? 1U : 0U);
}

static const struct rtos_host_sched_observer timeline_observer = {
	.task_state = on_task_state,
	.running = on_running,
	.handler = on_handler,
};

void hs_kernel_timeline_start(void)
{
	memset(&tl, 0, sizeof(tl));
	tl.running = hs_trace_signal("rtos", "running", 8);
	hs_trace_set(tl.running, 0);
	rtos_host_set_sched_observer(&timeline_observer);
}

void hs_kernel_timeline_stop(void)
{
	rtos_host_set_sched_observer(NULL);
	memset(&tl, 0, sizeof(tl));
}
