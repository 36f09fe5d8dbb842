/*
 * test_mtx.c — mutexes: the priority ceiling protocol (the holder runs at
 * the ceiling, E_ILUSE for a task above it, chg_pri above a held ceiling),
 * priority inheritance (a middle-priority task does not preempt a holder
 * that a high-priority task waits for; along a chain of holders; the
 * inherited priority drops when the waiter times out), E_OBJ for re-locking,
 * for unlocking another's mutex and out of locking order, hand-over to the
 * first waiter, release when the holder ends (ext_tsk, ter_tsk), ini_mtx
 * (E_DLT), ref_mtx, and E_CTX/E_ID.
 */
#define _POSIX_C_SOURCE 200809L
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"
#include "boot_refusal_test.h"

#define MS 1000000ULL

enum { M_CEIL = 1, M_INH, M_INH2, M_FIFO, M_TPRI };
enum { T_MAIN = 1, T_HIGH, T_MID, T_LOW, T_C_LOW, T_C_MID, T_C_HIGH, T_D_LOW, T_D_HIGH, T_EXIT, T_W1, T_TER, T_W2, T_W3 };

static PRI p_ceil, p_after, p_low_inh, p_chain, p_chain_after, p_d_during, p_d_after;
static ER r_ilu, r_obj[4], r_chg, r_tmo, r_ctx, r_id[2], r_ini, r_ref, r_ter;
static ER w_result[3];
static T_RMTX ref;

static void high(intptr_t x)
{
	rt_log("H-wait");
	loc_mtx(M_INH);
	rt_log("H-got");
	unl_mtx(M_INH);
}

static void mid(intptr_t x)
{
	rt_log("M-run");
}

static void low(intptr_t x)
{
	loc_mtx(M_INH);
	act_tsk(T_HIGH);                      /* HIGH (3) preempts and waits: LOW inherits 3 */
	get_pri(TSK_SELF, &p_low_inh);
	act_tsk(T_MID);                       /* MID (6) stays ready behind the holder */
	rt_log("L-unlock");
	unl_mtx(M_INH);
	rt_log("L-done");
}

/* The chain: C_LOW holds M_INH2; C_MID holds M_INH and waits for M_INH2; C_HIGH waits for M_INH. */
static void c_low(intptr_t x)
{
	loc_mtx(M_INH2);
	dly_tsk(3);
	get_pri(TSK_SELF, &p_chain);
	unl_mtx(M_INH2);
	get_pri(TSK_SELF, &p_chain_after);
}

static void c_mid(intptr_t x)
{
	loc_mtx(M_INH);
	loc_mtx(M_INH2);
	unl_mtx(M_INH2);
	unl_mtx(M_INH);
}

static void c_high(intptr_t x)
{
	loc_mtx(M_INH);
	unl_mtx(M_INH);
}

static void d_low(intptr_t x)
{
	loc_mtx(M_INH);
	dly_tsk(5);
	get_pri(TSK_SELF, &p_d_after);
	unl_mtx(M_INH);
}

static void d_high(intptr_t x)
{
	r_tmo = tloc_mtx(M_INH, 2);
}

static void exiter(intptr_t x)
{
	loc_mtx(M_FIFO);
	dly_tsk(2);
	ext_tsk();
}

static void holder(intptr_t x)
{
	loc_mtx(M_TPRI);
	slp_tsk();
}

static void waiter(intptr_t x)
{
	ID m = x == 0 ? M_FIFO : M_TPRI;

	w_result[x] = loc_mtx(m);
	if (w_result[x] == E_OK) {
		rt_log("W%d", (int)x);
		unl_mtx(m);
	}
}

static void cyc(intptr_t x)
{
	r_ctx = ploc_mtx(M_FIFO);
}

static void main_task(intptr_t x)
{
	/* ceiling 4: main (base 5) runs at 4 while holding it */
	loc_mtx(M_CEIL);
	get_pri(TSK_SELF, &p_ceil);
	r_obj[0] = loc_mtx(M_CEIL);
	r_chg = chg_pri(TSK_SELF, 2);
	loc_mtx(M_FIFO);
	r_obj[1] = unl_mtx(M_CEIL);
	unl_mtx(M_FIFO);
	unl_mtx(M_CEIL);
	get_pri(TSK_SELF, &p_after);
	chg_pri(TSK_SELF, 3);
	r_ilu = loc_mtx(M_CEIL);
	chg_pri(TSK_SELF, 2);

	act_tsk(T_LOW);
	dly_tsk(5);
	rt_log("|");

	act_tsk(T_C_LOW);
	dly_tsk(1);
	act_tsk(T_C_MID);
	dly_tsk(1);
	act_tsk(T_C_HIGH);
	dly_tsk(10);

	act_tsk(T_D_LOW);
	dly_tsk(1);
	act_tsk(T_D_HIGH);
	dly_tsk(1);
	get_pri(T_D_LOW, &p_d_during);
	dly_tsk(10);
	rt_log("|");

	act_tsk(T_EXIT);
	dly_tsk(1);
	act_tsk(T_W1);
	dly_tsk(0);
	r_obj[2] = unl_mtx(M_FIFO);
	r_ref = ref_mtx(M_FIFO, &ref);
	sta_cyc(1);
	dly_tsk(5);
	stp_cyc(1);

	act_tsk(T_TER);
	dly_tsk(1);
	act_tsk(T_W2);
	dly_tsk(1);
	r_ter = ter_tsk(T_TER);
	dly_tsk(1);

	loc_mtx(M_TPRI);
	act_tsk(T_W3);
	dly_tsk(1);
	r_ini = ini_mtx(M_TPRI);
	dly_tsk(1);
	r_obj[3] = unl_mtx(M_TPRI);
	r_id[0] = loc_mtx(0);
	r_id[1] = loc_mtx(TNUM_MTXID + 1);
}

static const struct rtos_task_cfg tasks[] = {
	{ T_MAIN, TA_ACT, 0, main_task, 5, 1024, TDOM_KERNEL, "main" },
	{ T_HIGH, TA_NULL, 0, high, 3, 1024, TDOM_KERNEL, "high" },
	{ T_MID, TA_NULL, 0, mid, 6, 1024, TDOM_KERNEL, "mid" },
	{ T_LOW, TA_NULL, 0, low, 10, 1024, TDOM_KERNEL, "low" },
	{ T_C_LOW, TA_NULL, 0, c_low, 10, 1024, TDOM_KERNEL, "c_low" },
	{ T_C_MID, TA_NULL, 0, c_mid, 8, 1024, TDOM_KERNEL, "c_mid" },
	{ T_C_HIGH, TA_NULL, 0, c_high, 3, 1024, TDOM_KERNEL, "c_high" },
	{ T_D_LOW, TA_NULL, 0, d_low, 10, 1024, TDOM_KERNEL, "d_low" },
	{ T_D_HIGH, TA_NULL, 0, d_high, 3, 1024, TDOM_KERNEL, "d_high" },
	{ T_EXIT, TA_NULL, 0, exiter, 9, 1024, TDOM_KERNEL, "exit" },
	{ T_W1, TA_NULL, 0, waiter, 9, 1024, TDOM_KERNEL, "w1" },
	{ T_TER, TA_NULL, 0, holder, 9, 1024, TDOM_KERNEL, "ter" },
	{ T_W2, TA_NULL, 1, waiter, 9, 1024, TDOM_KERNEL, "w2" },
	{ T_W3, TA_NULL, 2, waiter, 9, 1024, TDOM_KERNEL, "w3" },
};
static const struct rtos_mtx_cfg mtxs[] = {
	{ M_CEIL, TA_CEILING, 4, "ceil" },
	{ M_INH, TA_INHERIT, 0, "inh" },
	{ M_INH2, TA_INHERIT, 0, "inh2" },
	{ M_FIFO, TA_NULL, 0, "fifo" },
	{ M_TPRI, TA_TPRI, 0, "tpri" },
};
static const struct rtos_cyc_cfg cycs[] = { { 1, TA_NULL, 0, cyc, 1, 0, "cyc" } };
static const struct rtos_cfg cfg = {
	.name = "mtx", .tasks = RTOS_TABLE(tasks), .mtxs = RTOS_TABLE(mtxs), .cycs = RTOS_TABLE(cycs),
};

static const struct rtos_mtx_cfg bad_mtxs[] = { { 1, TA_CEILING, 0, "noceil" } };
static const struct rtos_cfg bad_cfg = { .name = "bad", .mtxs = RTOS_TABLE(bad_mtxs) };

int main(void)
{
	bool said_so = true;

	tap_plan(20);
	rt_log_reset();
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(100 * MS);
	ok(p_ceil == 4 && p_after == 5, "TA_CEILING: the holder runs at the ceiling (4), then at its base (5)");
	is_int(r_ilu, E_ILUSE, "loc_mtx with a base priority above the ceiling: E_ILUSE");
	is_int(r_chg, E_ILUSE, "chg_pri above the ceiling of a held mutex: E_ILUSE");
	is_int(r_obj[0], E_OBJ, "locking a mutex one holds: E_OBJ");
	is_int(r_obj[1], E_OBJ, "unlocking other than the last locked: E_OBJ");
	is_int(p_low_inh, 3, "TA_INHERIT: the holder inherits its waiter's priority");
	ok(strstr(rt_log_text(), "H-wait L-unlock H-got M-run L-done |") != NULL,
	   "a middle-priority task waits for the holder's unlock; the waiter gets the mutex at once (%s)", rt_log_text());
	is_int(p_chain, 3, "inheritance follows a chain of holders");
	is_int(p_chain_after, 10, "and is gone after the unlock");
	ok(p_d_during == 3 && r_tmo == E_TMOUT && p_d_after == 10,
	   "a timed-out waiter takes its priority back from the holder (%d, %d, %d)", p_d_during, r_tmo, p_d_after);
	ok(w_result[0] == E_OK && strstr(rt_log_text(), "| W0") != NULL, "ext_tsk of the holder hands the mutex to the waiter");
	ok(r_obj[2] == E_OBJ, "unlocking another task's mutex: E_OBJ");
	ok(r_ref == E_OK && ref.htskid == T_EXIT && ref.wtskid == T_W1, "ref_mtx: holder and first waiter");
	ok(r_ter == E_OK && w_result[1] == E_OK, "ter_tsk of the holder hands the mutex to the waiter");
	ok(r_ini == E_OK && w_result[2] == E_DLT && r_obj[3] == E_OBJ, "ini_mtx: the waiter gets E_DLT, the holder loses it");
	ok(r_ctx == E_CTX && r_id[0] == E_ID && r_id[1] == E_ID, "ploc_mtx from a handler: E_CTX; bad IDs: E_ID");
	is_int(rtos_host_bug_count(), 0, "no bug reports");
	rtos_host_shutdown();
	is_int(rt_boot_refused(&bad_cfg, &said_so), E_PAR, "boot refuses TA_CEILING with ceilpri 0");
	ok(said_so, "...printing its boot error on stderr");
	rtos_host_shutdown();
	return tap_done();
}
