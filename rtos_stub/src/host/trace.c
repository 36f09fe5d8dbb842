/*
 * trace.c — the event trace: one text line per kernel event or layer
 * record, "<ns> <source> <text>", with virtual time only (no pointers, no
 * wall time), so identical inputs give byte-identical traces.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "kernel_impl.h"

rtos_host_trace_sink trace_sink;
static void *trace_ctx;
static const char *trace_source;   /* the only source the sink takes (NULL: every one) */

/* Installs the sink that receives every trace line (NULL: tracing off). */
void rtos_host_trace_set_sink(rtos_host_trace_sink sink, void *ctx)
{
	trace_sink = sink;
	trace_ctx = ctx;
	trace_source = NULL;
}

/* Installs a sink for the lines of one source: the others are not formatted at
 * all (in a long run the kernel's interrupt entries and exits are most of the
 * lines, and formatting them took most of the run's time). */
void rtos_host_trace_set_source_sink(const char *source, rtos_host_trace_sink sink, void *ctx)
{
	rtos_host_trace_set_sink(sink, ctx);
	trace_source = source;
}

const struct rtos_host_sched_observer *sched_observer;

/* Installs the scheduler's observer (NULL: none). */
void rtos_host_set_sched_observer(const struct rtos_host_sched_observer *obs)
{
	sched_observer = obs;
}

/* Tells the observer of t's state (a waiting task that is also suspended: TTS_WAS). */
__attribute__((cold, noinline)) void observer_task_state(const struct tcb *t)
{
	sched_observer->task_state(t->id, t->cfg->name, t->state == TTS_WAI && t->suspended ? TTS_WAS : t->state);
}

/* Tells the observer which task runs (NULL: idle). */
__attribute__((cold, noinline)) void observer_running(const struct tcb *t)
{
	sched_observer->running(t != NULL ? t->id : 0);
}

/* Tells the observer of a handler's entry or exit. */
__attribute__((cold, noinline)) void observer_handler(enum rtos_host_handler_kind kind, unsigned id, bool enter)
{
	sched_observer->handler(kind, id, enter);
}

/* Records one line "<ns> <source> <text>" if a sink is installed. */
void rtos_host_trace(const char *source, const char *fmt, ...)
{
	char line[512];
	int n;
	va_list ap;

	if (trace_sink == NULL || (trace_source != NULL && strcmp(source, trace_source) != 0))
		return;
	n = snprintf(line, sizeof(line), "%llu %s ", (unsigned long long)now_ns, source);
	if (n < 0 || (size_t)n >= sizeof(line))
		n = 0;
	va_start(ap, fmt);
	vsnprintf(line + n, sizeof(line) - (size_t)n, fmt, ap);
	va_end(ap);
	trace_sink(line, trace_ctx);
}

/* Traces a failing service call and returns its code unchanged. */
ER trace_svc_error(const char *svc, ER ercd)
{
	rtos_host_trace("kernel", "%s -> %s", svc, ercd_name(ercd));
	return ercd;
}

/* Name of a TOPPERS main error code. */
const char *ercd_name(ER ercd)
{
	switch (MERCD(ercd)) {
	case E_OK: return "E_OK";
	case E_SYS: return "E_SYS";
	case E_NOSPT: return "E_NOSPT";
	case E_RSFN: return "E_RSFN";
	case E_RSATR: return "E_RSATR";
	case E_PAR: return "E_PAR";
	case E_ID: return "E_ID";
	case E_CTX: return "E_CTX";
	case E_MACV: return "E_MACV";
	case E_OACV: return "E_OACV";
	case E_ILUSE: return "E_ILUSE";
	case E_NOMEM: return "E_NOMEM";
	case E_NOID: return "E_NOID";
	case E_NORES: return "E_NORES";
	case E_OBJ: return "E_OBJ";
	case E_NOEXS: return "E_NOEXS";
	case E_QOVR: return "E_QOVR";
	case E_RLWAI: return "E_RLWAI";
	case E_TMOUT: return "E_TMOUT";
	case E_DLT: return "E_DLT";
	case E_CLS: return "E_CLS";
	case E_WBLK: return "E_WBLK";
	case E_BOVR: return "E_BOVR";
	default: return "E_?";
	}
}
