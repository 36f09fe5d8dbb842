/*
 * test_sem.c — semaphores: counts, E_QOVR at maxsem, wake order (FIFO and
 * TA_TPRI), pol_sem/twai_sem timeouts at exact virtual times, bad IDs.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

enum { SEM_FIFO = 1, SEM_TPRI, SEM_COUNT };

static ER r_pol[4], r_sig[4], r_bad[3];
static uint64_t t_tmout;
static ER r_twai;

static void waiter(intptr_t x)
{
	ID sem = (ID)(x / 1000);

	if (wai_sem(sem) == E_OK)
		rt_log("%c", (char)(x % 1000));
}

static void main_task(intptr_t x)
{
	/* Counting: isemcnt 2, maxsem 3 */
	r_pol[0] = pol_sem(SEM_COUNT);
	r_pol[1] = pol_sem(SEM_COUNT);
	r_pol[2] = pol_sem(SEM_COUNT);           /* empty: E_TMOUT */
	r_sig[0] = sig_sem(SEM_COUNT);
	r_sig[1] = sig_sem(SEM_COUNT);
	r_sig[2] = sig_sem(SEM_COUNT);
	r_sig[3] = sig_sem(SEM_COUNT);           /* 4th over maxsem 3: E_QOVR */
	r_bad[0] = sig_sem(0);
	r_bad[1] = sig_sem(TNUM_SEMID + 1);
	r_bad[2] = wai_sem(7);                   /* in range, not configured */

	/* Wake order: waiters of priority 5, 3, 4 start waiting in that order (1 ms apart). */
	for (ID id = 3; id <= 8; id++) {
		act_tsk(id);
		dly_tsk(1);
	}
	for (int i = 0; i < 3; i++) {
		sig_sem(SEM_FIFO);
		dly_tsk(1);                      /* lets the released waiter log */
	}
	rt_log("|");
	for (int i = 0; i < 3; i++) {
		sig_sem(SEM_TPRI);
		dly_tsk(1);
	}

	/* Timeout at an exact time: now is a tick boundary + 0; twai 3 ms */
	dly_tsk(1);
	rtos_host_consume(50000);                /* 50 us past the boundary */
	r_twai = twai_sem(SEM_FIFO, 3);
	t_tmout = rtos_host_now();
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 1, 1024, TDOM_KERNEL, "main" },
	{ 3, TA_NULL, SEM_FIFO * 1000 + 'a', waiter, 5, 1024, TDOM_KERNEL, "fa5" },
	{ 4, TA_NULL, SEM_FIFO * 1000 + 'b', waiter, 3, 1024, TDOM_KERNEL, "fb3" },
	{ 5, TA_NULL, SEM_FIFO * 1000 + 'c', waiter, 4, 1024, TDOM_KERNEL, "fc4" },
	{ 6, TA_NULL, SEM_TPRI * 1000 + 'x', waiter, 5, 1024, TDOM_KERNEL, "px5" },
	{ 7, TA_NULL, SEM_TPRI * 1000 + 'y', waiter, 3, 1024, TDOM_KERNEL, "py3" },
	{ 8, TA_NULL, SEM_TPRI * 1000 + 'z', waiter, 4, 1024, TDOM_KERNEL, "pz4" },
};
static const struct rtos_sem_cfg sems[] = {
	{ SEM_FIFO, TA_NULL, 0, 1, "fifo" },
	{ SEM_TPRI, TA_TPRI, 0, 1, "tpri" },
	{ SEM_COUNT, TA_NULL, 2, 3, "count" },
};
static const struct rtos_cfg cfg = { .name = "sem", .tasks = RTOS_TABLE(tasks), .sems = RTOS_TABLE(sems) };

int main(void)
{
	tap_plan(9);
	rt_log_reset();
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(20000000);
	ok(r_pol[0] == E_OK && r_pol[1] == E_OK, "pol_sem takes the two initial resources");
	is_int(r_pol[2], E_TMOUT, "pol_sem on an empty semaphore: E_TMOUT");
	ok(r_sig[0] == E_OK && r_sig[1] == E_OK && r_sig[2] == E_OK, "sig_sem counts up to maxsem");
	is_int(r_sig[3], E_QOVR, "sig_sem beyond maxsem: E_QOVR");
	ok(r_bad[0] == E_ID && r_bad[1] == E_ID && r_bad[2] == E_NOEXS,
	   "bad semaphore IDs: E_ID out of range, E_NOEXS unconfigured");
	is_str(rt_log_text(), "a b c | y z x", "FIFO semaphore wakes in arrival order, TA_TPRI by priority");
	is_int(r_twai, E_TMOUT, "twai_sem times out");
	/* dly_tsk(1) from 12.0 ms ends at 13.0 ms; +50 us = 13.05 ms; +3 ms = 16.05 -> boundary 16.2 ms */
	is_u64(t_tmout, 16200000, "twai_sem(3 ms) at 13.05 ms returns at the first tick boundary >= 16.05 ms");
	rtos_host_shutdown();
	return tap_done();
}
