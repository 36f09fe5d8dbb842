/*
 * test_determinism.c — two runs with identical inputs give byte-identical
 * traces: a busy system (tasks, a semaphore, an eventflag, a cyclic, device
 * events from a seeded generator raising nested interrupts, consumed CPU time).
 */
#include <stdlib.h>

#include "tap.h"
#include "kernel.h"
#include "syssvc/syslog.h"
#include "rtos_test.h"

#define IRQ_A 100U
#define IRQ_B 101U

static char *trace_buf;
static size_t trace_len, trace_cap;
static unsigned long trace_lines;

static void sink(const char *line, void *ctx)
{
	size_t n = strlen(line);

	(void)ctx;
	if (trace_len + n + 2 > trace_cap) {
		size_t cap = (trace_cap + n + 2) * 2;
		char *grown = realloc(trace_buf, cap);

		if (!grown) {
			fprintf(stderr, "test_determinism: no memory for a %zu-byte trace\n", cap);
			abort();
		}
		trace_buf = grown;
		trace_cap = cap;
	}
	memcpy(trace_buf + trace_len, line, n);
	trace_len += n;
	trace_buf[trace_len++] = '\n';
	trace_buf[trace_len] = '\0';
	trace_lines++;
}

static uint32_t rng;

static uint32_t next_rand(void)
{
	rng = rng * 1103515245U + 12345U;
	return rng >> 8;
}

static void device_event(void *arg)
{
	uintptr_t n = (uintptr_t)arg;

	rtos_host_irq_raise(next_rand() % 2 ? IRQ_A : IRQ_B);
	if (n > 0)
		rtos_host_event_at(rtos_host_now() + 1000 + next_rand() % 400000, device_event, (void *)(n - 1));
}

static void isr_a(intptr_t x)
{
	rtos_host_consume(3000);
	isig_sem(1);
}

static void isr_b(intptr_t x)
{
	rtos_host_consume(2000);
	iset_flg(1, 1U << (next_rand() % 3));
}

static void cyc(intptr_t x)
{
	iwup_tsk(3);
}

static void consumer(intptr_t x)
{
	for (;;) {
		if (twai_sem(1, 2) == E_OK)
			rtos_host_consume(20000);
		else
			syslog(LOG_DEBUG, "consumer timeout");
	}
}

static void flag_task(intptr_t x)
{
	FLGPTN p;

	for (;;) {
		wai_flg(1, 0x7, TWF_ORW, &p);
		clr_flg(1, 0);
		rtos_host_consume(5000 * p);
	}
}

static void periodic(intptr_t x)
{
	for (;;) {
		slp_tsk();
		rtos_host_consume(40000);
	}
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, consumer, 4, 1024, TDOM_KERNEL, "consumer" },
	{ 2, TA_ACT, 0, flag_task, 3, 1024, TDOM_KERNEL, "flag" },
	{ 3, TA_ACT, 0, periodic, 6, 1024, TDOM_KERNEL, "periodic" },
};
static const struct rtos_sem_cfg sems[] = { { 1, TA_TPRI, 0, 100, "s" } };
static const struct rtos_flg_cfg flgs[] = { { 1, TA_WMUL, 0, "f" } };
static const struct rtos_cyc_cfg cycs[] = { { 1, TA_STA, 0, cyc, 3, 1, "tick3" } };
static const struct rtos_int_cfg ints[] = { { IRQ_A, TA_ENAINT, -2 }, { IRQ_B, TA_ENAINT, -4 } };
static const struct rtos_isr_cfg isrs[] = {
	{ TA_NULL, 0, IRQ_A, isr_a, 1 },
	{ TA_NULL, 0, IRQ_B, isr_b, 1 },
};
static const struct rtos_cfg cfg = {
	.name = "determinism", .tasks = RTOS_TABLE(tasks), .sems = RTOS_TABLE(sems), .flgs = RTOS_TABLE(flgs),
	.cycs = RTOS_TABLE(cycs), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

static char *run_once(uint32_t seed, size_t *len)
{
	char *copy;

	trace_len = 0;
	trace_lines = 0;
	if (trace_buf)
		trace_buf[0] = '\0';
	rng = seed;
	rtos_host_boot(&cfg);
	syslog_msk_log(LOG_UPTO(LOG_DEBUG), 0);
	rtos_host_trace_set_sink(sink, NULL);
	rtos_host_event_at(5000, device_event, (void *)2000);
	rtos_host_run_for(200000000);
	rtos_host_trace_set_sink(NULL, NULL);
	rtos_host_shutdown();
	copy = malloc(trace_len + 1);
	memcpy(copy, trace_buf ? trace_buf : "", trace_len + 1);
	*len = trace_len;
	return copy;
}

int main(void)
{
	size_t la, lb, lc;
	char *a, *b, *c;

	tap_plan(5);
	a = run_once(42, &la);
	tap_diag("%lu trace lines, %zu bytes", trace_lines, la);
	if (getenv("RTOS_TRACE_DUMP"))
		fputs(a, stderr);
	b = run_once(42, &lb);
	c = run_once(43, &lc);
	ok(trace_lines > 5000, "the run produced a substantial trace");
	ok(la == lb && memcmp(a, b, la) == 0, "two runs with the same inputs give byte-identical traces");
	ok(lc != la || memcmp(a, c, la) != 0, "a different seed gives a different trace");
	ok(strstr(a, "0x") == NULL, "no pointers in the trace");
	ok(strstr(a, "kernel isr 101 enter") != NULL && strstr(a, "kernel dispatch consumer") != NULL &&
	   strstr(a, "syslog DEBUG: consumer timeout") != NULL,
	   "the trace has ISR, dispatch and syslog lines with virtual times");
	free(a);
	free(b);
	free(c);
	free(trace_buf);
	return tap_done();
}
