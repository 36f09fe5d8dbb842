/*
 * bench_host.c — the host part of `make bench` (docs/bench.md).
 *
 *   bench_host [calls [virtual_s]]     defaults: 10000 calls, 10 virtual seconds
 *
 * 1. From the application task on the simulated brick (bench_brick.h):
 *    ev3lx_motor_set_speed and ev3lx_uart_sensor_get_raw (sensor streaming, so
 *    the fast path), calls times each, clock_gettime(CLOCK_MONOTONIC) around
 *    each call; then, in the same task, write() of the same command bytes to
 *    /dev/null, calls times (a real system call each).  Virtual time does not
 *    advance inside an API call: a call that took the slow path (slept) is
 *    counted and reported.  Each measurement runs ROUNDS times in a row and
 *    the round with the lowest average is reported (a shared machine
 *    preempts the process now and then; one 4 ms preemption adds 400 ns to
 *    an average over 10 000 calls), with its maximum, median and 99th
 *    percentile.
 * 2. host_sim's speed: ev3_bench_full_brick (the simulated devices with a
 *    register-level polling host), and the full stack (linux_compat and the
 *    three drivers over the same four motors and four sensors, application
 *    idle), as virtual seconds per CPU second of the process (and per wall
 *    second).  Each runs ROUNDS times from the same seed (the same work) and
 *    the round with the least CPU time is reported, for the same reason.
 * Output: CSV records for bench/run_bench.sh,
 *   call,NAME,calls,avg_ns,min_ns,max_ns,slow_calls,errors,median_ns,p99_ns
 *   speed,NAME,virtual_s,wall_s,cpu_s,speedup,cpu_speedup
 */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>
#include "bench_brick.h"
#include "rtos_host.h"
#include "host_sim/bench.h"

#define DEFAULT_CALLS      10000U
#define DEFAULT_VIRTUAL_S  10.0
#define BENCH_SEED         1U
#define ROUNDS             3U

struct call_stats {
	const char *name;
	unsigned calls, slow, errors;
	uint64_t sum_ns, min_ns, max_ns;
	uint64_t median_ns, p99_ns;
	uint64_t *each_ns;          /* this round's samples */
};

static unsigned n_calls = DEFAULT_CALLS;
static double virtual_s = DEFAULT_VIRTUAL_S;
static struct call_stats st_speed = { .name = "ev3lx_motor_set_speed" };
static struct call_stats st_raw = { .name = "ev3lx_uart_sensor_get_raw" };
static struct call_stats st_write = { .name = "write_dev_null" };
static struct call_stats st_clock = { .name = "clock_gettime_pair" };
static ER prepare_result = E_SYS;
static bool calls_done;
static double stack_wall_s, stack_cpu_s, stack_virtual_s;

static uint64_t now_ns(clockid_t clock)
{
	struct timespec ts;

	clock_gettime(clock, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ULL + (uint64_t)ts.tv_nsec;
}

/* Adds one timed call. */
static void account(struct call_stats *s, uint64_t ns, bool slow, bool error)
{
	if (s->each_ns)
		s->each_ns[s->calls] = ns;
	if (s->calls == 0 || ns < s->min_ns)
		s->min_ns = ns;
	if (ns > s->max_ns)
		s->max_ns = ns;
	s->sum_ns += ns;
	s->calls++;
	s->slow += slow;
	s->errors += error;
}

static int u64_cmp(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return x < y ? -1 : x > y;
}

/* Runs measure ROUNDS times into *best, keeping the round with the lowest
 * average; slow calls and errors are summed over all rounds. */
static void best_of_rounds(struct call_stats *best, void (*measure)(struct call_stats *))
{
	unsigned slow = 0, errors = 0;

	for (unsigned round = 0; round < ROUNDS; round++) {
		struct call_stats s = { .name = best->name };

		s.each_ns = calloc(n_calls, sizeof(uint64_t));
		if (!s.each_ns) {
			best->errors = n_calls;
			return;
		}
		measure(&s);
		slow += s.slow;
		errors += s.errors;
		qsort(s.each_ns, s.calls, sizeof(uint64_t), u64_cmp);
		s.median_ns = s.each_ns[s.calls / 2];
		s.p99_ns = s.each_ns[(s.calls * 99U + 99U) / 100U - 1U];
		free(s.each_ns);
		s.each_ns = NULL;
		if (round == 0 || s.sum_ns < best->sum_ns)
			*best = s;
	}
	best->slow = slow;
	best->errors = errors;
}

static void measure_set_speed(struct call_stats *st)
{
	for (unsigned i = 0; i < n_calls; i++) {
		int speed = bench_speed_for(i);
		uint64_t v0 = rtos_host_now(), t0 = now_ns(CLOCK_MONOTONIC);
		ER ercd = ev3lx_motor_set_speed(BENCH_MOTOR_PORT, speed);
		uint64_t t1 = now_ns(CLOCK_MONOTONIC);

		account(st, t1 - t0, rtos_host_now() != v0, ercd != E_OK);
	}
}

static void measure_get_raw(struct call_stats *st)
{
	uint8_t raw[BENCH_RAW_BYTES];

	for (unsigned i = 0; i < n_calls; i++) {
		uint64_t v0 = rtos_host_now(), t0 = now_ns(CLOCK_MONOTONIC);
		ER ercd = ev3lx_uart_sensor_get_raw(BENCH_SENSOR_PORT, raw, sizeof(raw));
		uint64_t t1 = now_ns(CLOCK_MONOTONIC);

		account(st, t1 - t0, rtos_host_now() != v0, ercd != E_OK);
	}
}

/* What Linux costs for the same command: one write() system call each. */
static void measure_write(struct call_stats *st)
{
	int fd = open("/dev/null", O_WRONLY);
	uint8_t cmd[3];
	unsigned len;

	if (fd < 0) {
		st->errors = n_calls;
		return;
	}
	for (unsigned i = 0; i < n_calls; i++) {
		bench_speed_command(bench_speed_for(i), cmd, &len);
		uint64_t t0 = now_ns(CLOCK_MONOTONIC);
		ssize_t n = write(fd, cmd, len);
		uint64_t t1 = now_ns(CLOCK_MONOTONIC);

		account(st, t1 - t0, false, n != (ssize_t)len);
	}
	close(fd);
}

/* The cost of the measurement itself: two clock reads around nothing. */
static void measure_clock(struct call_stats *st)
{
	for (unsigned i = 0; i < n_calls; i++) {
		uint64_t t0 = now_ns(CLOCK_MONOTONIC);
		uint64_t t1 = now_ns(CLOCK_MONOTONIC);

		account(st, t1 - t0, false, false);
	}
}

static void calls_body(void)
{
	prepare_result = bench_brick_prepare();
	if (prepare_result != E_OK)
		return;
	best_of_rounds(&st_clock, measure_clock);
	best_of_rounds(&st_speed, measure_set_speed);
	best_of_rounds(&st_raw, measure_get_raw);
	best_of_rounds(&st_write, measure_write);
	calls_done = true;
}

/* The full stack running on its own: drivers, motors turning, sensors
 * streaming, the application asleep; wall and CPU time of virtual_s. */
static void stack_body(void)
{
	uint64_t w0, c0, v0;

	prepare_result = bench_brick_prepare();
	if (prepare_result != E_OK)
		return;
	w0 = now_ns(CLOCK_MONOTONIC);
	c0 = now_ns(CLOCK_PROCESS_CPUTIME_ID);
	v0 = rtos_host_now();
	dly_tsk((RELTIM)(virtual_s * 1000.0));
	stack_virtual_s = (double)(rtos_host_now() - v0) / 1e9;
	stack_wall_s = (double)(now_ns(CLOCK_MONOTONIC) - w0) / 1e9;
	stack_cpu_s = (double)(now_ns(CLOCK_PROCESS_CPUTIME_ID) - c0) / 1e9;
}

static void print_call(const struct call_stats *s)
{
	printf("call,%s,%u,%.1f,%llu,%llu,%u,%u,%llu,%llu\n", s->name, s->calls,
	       s->calls ? (double)s->sum_ns / s->calls : 0.0, (unsigned long long)s->min_ns,
	       (unsigned long long)s->max_ns, s->slow, s->errors, (unsigned long long)s->median_ns,
	       (unsigned long long)s->p99_ns);
}

static void print_speed(const char *name, double vs, double ws, double cs)
{
	printf("speed,%s,%.3f,%.3f,%.3f,%.1f,%.1f\n", name, vs, ws, cs,
	       ws > 0 ? vs / ws : 0.0, cs > 0 ? vs / cs : 0.0);
}

int main(int argc, char **argv)
{
	struct ev3_bench_result r, best = { 0 };
	unsigned round;
	ER ercd;

	if (argc > 1)
		n_calls = (unsigned)strtoul(argv[1], NULL, 10);
	if (argc > 2)
		virtual_s = strtod(argv[2], NULL);
	if (n_calls == 0 || !(virtual_s > 0.0 && virtual_s <= 3600.0)) {
		fprintf(stderr, "usage: bench_host [calls [virtual_s]]\n");
		return 2;
	}

	if (!bench_brick_run(BENCH_BRICK_FULL, calls_body, BENCH_SEED, 60) || !calls_done) {
		fprintf(stderr, "bench_host: the measured calls did not run (prepare: %d)\n",
			(int)prepare_result);
		return 1;
	}
	print_call(&st_speed);
	print_call(&st_raw);
	print_call(&st_write);
	print_call(&st_clock);

	for (round = 0; round < ROUNDS; round++) {
		ercd = ev3_bench_full_brick(virtual_s, BENCH_SEED, &r);
		if (ercd != E_OK) {
			fprintf(stderr, "bench_host: ev3_bench_full_brick: %d\n", (int)ercd);
			return 1;
		}
		if (round == 0 || r.cpu_s < best.cpu_s)
			best = r;
	}
	print_speed("host_sim_devices", best.virtual_s, best.wall_s, best.cpu_s);

	for (round = 0; round < ROUNDS; round++) {
		stack_wall_s = 0.0;
		if (!bench_brick_run(BENCH_BRICK_FULL, stack_body, BENCH_SEED, 30U + (unsigned)virtual_s) ||
		    stack_wall_s <= 0.0) {
			fprintf(stderr, "bench_host: the full stack did not run (prepare: %d)\n",
				(int)prepare_result);
			return 1;
		}
		if (round == 0 || stack_cpu_s < best.cpu_s)
			best = (struct ev3_bench_result){ .virtual_s = stack_virtual_s, .wall_s = stack_wall_s,
							  .cpu_s = stack_cpu_s };
	}
	print_speed("full_stack", best.virtual_s, best.wall_s, best.cpu_s);
	return st_speed.errors || st_raw.errors || st_write.errors ? 1 : 0;
}
