/*
 * boot.c — boot and shutdown: checks the static configuration (with its
 * INCLUDEs) row by row, creates the objects, runs the ATT_INI routines and
 * activates TA_ACT tasks.  A bad row is a boot error naming the
 * configuration, the table and the row, and an E_* return.  Shutdown runs
 * the ATT_TER routines (reverse order) while the system still exists, then
 * frees everything.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kernel_impl.h"

#define MAX_CONFIGS        32
#define MAX_INCLUDE_DEPTH  8

bool kernel_booted;
bool terminating;

static const struct rtos_cfg *configs[MAX_CONFIGS];
static uint_t nconfigs;
static char boot_error[512];

/* Records and prints a boot error for one row; returns ercd. */
static ER __attribute__((format(printf, 6, 7)))
boot_fail(const struct rtos_cfg *cfg, const char *table, uint_t row, const char *row_name,
	  ER ercd, const char *fmt, ...)
{
	char msg[256];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	snprintf(boot_error, sizeof(boot_error), "config \"%s\" %s[%u]%s%s%s: %s (%s)",
		 cfg != NULL && cfg->name != NULL ? cfg->name : "?", table, row,
		 row_name != NULL ? " \"" : "", row_name != NULL ? row_name : "",
		 row_name != NULL ? "\"" : "", msg, ercd_name(ercd));
	fflush(stdout);
	fprintf(stderr, "rtos_host_boot: %s\n", boot_error);
	printf("# rtos_host_boot: %s\n", boot_error);
	fflush(NULL);
	return ercd;
}

/* Text of the last boot error (empty after a successful boot). */
const char *rtos_host_boot_error(void)
{
	return boot_error;
}

/* Collects cfg and its includes depth-first; a configuration may appear only once. */
static ER collect_configs(const struct rtos_cfg *cfg, const struct rtos_cfg *parent, uint_t depth)
{
	ER ercd;

	if (depth > MAX_INCLUDE_DEPTH)
		return boot_fail(parent, "INCLUDE", 0, cfg->name, E_PAR,
				 "includes nested deeper than %d (a cycle?)", MAX_INCLUDE_DEPTH);
	for (uint_t i = 0; i < nconfigs; i++)
		if (configs[i] == cfg)
			return boot_fail(parent, "INCLUDE", 0, cfg->name, E_OBJ,
					 "configuration included twice");
	if (nconfigs == MAX_CONFIGS)
		return boot_fail(parent, "INCLUDE", 0, cfg->name, E_NOMEM,
				 "more than %d configurations", MAX_CONFIGS);
	configs[nconfigs++] = cfg;
	for (uint_t i = 0; cfg->includes != NULL && cfg->includes[i] != NULL; i++)
		if ((ercd = collect_configs(cfg->includes[i], cfg, depth + 1)) != E_OK)
			return ercd;
	return E_OK;
}

/* Checks and applies the CFG_INT rows of one configuration. */
static ER check_ints(const struct rtos_cfg *cfg)
{
	for (uint_t i = 0; i < cfg->nints; i++) {
		const struct rtos_int_cfg *r = &cfg->ints[i];

		if (r->intno > TMAX_INTNO)
			return boot_fail(cfg, "CFG_INT", i, NULL, E_PAR, "intno %u out of range 0..%u",
					 r->intno, TMAX_INTNO);
		if (r->intatr & ~(ATR)(TA_ENAINT | TA_EDGE))
			return boot_fail(cfg, "CFG_INT", i, NULL, E_RSATR, "intno %u: unknown attribute bits 0x%x",
					 r->intno, r->intatr & ~(ATR)(TA_ENAINT | TA_EDGE));
		if (r->intpri < TMIN_INTPRI || r->intpri > TMAX_INTPRI)
			return boot_fail(cfg, "CFG_INT", i, NULL, E_PAR, "intno %u: intpri %d out of range %d..%d",
					 r->intno, r->intpri, TMIN_INTPRI, TMAX_INTPRI);
		if (r->intno == INTNO_TICK) {
			if (r->intpri != INTPRI_TICK)
				return boot_fail(cfg, "CFG_INT", i, NULL, E_OBJ,
						 "intno %u is the kernel tick (priority %d); it needs no CFG_INT",
						 r->intno, INTPRI_TICK);
			continue;
		}
		if (irq_configured(r->intno))
			return boot_fail(cfg, "CFG_INT", i, NULL, E_OBJ, "intno %u configured twice", r->intno);
		irq_configure(r->intno, r->intatr, r->intpri);
	}
	return E_OK;
}

/* Checks the CRE_TSK rows and allocates their control blocks. */
static ER check_tasks(const struct rtos_cfg *cfg)
{
	for (uint_t i = 0; i < cfg->ntasks; i++) {
		const struct rtos_task_cfg *r = &cfg->tasks[i];
		struct tcb *t;

		if (r->tskid < 1 || r->tskid > TNUM_TSKID)
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_ID, "tskid %d out of range 1..%d",
					 r->tskid, TNUM_TSKID);
		if (tcb_table[r->tskid] != NULL)
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_OBJ, "tskid %d already used by \"%s\" (config \"%s\")",
					 r->tskid, tcb_table[r->tskid]->cfg->name ? tcb_table[r->tskid]->cfg->name : "?",
					 tcb_table[r->tskid]->cfg_name);
		if (r->tskatr & ~(ATR)TA_ACT)
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_RSATR, "unknown attribute bits 0x%x",
					 r->tskatr & ~(ATR)TA_ACT);
		if (r->task == NULL)
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_PAR, "NULL task function");
		if (r->itskpri < TMIN_TPRI || r->itskpri > TMAX_TPRI)
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_PAR, "itskpri %d out of range %d..%d",
					 r->itskpri, TMIN_TPRI, TMAX_TPRI);
		if (r->stksz == 0)
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_PAR, "zero stack size");
		if (r->domid != TDOM_KERNEL && (r->domid < 1 || r->domid > TNUM_DOMID))
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_ID,
					 "domid %d is neither TDOM_KERNEL nor 1..%d", r->domid, TNUM_DOMID);
		if ((t = calloc(1, sizeof(*t))) == NULL)
			return boot_fail(cfg, "CRE_TSK", i, r->name, E_NOMEM, "out of memory");
		t->cfg = r;
		t->cfg_name = cfg->name ? cfg->name : "?";
		t->id = r->tskid;
		tcb_table[r->tskid] = t;
	}
	return E_OK;
}

/* Checks the CRE_SEM rows and creates the semaphores. */
static ER check_sems(const struct rtos_cfg *cfg)
{
	for (uint_t i = 0; i < cfg->nsems; i++) {
		const struct rtos_sem_cfg *r = &cfg->sems[i];
		struct semcb *s;

		if (r->semid < 1 || r->semid > TNUM_SEMID)
			return boot_fail(cfg, "CRE_SEM", i, r->name, E_ID, "semid %d out of range 1..%d",
					 r->semid, TNUM_SEMID);
		if (sem_table[r->semid] != NULL)
			return boot_fail(cfg, "CRE_SEM", i, r->name, E_OBJ, "semid %d already used", r->semid);
		if (r->sematr & ~(ATR)TA_TPRI)
			return boot_fail(cfg, "CRE_SEM", i, r->name, E_RSATR, "unknown attribute bits 0x%x",
					 r->sematr & ~(ATR)TA_TPRI);
		if (r->maxsem == 0)
			return boot_fail(cfg, "CRE_SEM", i, r->name, E_PAR, "maxsem is 0");
		if (r->isemcnt > r->maxsem)
			return boot_fail(cfg, "CRE_SEM", i, r->name, E_PAR, "isemcnt %u > maxsem %u",
					 r->isemcnt, r->maxsem);
		if ((s = calloc(1, sizeof(*s))) == NULL)
			return boot_fail(cfg, "CRE_SEM", i, r->name, E_NOMEM, "out of memory");
		s->cfg = r;
		s->cnt = r->isemcnt;
		queue_init(&s->wq);
		sem_table[r->semid] = s;
	}
	return E_OK;
}

/* Checks the CRE_FLG rows and creates the eventflags. */
static ER check_flgs(const struct rtos_cfg *cfg)
{
	const ATR known = TA_TPRI | TA_WMUL | TA_CLR;

	for (uint_t i = 0; i < cfg->nflgs; i++) {
		const struct rtos_flg_cfg *r = &cfg->flgs[i];
		struct flgcb *f;

		if (r->flgid < 1 || r->flgid > TNUM_FLGID)
			return boot_fail(cfg, "CRE_FLG", i, r->name, E_ID, "flgid %d out of range 1..%d",
					 r->flgid, TNUM_FLGID);
		if (flg_table[r->flgid] != NULL)
			return boot_fail(cfg, "CRE_FLG", i, r->name, E_OBJ, "flgid %d already used", r->flgid);
		if (r->flgatr & ~known)
			return boot_fail(cfg, "CRE_FLG", i, r->name, E_RSATR, "unknown attribute bits 0x%x",
					 r->flgatr & ~known);
		if ((f = calloc(1, sizeof(*f))) == NULL)
			return boot_fail(cfg, "CRE_FLG", i, r->name, E_NOMEM, "out of memory");
		f->cfg = r;
		f->ptn = r->iflgptn;
		queue_init(&f->wq);
		flg_table[r->flgid] = f;
	}
	return E_OK;
}

/* Checks the CRE_DTQ, CRE_PDQ and CRE_MTX rows and creates the objects. */
static ER check_dtqs_pdqs_mtxs(const struct rtos_cfg *cfg)
{
	for (uint_t i = 0; i < cfg->ndtqs; i++) {
		const struct rtos_dtq_cfg *r = &cfg->dtqs[i];

		if (r->dtqid < 1 || r->dtqid > TNUM_DTQID)
			return boot_fail(cfg, "CRE_DTQ", i, r->name, E_ID, "dtqid %d out of range 1..%d",
					 r->dtqid, TNUM_DTQID);
		if (dtq_table[r->dtqid] != NULL)
			return boot_fail(cfg, "CRE_DTQ", i, r->name, E_OBJ, "dtqid %d already used by \"%s\"",
					 r->dtqid, dtq_table[r->dtqid]->cfg->name ? dtq_table[r->dtqid]->cfg->name : "?");
		if (r->dtqatr & ~(ATR)TA_TPRI)
			return boot_fail(cfg, "CRE_DTQ", i, r->name, E_RSATR, "unknown attribute bits 0x%x",
					 r->dtqatr & ~(ATR)TA_TPRI);
		if (dtq_create(r) != E_OK)
			return boot_fail(cfg, "CRE_DTQ", i, r->name, E_NOMEM, "out of memory");
	}
	for (uint_t i = 0; i < cfg->npdqs; i++) {
		const struct rtos_pdq_cfg *r = &cfg->pdqs[i];

		if (r->pdqid < 1 || r->pdqid > TNUM_PDQID)
			return boot_fail(cfg, "CRE_PDQ", i, r->name, E_ID, "pdqid %d out of range 1..%d",
					 r->pdqid, TNUM_PDQID);
		if (pdq_table[r->pdqid] != NULL)
			return boot_fail(cfg, "CRE_PDQ", i, r->name, E_OBJ, "pdqid %d already used by \"%s\"",
					 r->pdqid, pdq_table[r->pdqid]->cfg->name ? pdq_table[r->pdqid]->cfg->name : "?");
		if (r->pdqatr & ~(ATR)TA_TPRI)
			return boot_fail(cfg, "CRE_PDQ", i, r->name, E_RSATR, "unknown attribute bits 0x%x",
					 r->pdqatr & ~(ATR)TA_TPRI);
		if (r->maxdpri < TMIN_DPRI || r->maxdpri > TMAX_DPRI)
			return boot_fail(cfg, "CRE_PDQ", i, r->name, E_PAR, "maxdpri %d out of range %d..%d",
					 r->maxdpri, TMIN_DPRI, TMAX_DPRI);
		if (pdq_create(r) != E_OK)
			return boot_fail(cfg, "CRE_PDQ", i, r->name, E_NOMEM, "out of memory");
	}
	for (uint_t i = 0; i < cfg->nmtxs; i++) {
		const struct rtos_mtx_cfg *r = &cfg->mtxs[i];

		if (r->mtxid < 1 || r->mtxid > TNUM_MTXID)
			return boot_fail(cfg, "CRE_MTX", i, r->name, E_ID, "mtxid %d out of range 1..%d",
					 r->mtxid, TNUM_MTXID);
		if (mtx_table[r->mtxid] != NULL)
			return boot_fail(cfg, "CRE_MTX", i, r->name, E_OBJ, "mtxid %d already used by \"%s\"",
					 r->mtxid, mtx_table[r->mtxid]->cfg->name ? mtx_table[r->mtxid]->cfg->name : "?");
		if (r->mtxatr != TA_NULL && r->mtxatr != TA_TPRI && r->mtxatr != TA_CEILING &&
		    r->mtxatr != TA_INHERIT)
			return boot_fail(cfg, "CRE_MTX", i, r->name, E_RSATR, "unknown attribute 0x%x", r->mtxatr);
		if (r->mtxatr == TA_CEILING && (r->ceilpri < TMIN_TPRI || r->ceilpri > TMAX_TPRI))
			return boot_fail(cfg, "CRE_MTX", i, r->name, E_PAR, "ceilpri %d out of range %d..%d",
					 r->ceilpri, TMIN_TPRI, TMAX_TPRI);
		if (mtx_create(r) != E_OK)
			return boot_fail(cfg, "CRE_MTX", i, r->name, E_NOMEM, "out of memory");
	}
	return E_OK;
}

/* Checks the CRE_CYC and CRE_ALM rows and registers the handlers. */
static ER check_cycs_alms(const struct rtos_cfg *cfg)
{
	/* HRP3 has no TA_PHS and counts in us up to its own TMAX_RELTIM
	 * (ev3rt-git/ev3rt-hrp3, kernel/cyclic.trb and include/t_stddef.h). */
	bool hrp3 = cfg->profile == RTOS_PROFILE_HRP3;
	const ATR known = hrp3 ? TA_STA : TA_STA | TA_PHS;
	const uint32_t max = hrp3 ? HRP3_TMAX_RELTIM : TMAX_RELTIM;
	const char *unit = hrp3 ? "us" : "ms";

	if (cfg->profile > RTOS_PROFILE_HRP3)
		return boot_fail(cfg, "profile", 0, cfg->name, E_PAR, "unknown kernel profile %u", cfg->profile);
	for (uint_t i = 0; i < cfg->ncycs; i++) {
		const struct rtos_cyc_cfg *r = &cfg->cycs[i];

		if (r->cycid < 1 || r->cycid > TNUM_CYCID)
			return boot_fail(cfg, "CRE_CYC", i, r->name, E_ID, "cycid %d out of range 1..%d",
					 r->cycid, TNUM_CYCID);
		if (cyc_exists(r->cycid))
			return boot_fail(cfg, "CRE_CYC", i, r->name, E_OBJ, "cycid %d already used", r->cycid);
		if (r->cycatr & ~known)
			return boot_fail(cfg, "CRE_CYC", i, r->name, E_RSATR, "unknown attribute bits 0x%x",
					 r->cycatr & ~known);
		if (r->cychdr == NULL)
			return boot_fail(cfg, "CRE_CYC", i, r->name, E_PAR, "NULL handler");
		if (r->cyctim == 0 || r->cyctim > max)
			return boot_fail(cfg, "CRE_CYC", i, r->name, E_PAR, "cyctim %u out of range 1..%u %s",
					 r->cyctim, max, unit);
		if (r->cycphs > max)
			return boot_fail(cfg, "CRE_CYC", i, r->name, E_PAR, "cycphs %u out of range 0..%u %s",
					 r->cycphs, max, unit);
		if (cyc_register(r, hrp3 ? 1000U : 1000000U) != E_OK)
			return boot_fail(cfg, "CRE_CYC", i, r->name, E_NOMEM, "out of memory");
	}
	for (uint_t i = 0; i < cfg->nalms; i++) {
		const struct rtos_alm_cfg *r = &cfg->alms[i];

		if (r->almid < 1 || r->almid > TNUM_ALMID)
			return boot_fail(cfg, "CRE_ALM", i, r->name, E_ID, "almid %d out of range 1..%d",
					 r->almid, TNUM_ALMID);
		if (alm_exists(r->almid))
			return boot_fail(cfg, "CRE_ALM", i, r->name, E_OBJ, "almid %d already used", r->almid);
		if (r->almatr != TA_NULL)
			return boot_fail(cfg, "CRE_ALM", i, r->name, E_RSATR, "unknown attribute bits 0x%x",
					 r->almatr);
		if (r->almhdr == NULL)
			return boot_fail(cfg, "CRE_ALM", i, r->name, E_PAR, "NULL handler");
		if (alm_register(r) != E_OK)
			return boot_fail(cfg, "CRE_ALM", i, r->name, E_NOMEM, "out of memory");
	}
	return E_OK;
}

/* True if configuration cfg declares a function-code range. */
static bool svc_range_declared(const struct rtos_cfg *cfg)
{
	return cfg->svc_count != 0;
}

/*
 * Checks the function-code range cfg declares: inside 1..TNUM_FNCD and
 * disjoint from the ranges of the configurations checked before it (index <
 * self), whose name the error gives.
 */
static ER check_svc_range(uint_t self)
{
	const struct rtos_cfg *cfg = configs[self];
	long first = cfg->svc_first, last = first + (long)cfg->svc_count - 1;

	if (!svc_range_declared(cfg))
		return E_OK;
	if (first < 1 || last > TNUM_FNCD)
		return boot_fail(cfg, "DEF_SVC", 0, NULL, E_PAR,
				 "function codes %ld..%ld out of range 1..%d (TNUM_FNCD is a build setting)",
				 first, last, TNUM_FNCD);
	for (uint_t i = 0; i < self; i++) {
		const struct rtos_cfg *other = configs[i];
		long ofirst = other->svc_first, olast = ofirst + (long)other->svc_count - 1;

		if (svc_range_declared(other) && first <= olast && ofirst <= last)
			return boot_fail(cfg, "DEF_SVC", 0, NULL, E_OBJ,
					 "function codes %ld..%ld overlap those of config \"%s\" (%ld..%ld)",
					 first, last, other->name != NULL ? other->name : "?", ofirst, olast);
	}
	return E_OK;
}

/* The configuration that defined fncd (boot), for the duplicate report. */
static const struct rtos_cfg *svc_owner(FN fncd)
{
	for (uint_t c = 0; c < nconfigs; c++)
		for (uint_t i = 0; i < configs[c]->nsvcs; i++)
			if (configs[c]->svcs[i].fncd == fncd)
				return configs[c];
	return NULL;
}

/* Checks ATT_ISR, DEF_SVC, memory-region and ATT_INI rows and applies them. */
static ER check_isrs_svcs_mems_inis(const struct rtos_cfg *cfg)
{
	for (uint_t i = 0; i < cfg->nisrs; i++) {
		const struct rtos_isr_cfg *r = &cfg->isrs[i];

		if (r->intno > TMAX_INTNO)
			return boot_fail(cfg, "ATT_ISR", i, NULL, E_PAR, "intno %u out of range 0..%u",
					 r->intno, TMAX_INTNO);
		if (!irq_configured(r->intno))
			return boot_fail(cfg, "ATT_ISR", i, NULL, E_OBJ, "intno %u has no CFG_INT", r->intno);
		if (r->isratr != TA_NULL)
			return boot_fail(cfg, "ATT_ISR", i, NULL, E_RSATR, "intno %u: unknown attribute bits 0x%x",
					 r->intno, r->isratr);
		if (r->isr == NULL)
			return boot_fail(cfg, "ATT_ISR", i, NULL, E_PAR, "intno %u: NULL ISR", r->intno);
		if (r->isrpri < TMIN_ISRPRI || r->isrpri > TMAX_ISRPRI)
			return boot_fail(cfg, "ATT_ISR", i, NULL, E_PAR, "intno %u: isrpri %d out of range %d..%d",
					 r->intno, r->isrpri, TMIN_ISRPRI, TMAX_ISRPRI);
		if (irq_attach(r) != E_OK)
			return boot_fail(cfg, "ATT_ISR", i, NULL, E_NOMEM, "out of memory");
	}
	for (uint_t i = 0; i < cfg->nsvcs; i++) {
		const struct rtos_svc_cfg *r = &cfg->svcs[i];

		if (r->fncd < 1 || r->fncd > TNUM_FNCD)
			return boot_fail(cfg, "DEF_SVC", i, NULL, E_PAR, "fncd %d out of range 1..%d",
					 r->fncd, TNUM_FNCD);
		if (svc_range_declared(cfg) &&
		    (r->fncd < cfg->svc_first || r->fncd > cfg->svc_first + (FN)cfg->svc_count - 1))
			return boot_fail(cfg, "DEF_SVC", i, NULL, E_PAR, "fncd %d outside the configuration's codes %d..%d",
					 r->fncd, cfg->svc_first, cfg->svc_first + (FN)cfg->svc_count - 1);
		if (svc_defined(r->fncd)) {
			const struct rtos_cfg *owner = svc_owner(r->fncd);

			return boot_fail(cfg, "DEF_SVC", i, NULL, E_OBJ, "fncd %d already defined by config \"%s\"",
					 r->fncd, owner != NULL && owner->name != NULL ? owner->name : "?");
		}
		if (r->extsvc == NULL)
			return boot_fail(cfg, "DEF_SVC", i, NULL, E_PAR, "fncd %d: NULL routine", r->fncd);
		svc_define(r->fncd, r->extsvc);
	}
	for (uint_t i = 0; i < cfg->nmems; i++) {
		const struct rtos_mem_cfg *r = &cfg->mems[i];
		const MODE known = TPM_READ | TPM_WRITE | TPM_EXEC;

		if (r->domid < 1 || r->domid > TNUM_DOMID)
			return boot_fail(cfg, "ATT_MEM", i, r->name, E_ID, "domid %d out of range 1..%d",
					 r->domid, TNUM_DOMID);
		if (r->base == NULL || r->size == 0 || r->size > UINTPTR_MAX - (uintptr_t)r->base)
			return boot_fail(cfg, "ATT_MEM", i, r->name, E_PAR, "empty, NULL or wrapping region");
		if (r->access == 0 || (r->access & ~known))
			return boot_fail(cfg, "ATT_MEM", i, r->name, E_RSATR, "access 0x%x is not a TPM_ set",
					 r->access);
		if (mem_add_region(r) != E_OK)
			return boot_fail(cfg, "ATT_MEM", i, r->name, E_NOMEM, "out of memory");
	}
	for (uint_t i = 0; i < cfg->ninis; i++)
		if (cfg->inis[i].inirtn == NULL)
			return boot_fail(cfg, "ATT_INI", i, NULL, E_PAR, "NULL initialisation routine");
	for (uint_t i = 0; i < cfg->nters; i++)
		if (cfg->ters[i].terrtn == NULL)
			return boot_fail(cfg, "ATT_TER", i, NULL, E_PAR, "NULL termination routine");
	return E_OK;
}

/* Frees every kernel object and resets the clock, lines and events. */
static void free_objects(void)
{
	task_destroy_all();
	for (ID id = 0; id <= TNUM_SEMID; id++) {
		free(sem_table[id]);
		sem_table[id] = NULL;
	}
	for (ID id = 0; id <= TNUM_FLGID; id++) {
		free(flg_table[id]);
		flg_table[id] = NULL;
	}
	dtq_pdq_mtx_reset();
	cyc_reset();
	svc_reset();
	mem_reset();
	irq_reset();
	event_reset();
	time_reset();
	paused_task = NULL;
	run_active = false;
	kernel_exited = false;
}

/*
 * Runs the ATT_TER routines as ext_ker does: the reverse of the order in
 * which they were registered (configurations and rows backwards, so a
 * library initialised after the application is terminated before it).
 * Unlike HRP2, where dispatching has stopped, they run in the harness's
 * non-task context with the CPU unlocked and the system intact, so that a
 * routine can hand work to a task with an i-call and run the system
 * (rtos_host_run_*) until that work is done.
 */
static void run_termination_routines(void)
{
	terminating = true;
	if (trace_on())
		rtos_host_trace("kernel", "shutdown");
	for (uint_t c = nconfigs; c-- > 0;)
		for (uint_t i = configs[c]->nters; i-- > 0;)
			configs[c]->ters[i].terrtn(configs[c]->ters[i].exinf);
	terminating = false;
}

static const char *boot_args;    /* the boot loader's command line, kept across boots */

/* Sets the command line later boots see. */
void rtos_host_set_boot_args(const char *args)
{
	boot_args = args;
}

/* The command line, "" if none was set. */
const char *rtos_host_boot_args(void)
{
	return boot_args != NULL ? boot_args : "";
}

/* Runs the ATT_TER routines, then frees task stacks and forgets objects and events. */
void rtos_host_shutdown(void)
{
	if (cpu.kind != EXEC_IDLE || cpu.isr_depth != 0 || run_active || terminating) {
		rtos_host_bug("harness", "rtos_host_shutdown from inside the kernel (%s)",
			      rtos_host_context_name());
		return;
	}
	if (kernel_booted)
		run_termination_routines();
	free_objects();
	kernel_booted = false;
}

/* Checks cfg with its includes, creates the objects, runs ATT_INI, activates TA_ACT tasks. */
ER rtos_host_boot(const struct rtos_cfg *cfg)
{
	ER ercd = E_OK;

	if (cpu.kind != EXEC_IDLE || cpu.isr_depth != 0 || run_active || terminating) {
		rtos_host_bug("harness", "rtos_host_boot from inside the kernel (%s)", rtos_host_context_name());
		return E_CTX;
	}
	rtos_host_crash_install();
	free_objects();
	kernel_booted = false;
	/* kept through shutdown: a program's exit status still says why its system ended */
	kernel_stalled = false;
	kernel_stack_overrun = false;
	bug_reset();
	syslog_reset();
	boot_error[0] = '\0';
	nconfigs = 0;
	if (cfg == NULL)
		return boot_fail(NULL, "rtos_cfg", 0, NULL, E_PAR, "NULL configuration");
	irq_configure(INTNO_TICK, TA_ENAINT, INTPRI_TICK);
	ercd = collect_configs(cfg, cfg, 0);
	for (uint_t i = 0; ercd == E_OK && i < nconfigs; i++)
		ercd = check_ints(configs[i]);
	for (uint_t i = 0; ercd == E_OK && i < nconfigs; i++)
		ercd = check_svc_range(i);
	for (uint_t i = 0; ercd == E_OK && i < nconfigs; i++)
		if ((ercd = check_tasks(configs[i])) == E_OK && (ercd = check_sems(configs[i])) == E_OK &&
		    (ercd = check_flgs(configs[i])) == E_OK && (ercd = check_dtqs_pdqs_mtxs(configs[i])) == E_OK &&
		    (ercd = check_cycs_alms(configs[i])) == E_OK)
			ercd = check_isrs_svcs_mems_inis(configs[i]);
	if (ercd == E_OK && (ercd = task_create_all()) != E_OK)
		boot_fail(cfg, "CRE_TSK", 0, NULL, ercd, "cannot allocate task stacks");
	if (ercd != E_OK) {
		free_objects();
		return ercd;
	}
	kernel_booted = true;
	for (ID id = 1; id <= TNUM_TSKID; id++)
		if (tcb_table[id] != NULL && (tcb_table[id]->cfg->tskatr & TA_ACT))
			task_activate(tcb_table[id]);
	cyc_create_all();
	time_start();
	/* ATT_INI routines run in non-task context with the CPU locked, as in TOPPERS. */
	cpu.kind = EXEC_INIT;
	for (uint_t c = 0; c < nconfigs; c++) {
		for (uint_t i = 0; i < configs[c]->ninis; i++) {
			cpu.locked = true;
			configs[c]->inis[i].inirtn(configs[c]->inis[i].exinf);
		}
	}
	cpu.locked = false;
	cpu.kind = EXEC_IDLE;
	if (trace_on())
		rtos_host_trace("kernel", "boot %s", cfg->name ? cfg->name : "?");
	return E_OK;
}
