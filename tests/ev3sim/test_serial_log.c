/*
 * test_serial_log.c — the serial log channel's polled write service call:
 * bytes leave at the baud (two in the port at once, the caller spinning for
 * the rest), the far end gets them in order, the spin is preemptible by a
 * higher-priority task, and every bad argument is an error code.
 */
#define _POSIX_C_SOURCE 200809L
#include <string.h>
#include "tap.h"
#include "rtos_host.h"
#include "ev3sim/serial_log.h"

#define WRITER_TSKID  1
#define HIGH_TSKID    2
#define ALM_ID        1
#define DOMAIN        1
#define BYTE_NS       86806ULL          /* 10 bits at 115200 baud, rounded up */

static char global_buf[16] = "outside";     /* not in the writer's domain */
static ER_UINT alarm_result;
static uint64_t high_started, alarm_at, write_start, write_end, long_end;
static ER_UINT results[8];
static bool done;

static void high_task(intptr_t exinf)
{
	(void)exinf;
	high_started = rtos_host_now();
}

static void alarm_handler(intptr_t exinf)
{
	(void)exinf;
	alarm_at = rtos_host_now();
	alarm_result = serial_log_write("x", 1);
	(void)iact_tsk(HIGH_TSKID);
}

static void writer_task(intptr_t exinf)
{
	char line[64];

	(void)exinf;
	memcpy(line, "0123456789", 10);
	write_start = rtos_host_now();
	results[0] = serial_log_write(line, 10);
	write_end = rtos_host_now();
	results[1] = serial_log_write(line, 0);
	results[2] = serial_log_write(line, SERIAL_LOG_MAX_WRITE + 1);
	results[3] = serial_log_write(NULL, 4);
	results[4] = serial_log_write(global_buf, 4);
	results[5] = cal_svc(SERIAL_LOG_FN_WRITE, (intptr_t)line, -3, 0, 0, 0);
	/* a long write, interrupted by a higher-priority task 1 ms into it */
	memset(line, 'a', sizeof(line));
	dly_tsk(5);
	sta_alm(ALM_ID, 1);
	results[6] = serial_log_write(line, sizeof(line));
	long_end = rtos_host_now();
	done = true;
}

static const struct rtos_task_cfg tasks[] = {
	{ WRITER_TSKID, TA_ACT, 0, writer_task, 10, 16 * 1024, DOMAIN, "writer" },
	{ HIGH_TSKID, TA_NULL, 0, high_task, 2, 16 * 1024, DOMAIN, "high" },
};
static const struct rtos_alm_cfg alms[] = { { ALM_ID, TA_NULL, 0, alarm_handler, "alarm" } };
static const struct rtos_cfg *const includes[] = { &serial_log_cfg, NULL };
static const struct rtos_cfg cfg = {
	.name = "test_serial_log", .tasks = RTOS_TABLE(tasks), .alms = RTOS_TABLE(alms),
	.includes = includes,
};

int main(void)
{
	FILE *far = tmpfile();
	char got[128] = { 0 };
	const struct serial_log_stats *st;
	size_t n;

	tap_plan(16);
	is_int(serial_log_setup(0, NULL), E_PAR, "baud 0: E_PAR");
	is_int(serial_log_setup(115200, far), E_OK, "115200 baud into a file");
	if (rtos_host_boot(&cfg) != E_OK)
		return tap_done();
	rtos_host_run_for(100000000ULL);
	ok(done, "the writer finished");
	is_int(results[0], 10, "a 10-byte write returns 10");
	/* bytes 1 and 2 go into the shift and holding registers at once; the caller
	 * spins for each of the other 8 until the holding register empties */
	ok(write_end - write_start >= 8 * BYTE_NS && write_end - write_start <= 8 * BYTE_NS + 25000,
	   "it took 8 character times of spinning (%llu ns)", (unsigned long long)(write_end - write_start));
	is_int(results[1], E_PAR, "length 0: E_PAR");
	is_int(results[2], E_PAR, "length above SERIAL_LOG_MAX_WRITE: E_PAR");
	is_int(results[3], E_MACV, "NULL buffer: E_MACV");
	is_int(results[4], E_MACV, "a buffer outside the caller's domain: E_MACV");
	is_int(results[5], E_PAR, "negative length: E_PAR");
	is_int(alarm_result, E_CTX, "from an alarm handler: E_CTX");
	is_int(results[6], 64, "the long write completed");
	ok(high_started >= alarm_at && high_started - alarm_at < 10000 && high_started < long_end,
	   "a higher-priority task preempts the spinning writer at once (%llu ns)",
	   (unsigned long long)(high_started - alarm_at));
	st = serial_log_get_stats();
	ok(st->bytes == 74 && st->writes == 2, "74 bytes in 2 writes counted (%llu, %llu)",
	   (unsigned long long)st->bytes, (unsigned long long)st->writes);
	rtos_host_shutdown();
	rewind(far);
	n = fread(got, 1, sizeof(got) - 1, far);
	is_int(n, 74, "the far end received 74 bytes");
	ok(strncmp(got, "0123456789aaaa", 14) == 0, "in order");
	fclose(far);
	return tap_done();
}
