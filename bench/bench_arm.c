/*
 * bench_arm.c — the ARMv5 part of `make bench`: the measured calls on the
 * simulated brick, cross-built for the ARM926 and run under
 * `qemu-arm -cpu arm926` with QEMU's per-translation-block execution log.
 * The program measures nothing itself: insn_count.c reads the log and counts
 * the instructions of every call of the measured functions made while a
 * window is open (between the marker functions bench_window_open and
 * bench_window_close, whose addresses it takes from the symbol table).
 *
 *   bench_arm [calls [tick_ms [light]]]   defaults: 10000 calls, 200 ms of
 *                                          ticks, the full brick
 *
 * It prints one line per phase ("phase <name> <calls> <errors>") so the
 * script can check that every call succeeded.
 */
#include <stdio.h>
#include <stdlib.h>
#include "bench_brick.h"

#define DEFAULT_CALLS    10000U
#define DEFAULT_TICK_MS  200U

static unsigned n_calls = DEFAULT_CALLS;
static unsigned tick_ms = DEFAULT_TICK_MS;
static enum bench_brick_kind brick = BENCH_BRICK_FULL;
static unsigned set_speed_errors, get_raw_errors;
static ER prepare_result = E_SYS;
static bool finished;

/* Marker: the instruction counter counts measured calls from here on.  It
 * must stay a real call (noinline, with a side effect the compiler keeps). */
__attribute__((noinline)) void bench_window_open(void);
__attribute__((noinline)) void bench_window_open(void)
{
	__asm__ volatile("" ::: "memory");
}

/* Marker: the counter stops counting measured calls here. */
__attribute__((noinline)) void bench_window_close(void);
__attribute__((noinline)) void bench_window_close(void)
{
	__asm__ volatile("" ::: "memory");
}

/* The application task: prepares the brick, then the three measured phases. */
static void body(void)
{
	uint8_t raw[BENCH_RAW_BYTES];

	prepare_result = bench_brick_prepare();
	if (prepare_result != E_OK)
		return;

	bench_window_open();
	for (unsigned i = 0; i < n_calls; i++)
		if (ev3lx_motor_set_speed(BENCH_MOTOR_PORT, bench_speed_for(i)) != E_OK)
			set_speed_errors++;
	bench_window_close();

	bench_window_open();
	for (unsigned i = 0; i < n_calls; i++)
		if (ev3lx_uart_sensor_get_raw(BENCH_SENSOR_PORT, raw, sizeof(raw)) != E_OK)
			get_raw_errors++;
	bench_window_close();

	/* Ticks while the application sleeps: every driver's timer is armed,
	 * the motors turn and the sensors stream. */
	bench_window_open();
	dly_tsk(tick_ms);
	bench_window_close();
	finished = true;
}

int main(int argc, char **argv)
{
	if (argc > 1)
		n_calls = (unsigned)strtoul(argv[1], NULL, 10);
	if (argc > 2)
		tick_ms = (unsigned)strtoul(argv[2], NULL, 10);
	if (argc > 3)
		brick = BENCH_BRICK_LIGHT;
	if (n_calls == 0 || tick_ms == 0) {
		fprintf(stderr, "usage: bench_arm [calls [tick_ms [light]]]\n");
		return 2;
	}
	if (!bench_brick_run(brick, body, 1, 30U + tick_ms / 1000U) || !finished) {
		fprintf(stderr, "bench_arm: the brick did not finish (prepare: %d)\n",
			(int)prepare_result);
		return 1;
	}
	printf("phase ev3lx_motor_set_speed %u %u\n", n_calls, set_speed_errors);
	printf("phase ev3lx_uart_sensor_get_raw %u %u\n", n_calls, get_raw_errors);
	printf("phase tick %u 0\n", tick_ms);
	return set_speed_errors || get_raw_errors ? 1 : 0;
}
