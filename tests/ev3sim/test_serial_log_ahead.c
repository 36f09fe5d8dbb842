/*
 * test_serial_log_ahead.c — serial_log_send times the bytes whose spins and
 * accesses end before the kernel's quiet bound itself and moves the clock
 * once; it must leave everything exactly as one rtos_host_spin_until and one
 * rtos_host_consume per byte did.  The same load — a writer under a dense
 * interrupt load whose times share a 50 ns grid with the bytes' (ties), a
 * higher-priority task that preempts it and writes too, writes under
 * loc_cpu and dis_dsp, runs ending at arbitrary deadlines — runs once with
 * serial_log_send and once with the per-byte driver below; every context's
 * times, the kernel trace, the statistics and the far end's bytes must match.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "rtos_host.h"
#include "ev3sim/serial_log.h"

#define WRITER_TSKID  1
#define HIGH_TSKID    2
#define IRQ_DEV       120U
#define RUN_NS        40000000ULL
#define MAX_MARKS     400000U

typedef ER_UINT (*send_fn)(const char *buf, uint_t len);

/* The per-byte driver serial_log_send replaced: the reference. */
static struct {
	uint64_t byte_ns;
	uint64_t line_free_at;
	FILE *out;
	struct serial_log_stats stats;
} ref;

static void ref_setup(uint32_t baud, FILE *out)
{
	ref.byte_ns = (10ULL * 1000000000ULL + baud - 1) / baud;
	ref.line_free_at = 0;
	ref.out = out;
	memset(&ref.stats, 0, sizeof(ref.stats));
}

static ER_UINT ref_send(const char *buf, uint_t len)
{
	for (uint_t i = 0; i < len; i++) {
		uint64_t now = rtos_host_now();

		if (ref.line_free_at > now + ref.byte_ns)
			ref.stats.spin_ns += rtos_host_spin_until(ref.line_free_at - ref.byte_ns);
		now = rtos_host_now();
		ref.line_free_at = (ref.line_free_at > now ? ref.line_free_at : now) + ref.byte_ns;
		rtos_host_consume(SERIAL_LOG_ACCESS_NS);
		fputc(buf[i], ref.out);
		ref.stats.bytes++;
	}
	ref.stats.writes++;
	return (ER_UINT)len;
}

/* One run's record: what happened when, in order. */
struct record {
	uint64_t *marks;
	uint_t n;
	uint64_t trace_hash;
};

static struct record *rec;
static send_fn send;
static uint64_t grid_ns;       /* the load's times are multiples of it */
static uint64_t rng;

static uint32_t rnd(uint32_t n)
{
	rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
	return (uint32_t)(rng >> 33) % n;
}

/* Records a context's step: a tag and the clock. */
static void mark(uint64_t tag)
{
	if (rec->n + 2 > MAX_MARKS)
		return;
	rec->marks[rec->n++] = tag;
	rec->marks[rec->n++] = rtos_host_now();
}

static void trace_sink(const char *line, void *ctx)
{
	struct record *r = ctx;

	for (; *line; line++)
		r->trace_hash = (r->trace_hash ^ (uint8_t)*line) * 1099511628211ULL;
}

static void write_line(uint64_t tag, uint_t len)
{
	char line[SERIAL_LOG_MAX_WRITE];

	for (uint_t i = 0; i < len; i++)
		line[i] = (char)('a' + (rec->n + i) % 26);
	mark(tag);
	mark(tag + 1 + (uint64_t)send(line, len));
}

static void writer_task(intptr_t exinf)
{
	(void)exinf;
	for (;;) {
		uint32_t how = rnd(16);
		uint_t len = how == 0 ? SERIAL_LOG_MAX_WRITE : 1 + rnd(40);

		if (how == 1) {
			loc_cpu();      /* an interrupt raised meanwhile waits: nothing preempts */
			write_line(100, len);
			unl_cpu();
		} else if (how == 2) {
			dis_dsp();      /* a task woken meanwhile waits for ena_dsp */
			write_line(200, len);
			ena_dsp();
		} else {
			write_line(300, len);
		}
		if (rnd(8) == 0)
			dly_tsk(1);
	}
}

static void high_task(intptr_t exinf)
{
	(void)exinf;
	for (;;) {
		slp_tsk();
		mark(400);
		rtos_host_consume(grid_ns * rnd(5000 / grid_ns + 2));
		if (rnd(4) == 0)
			write_line(500, 1 + rnd(6));
	}
}

static void isr_dev(intptr_t exinf)
{
	(void)exinf;
	mark(600);
	rtos_host_consume(grid_ns * rnd(2000 / grid_ns + 2));
	if (rnd(6) == 0)
		(void)iwup_tsk(HIGH_TSKID);
}

/* The load: an interrupt, or an event nobody sees, every 0..60 us on the grid. */
static void device_event(void *arg)
{
	(void)arg;
	if (rnd(3) != 0)
		rtos_host_irq_raise(IRQ_DEV);
	rtos_host_event_at(rtos_host_now() + grid_ns * rnd(1200 * 50 / grid_ns), device_event, NULL);
}

static const struct rtos_task_cfg tasks[] = {
	{ WRITER_TSKID, TA_ACT, 0, writer_task, 10, 16 * 1024, TDOM_KERNEL, "writer" },
	{ HIGH_TSKID, TA_ACT, 0, high_task, 4, 16 * 1024, TDOM_KERNEL, "high" },
};
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg cfg = {
	.name = "serial_log_ahead", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

/* Runs the load for RUN_NS in runs of random lengths with send as the driver;
 * the far end's bytes go to far, the statistics to stats. */
static void run_load(uint32_t baud, uint64_t grid, send_fn fn, struct record *r, FILE *far, struct serial_log_stats *stats)
{
	uint64_t chunk_rng;

	rec = r;
	send = fn;
	grid_ns = grid;
	rng = baud + grid;
	r->n = 0;
	r->trace_hash = 1469598103934665603ULL;
	serial_log_setup(baud, fn == serial_log_send ? far : NULL);
	ref_setup(baud, far);
	rtos_host_trace_set_sink(trace_sink, r);
	if (rtos_host_boot(&cfg) != E_OK)
		return;
	rtos_host_event_at(grid, device_event, NULL);
	chunk_rng = baud;
	while (rtos_host_now() < RUN_NS) {
		chunk_rng = chunk_rng * 6364136223846793005ULL + 1442695040888963407ULL;
		rtos_host_run_for(50 * ((chunk_rng >> 33) % 4000) + (chunk_rng >> 62));
	}
	*stats = fn == serial_log_send ? *serial_log_get_stats() : ref.stats;
	rtos_host_shutdown();
	rtos_host_trace_set_sink(NULL, NULL);
}

/* The far end's bytes, read back from the start. */
static size_t far_bytes(FILE *far, char **out)
{
	long size;

	fflush(far);
	size = ftell(far);
	*out = malloc(size > 0 ? (size_t)size : 1U);
	rewind(far);
	return fread(*out, 1, size > 0 ? (size_t)size : 0U, far);
}

static void compare(uint32_t baud, uint64_t grid)
{
	struct record fast = { calloc(MAX_MARKS, sizeof(uint64_t)), 0, 0 };
	struct record slow = { calloc(MAX_MARKS, sizeof(uint64_t)), 0, 0 };
	struct serial_log_stats fast_stats, slow_stats;
	FILE *fast_far = tmpfile(), *slow_far = tmpfile();
	char *fast_bytes, *slow_bytes;
	size_t fast_n, slow_n;
	uint_t first_diff = 0;

	run_load(baud, grid, serial_log_send, &fast, fast_far, &fast_stats);
	run_load(baud, grid, ref_send, &slow, slow_far, &slow_stats);
	while (first_diff < fast.n && first_diff < slow.n && fast.marks[first_diff] == slow.marks[first_diff])
		first_diff++;
	ok(fast.n == slow.n && first_diff == fast.n && fast.n > 1000,
	   "%u baud, %llu ns grid: every context's steps at the same times (%u marks, first difference at %u)",
	   (unsigned)baud, (unsigned long long)grid, fast.n, first_diff);
	ok(fast.trace_hash == slow.trace_hash, "%u baud, %llu ns grid: the same kernel trace", (unsigned)baud, (unsigned long long)grid);
	ok(fast_stats.bytes == slow_stats.bytes && fast_stats.writes == slow_stats.writes &&
	   fast_stats.spin_ns == slow_stats.spin_ns && fast_stats.spin_ns > 0,
	   "%u baud, %llu ns grid: the same statistics (%llu bytes, %llu writes, %llu ns spun)", (unsigned)baud, (unsigned long long)grid,
	   (unsigned long long)fast_stats.bytes, (unsigned long long)fast_stats.writes,
	   (unsigned long long)fast_stats.spin_ns);
	fast_n = far_bytes(fast_far, &fast_bytes);
	slow_n = far_bytes(slow_far, &slow_bytes);
	ok(fast_n == slow_n && fast_n == fast_stats.bytes && memcmp(fast_bytes, slow_bytes, fast_n) == 0,
	   "%u baud, %llu ns grid: the far end got the same %zu bytes", (unsigned)baud, (unsigned long long)grid, fast_n);
	free(fast_bytes);
	free(slow_bytes);
	fclose(fast_far);
	fclose(slow_far);
	free(fast.marks);
	free(slow.marks);
}

int main(void)
{
	/* a 2.5 us grid divides the 1 and 2 Mbaud byte times: events often fall
	 * due exactly where a spin or an access ends */
	static const struct { uint32_t baud; uint64_t grid_ns; } loads[] = {
		{ 9600, 50 }, { 115200, 50 }, { 1000000, 50 }, { 2000000, 50 }, { 1000000, 2500 }, { 2000000, 2500 },
	};

	tap_plan(4 * (int)(sizeof(loads) / sizeof(loads[0])));
	for (uint_t i = 0; i < sizeof(loads) / sizeof(loads[0]); i++)
		compare(loads[i].baud, loads[i].grid_ns);
	return tap_done();
}
