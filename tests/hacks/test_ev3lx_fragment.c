/*
 * test_ev3lx_fragment — the library's static-API fragment (cfg/ev3lx.cfg) is
 * the configuration the host boots: ev3cfg --library read it into the
 * kernel_cfg.h every library source takes its IDs from and into the table
 * ev3lx_cfg (kernel_cfg.c, included here); every task, semaphore, interrupt
 * line, ISR, initialisation and termination routine and extended service
 * call of that table is, with the same ID, routine and parameters, one of the
 * C tables the host kernel boots (ev3api_cfg and what it includes), and
 * nothing of those is missing from the fragment.
 */
#include <string.h>
#include "tap.h"
#include "rtos_cfg.h"
#include <linux_compat/config.h>
#include "ev3api_routines.h"
#include "kernel_cfg.c"

extern const struct rtos_cfg ev3api_cfg;

#define MAX_ROWS 128

/* Every row of one kind in a configuration and what it includes. */
struct rows {
	const struct rtos_task_cfg *tasks[MAX_ROWS]; int ntasks;
	const struct rtos_sem_cfg *sems[MAX_ROWS]; int nsems;
	const struct rtos_int_cfg *ints[MAX_ROWS]; int nints;
	const struct rtos_isr_cfg *isrs[MAX_ROWS]; int nisrs;
	const struct rtos_ini_cfg *inis[MAX_ROWS]; int ninis;
	const struct rtos_ter_cfg *ters[MAX_ROWS]; int nters;
	const struct rtos_svc_cfg *svcs[MAX_ROWS]; int nsvcs;
	int other;	/* rows of kinds the library does not create */
};

/* Collects cfg's rows and its includes' into r. */
static void collect(const struct rtos_cfg *cfg, struct rows *r)
{
	for (uint_t i = 0; i < cfg->ntasks && r->ntasks < MAX_ROWS; i++)
		r->tasks[r->ntasks++] = &cfg->tasks[i];
	for (uint_t i = 0; i < cfg->nsems && r->nsems < MAX_ROWS; i++)
		r->sems[r->nsems++] = &cfg->sems[i];
	for (uint_t i = 0; i < cfg->nints && r->nints < MAX_ROWS; i++)
		r->ints[r->nints++] = &cfg->ints[i];
	for (uint_t i = 0; i < cfg->nisrs && r->nisrs < MAX_ROWS; i++)
		r->isrs[r->nisrs++] = &cfg->isrs[i];
	for (uint_t i = 0; i < cfg->ninis && r->ninis < MAX_ROWS; i++)
		r->inis[r->ninis++] = &cfg->inis[i];
	for (uint_t i = 0; i < cfg->nters && r->nters < MAX_ROWS; i++)
		r->ters[r->nters++] = &cfg->ters[i];
	for (uint_t i = 0; i < cfg->nsvcs && r->nsvcs < MAX_ROWS; i++)
		r->svcs[r->nsvcs++] = &cfg->svcs[i];
	r->other += (int)(cfg->nflgs + cfg->ncycs + cfg->nalms + cfg->ndtqs + cfg->npdqs + cfg->nmtxs);
	for (const struct rtos_cfg *const *inc = cfg->includes; inc != NULL && *inc != NULL; inc++)
		collect(*inc, r);
}

/* The task of the C tables with t's ID, or NULL. */
static const struct rtos_task_cfg *task_by_id(const struct rows *r, ID id)
{
	for (int i = 0; i < r->ntasks; i++)
		if (r->tasks[i]->tskid == id)
			return r->tasks[i];
	return NULL;
}

int main(void)
{
	static struct rows frag, host;
	int same;

	collect(&ev3lx_cfg, &frag);
	collect(&ev3api_cfg, &host);
	tap_plan(17);

	/* the IDs the library is compiled with are the configurator's */
#ifdef EV3CFG_LIBRARY_KERNEL_CFG_H
	ok(1, "linux_compat/config.h takes its IDs from ev3cfg --library's kernel_cfg.h");
#else
	ok(0, "linux_compat/config.h takes its IDs from ev3cfg --library's kernel_cfg.h");
#endif
	is_int(EV3LX_LIB_NUM_TSKID, frag.ntasks, "kernel_cfg.h counts the fragment's %d tasks", frag.ntasks);
	is_int(LX_WORKER_TSKID, TNUM_TSKID - EV3LX_LIB_NUM_TSKID + 1,
	       "the worker is the fragment's first task, first of the library's block at the top");
	is_int(EV3_BUTTON_TSKID, TNUM_TSKID, "the button task is its last, TNUM_TSKID");
	is_int(EV3_BUTTON_SEMID, TNUM_SEMID, "the button semaphore is TNUM_SEMID");

	/* tasks: same IDs, bodies, parameters and domains */
	is_int(frag.ntasks, host.ntasks, "as many tasks in the fragment as the host boots (%d)", host.ntasks);
	same = 0;
	for (int i = 0; i < frag.ntasks; i++) {
		const struct rtos_task_cfg *f = frag.tasks[i], *h = task_by_id(&host, f->tskid);

		same += h != NULL && h->task == f->task && h->exinf == f->exinf && h->itskpri == f->itskpri &&
			h->stksz == f->stksz && h->tskatr == f->tskatr && h->domid == f->domid;
	}
	is_int(same, frag.ntasks, "every task of the fragment is the host's, ID, body, exinf, priority, stack, domain");

	/* the semaphore */
	ok(frag.nsems == 1 && host.nsems == 1 && frag.sems[0]->semid == host.sems[0]->semid &&
	   frag.sems[0]->sematr == host.sems[0]->sematr && frag.sems[0]->isemcnt == host.sems[0]->isemcnt &&
	   frag.sems[0]->maxsem == host.sems[0]->maxsem, "one semaphore, the host's");

	/* interrupt lines and their ISRs */
	same = frag.nints == host.nints;
	for (int i = 0; same && i < frag.nints; i++) {
		int found = 0;

		for (int j = 0; j < host.nints; j++)
			found |= host.ints[j]->intno == frag.ints[i]->intno && host.ints[j]->intpri == frag.ints[i]->intpri &&
				 host.ints[j]->intatr == frag.ints[i]->intatr;
		same = found;
	}
	ok(same, "the same %d interrupt lines at the same priority (CFG_INT)", frag.nints);
	for (int i = 0; i < frag.nints; i++)
		if (frag.ints[i]->intpri != INTPRI_TICK)
			same = 0;
	ok(same, "every Linux line at the tick's priority, INTPRI_TICK = %d", INTPRI_TICK);
	same = frag.nisrs == host.nisrs;
	for (int i = 0; same && i < frag.nisrs; i++) {
		int found = 0;

		for (int j = 0; j < host.nisrs; j++)
			found |= host.isrs[j]->intno == frag.isrs[i]->intno && host.isrs[j]->isr == frag.isrs[i]->isr &&
				 host.isrs[j]->exinf == frag.isrs[i]->exinf && host.isrs[j]->isrpri == frag.isrs[i]->isrpri;
		same = found;
	}
	ok(same, "the same %d ISRs: line, routine, exinf, order", frag.nisrs);
	same = 1;
	for (int i = 0; i < frag.nints; i++) {
		int has = 0;

		for (int j = 0; j < frag.nisrs; j++)
			has |= frag.isrs[j]->intno == frag.ints[i]->intno;
		same &= has;
	}
	ok(same, "every line the fragment configures has its routine");

	/* initialisation and termination routines */
	same = frag.ninis == host.ninis;
	for (int i = 0; same && i < frag.ninis; i++) {
		int found = 0;

		for (int j = 0; j < host.ninis; j++)
			found |= host.inis[j]->inirtn == frag.inis[i]->inirtn && host.inis[j]->exinf == frag.inis[i]->exinf;
		same = found;
	}
	ok(same, "the same %d initialisation routines (ATT_INI)", frag.ninis);
	ok(frag.nters == host.nters && frag.nters == 1 && frag.ters[0]->terrtn == host.ters[0]->terrtn,
	   "the same termination routine (ATT_TER)");

	/* extended service calls */
	same = frag.nsvcs == host.nsvcs;
	for (int i = 0; same && i < frag.nsvcs; i++) {
		int found = 0;

		for (int j = 0; j < host.nsvcs; j++)
			found |= host.svcs[j]->fncd == frag.svcs[i]->fncd && host.svcs[j]->extsvc == frag.svcs[i]->extsvc &&
				 host.svcs[j]->stksz == frag.svcs[i]->stksz;
		same = found;
	}
	ok(same, "the same %d extended service calls: function code, routine, stack", frag.nsvcs);
	same = 1;
	for (int i = 0; i < frag.nsvcs; i++)
		same &= frag.svcs[i]->fncd >= EV3LX_FNCD_BASE && frag.svcs[i]->fncd > 42;
	ok(same, "every function code from EV3LX_FNCD_BASE (%d) on, clear of EV3RT's 1..42", EV3LX_FNCD_BASE);
	is_int(frag.other + host.other, 0, "no object of another kind on either side");
	return tap_done();
}
