/*
 * time.c — the tick, time events (timeouts, cyclic and alarm handlers) and
 * the time service calls.
 *
 * Time events are kept in a heap keyed by (tick index, sequence) and are
 * processed by the kernel's part of the tick interrupt (INTNO_TICK).  Tick k
 * is the boundary at k * RTOS_HOST_TICK_NS.  A relative time of ms from now expires at
 * the first tick boundary at or after now + ms, and never at a tick already
 * processed (docs/rtos-stub.md, "Timing rules").  The tick interrupt is only
 * raised at boundaries where something is due, unless ISRs are attached to
 * INTNO_TICK: then it is raised on every boundary, like the hardware timer.
 */
#include <stdlib.h>
#include <string.h>

#include "kernel_impl.h"

#define NS_PER_MS 1000000ULL
#define NS_PER_US 1000ULL

uint64_t now_ns;
uint64_t tick_done;

static struct tmevt **tm_heap;
static uint_t tm_len;
static uint_t tm_cap;
static uint64_t tm_seq;

static bool tick_every;

struct cyccb {
	const struct rtos_cyc_cfg *cfg;
	uint64_t unit_ns;     /* cyctim and cycphs are in ms (HRP2) or us (HRP3) */
	bool     started;
	uint64_t origin_ns;   /* activation k is due at origin + cycphs + k * cyctim */
	uint64_t k;
	struct tmevt ev;
};

struct almcb {
	const struct rtos_alm_cfg *cfg;
	struct tmevt ev;
};

static struct cyccb *cyc_table[TNUM_CYCID + 1];
static struct almcb *alm_table[TNUM_ALMID + 1];

/* ---- The time-event heap ---- */

/* Heap order: earlier tick first, then queueing order. */
static bool tm_before(const struct tmevt *a, const struct tmevt *b)
{
	return a->tick < b->tick || (a->tick == b->tick && a->seq < b->seq);
}

/* Puts ev at heap position pos. */
static void tm_place(uint_t pos, struct tmevt *ev)
{
	tm_heap[pos] = ev;
	ev->heap_index = pos;
}

/* Restores heap order upwards from pos. */
static void tm_sift_up(uint_t pos)
{
	struct tmevt *ev = tm_heap[pos];

	while (pos > 0 && tm_before(ev, tm_heap[(pos - 1) / 2])) {
		tm_place(pos, tm_heap[(pos - 1) / 2]);
		pos = (pos - 1) / 2;
	}
	tm_place(pos, ev);
}

/* Restores heap order downwards from pos. */
static void tm_sift_down(uint_t pos)
{
	struct tmevt *ev = tm_heap[pos];

	for (;;) {
		uint_t child = 2 * pos + 1;

		if (child >= tm_len)
			break;
		if (child + 1 < tm_len && tm_before(tm_heap[child + 1], tm_heap[child]))
			child++;
		if (!tm_before(tm_heap[child], ev))
			break;
		tm_place(pos, tm_heap[child]);
		pos = child;
	}
	tm_place(pos, ev);
}

/* Makes sure a tick interrupt happens at boundary tick (or earlier). */
static void tick_need(uint64_t tick)
{
	uint64_t t = tick * RTOS_HOST_TICK_NS;

	if (tick_every)
		return;
	if (t < now_ns)
		t = now_ns;
	if (t >= event_timer_time())
		return;
	event_timer_set(t, 0);
}

/* Queues ev to fire when the tick handler reaches tick. */
void tmevt_enqueue(struct tmevt *ev, uint64_t tick)
{
	if (tm_len == tm_cap) {
		uint_t ncap = tm_cap ? tm_cap * 2 : 64;
		struct tmevt **nheap = realloc(tm_heap, ncap * sizeof(*nheap));

		if (nheap == NULL) {
			rtos_host_bug("kernel", "out of memory for time events");
			return;
		}
		tm_heap = nheap;
		tm_cap = ncap;
	}
	ev->tick = tick;
	ev->seq = tm_seq++;
	tm_heap[tm_len] = ev;
	ev->heap_index = tm_len++;
	tm_sift_up(ev->heap_index);
	tick_need(tick);
}

/* Removes a queued time event. */
void tmevt_dequeue(struct tmevt *ev)
{
	uint_t pos = ev->heap_index;
	struct tmevt *last = tm_heap[--tm_len];

	ev->heap_index = UINT32_MAX;
	if (pos == tm_len)
		return;
	tm_place(pos, last);
	tm_sift_down(pos);
	tm_sift_up(last->heap_index);
}

/* Tick index of a relative time of ns from now: the first boundary at or after
 * now + ns, and at least the next tick not yet processed. */
uint64_t tick_after_ns(uint64_t ns)
{
	uint64_t due = now_ns + ns;
	uint64_t tick = (due + RTOS_HOST_TICK_NS - 1) / RTOS_HOST_TICK_NS;

	return tick > tick_done ? tick : tick_done + 1;
}

/* The running call's largest relative time: ms for HRP2, us for HRP3. */
uint32_t svc_reltim_max(void)
{
	return svc_in_us() ? HRP3_TMAX_RELTIM : TMAX_RELTIM;
}

/* A relative time in the running call's unit, in ns. */
uint64_t svc_reltim_ns(uint32_t reltim)
{
	return (uint64_t)reltim * (svc_in_us() ? NS_PER_US : NS_PER_MS);
}

/* ---- The tick ---- */

/* tick_handler's work when time events are due, or the next one needs the
 * tick (no ISR on it): processes those due by tick cur and arms the next. */
static __attribute__((noinline)) void tick_process(uint64_t cur)
{
	while (tm_len > 0 && tm_heap[0]->tick <= cur) {
		struct tmevt *ev = tm_heap[0];

		tmevt_dequeue(ev);
		ev->callback(ev);
	}
	if (tm_len > 0)
		tick_need(tm_heap[0]->tick);
}

/* The kernel's part of the tick interrupt: processes every time event due by now. */
void tick_handler(void)
{
	uint64_t cur = now_ns / RTOS_HOST_TICK_NS;

	tick_done = cur;
	/* on most ticks of a tick with ISRs nothing is due: no frame, no loop */
	if (tm_len > 0 && (tm_heap[0]->tick <= cur || !tick_every))
		tick_process(cur);
}

/* Decides whether the tick runs on every boundary (ISRs attached to INTNO_TICK). */
void tick_set_every(bool every)
{
	tick_every = every;
}

/* Forgets all time state (boot/shutdown). */
void time_reset(void)
{
	now_ns = 0;
	tick_done = 0;
	tm_len = 0;
	tm_seq = 0;
	tick_every = false;
}

/* Starts the tick timer (every boundary mode) once the objects exist, and
 * lets quiet_until follow the events now that the kernel is booted. */
void time_start(void)
{
	event_set_run_bound(UINT64_MAX);
	if (tick_every)
		event_timer_set(RTOS_HOST_TICK_NS, RTOS_HOST_TICK_NS);
}

/* ---- Cyclic handlers ---- */

/* Virtual time activation k is due (from k: no accumulated drift). */
static uint64_t cyc_due_ns(const struct cyccb *c, uint64_t k)
{
	return c->origin_ns + (uint64_t)c->cfg->cycphs * c->unit_ns +
	       k * (uint64_t)c->cfg->cyctim * c->unit_ns;
}

/* Tick at which activation k runs: the first boundary at or after its due time. */
static uint64_t cyc_tick(const struct cyccb *c, uint64_t k)
{
	return (cyc_due_ns(c, k) + RTOS_HOST_TICK_NS - 1) / RTOS_HOST_TICK_NS;
}

/* Tick callback of a cyclic handler: queues the next activation, then runs the handler. */
static void cyc_fire(struct tmevt *ev)
{
	struct cyccb *c = container_of_kernel(ev, struct cyccb, ev);

	c->k++;
	tmevt_enqueue(&c->ev, cyc_tick(c, c->k));
	run_handler(EXEC_CYC, c->cfg->cycid, c->cfg->cychdr, c->cfg->exinf);
}

/* Starts c on the grid origin + cycphs + k * cyctim: keep_phase skips activations
 * already past; the first one never falls on a tick already processed. */
static void cyc_start(struct cyccb *c, uint64_t origin, bool keep_phase)
{
	uint64_t tick;

	c->origin_ns = origin;
	c->k = 0;
	if (keep_phase && now_ns > cyc_due_ns(c, 0)) {
		uint64_t period = (uint64_t)c->cfg->cyctim * c->unit_ns;

		c->k = (now_ns - cyc_due_ns(c, 0) + period - 1) / period;
	}
	tick = cyc_tick(c, c->k);
	if (tick <= tick_done)
		tick = tick_done + 1;
	c->started = true;
	tmevt_enqueue(&c->ev, tick);
}

/* Resolves a cyclic handler ID; NULL and *ercd on failure. */
static struct cyccb *cyc_lookup(ID cycid, ER *ercd)
{
	if (cycid < 1 || cycid > TNUM_CYCID) {
		*ercd = E_ID;
		return NULL;
	}
	if (cyc_table[cycid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return cyc_table[cycid];
}

/* Starts a cyclic handler: TA_PHS keeps the boot-time phase grid, else restarts from now. */
ER sta_cyc(ID cycid)
{
	struct cyccb *c;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("sta_cyc", E_CTX);
	if ((c = cyc_lookup(cycid, &ercd)) == NULL)
		return svc_result("sta_cyc", ercd);
	if (c->cfg->cycatr & TA_PHS) {
		if (!c->started)
			cyc_start(c, 0, true);
	} else {
		if (tmevt_queued(&c->ev))
			tmevt_dequeue(&c->ev);
		cyc_start(c, now_ns, false);
	}
	return E_OK;
}

/* Stops a cyclic handler (no further activations). */
ER stp_cyc(ID cycid)
{
	struct cyccb *c;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("stp_cyc", E_CTX);
	if ((c = cyc_lookup(cycid, &ercd)) == NULL)
		return svc_result("stp_cyc", ercd);
	if (tmevt_queued(&c->ev))
		tmevt_dequeue(&c->ev);
	c->started = false;
	return E_OK;
}

/* ---- Alarm handlers ---- */

/* Time event of an alarm: runs its handler once. */
static void alm_fire(struct tmevt *ev)
{
	struct almcb *a = container_of_kernel(ev, struct almcb, ev);

	run_handler(EXEC_ALM, a->cfg->almid, a->cfg->almhdr, a->cfg->exinf);
}

/* Resolves an alarm ID; NULL and *ercd on failure. */
static struct almcb *alm_lookup(ID almid, ER *ercd)
{
	if (almid < 1 || almid > TNUM_ALMID) {
		*ercd = E_ID;
		return NULL;
	}
	if (alm_table[almid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return alm_table[almid];
}

/* Common body of sta_alm/ista_alm and HRP3's sta_alm: (re)arms the alarm ns from now. */
ER alm_start_ns(const char *svc, ID almid, uint64_t ns)
{
	struct almcb *a;
	ER ercd = E_OK;

	if ((a = alm_lookup(almid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (tmevt_queued(&a->ev))
		tmevt_dequeue(&a->ev);
	tmevt_enqueue(&a->ev, tick_after_ns(ns));
	return E_OK;
}

/* sta_alm/ista_alm's body: almtim in ms (E_PAR beyond TMAX_RELTIM). */
static ER alm_start(const char *svc, ID almid, RELTIM almtim)
{
	ER ercd = E_OK;

	if (alm_lookup(almid, &ercd) == NULL)
		return svc_result(svc, ercd);
	if (almtim > TMAX_RELTIM)
		return svc_result(svc, E_PAR);
	return alm_start_ns(svc, almid, (uint64_t)almtim * NS_PER_MS);
}

/* Common body of stp_alm/istp_alm. */
static ER alm_stop(const char *svc, ID almid)
{
	struct almcb *a;
	ER ercd = E_OK;

	if ((a = alm_lookup(almid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (tmevt_queued(&a->ev))
		tmevt_dequeue(&a->ev);
	return E_OK;
}

/* Starts (or restarts) an alarm almtim ms from now. */
ER sta_alm(ID almid, RELTIM almtim)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("sta_alm", E_CTX);
	return alm_start("sta_alm", almid, almtim);
}

/* sta_alm from non-task context. */
ER ista_alm(ID almid, RELTIM almtim)
{
	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("ista_alm", E_CTX);
	return alm_start("ista_alm", almid, almtim);
}

/* Stops an alarm. */
ER stp_alm(ID almid)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("stp_alm", E_CTX);
	return alm_stop("stp_alm", almid);
}

/* stp_alm from non-task context. */
ER istp_alm(ID almid)
{
	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("istp_alm", E_CTX);
	return alm_stop("istp_alm", almid);
}

/* ---- Creation (boot) ---- */

/* Registers a checked CRE_CYC row whose times are in units of unit_ns. */
ER cyc_register(const struct rtos_cyc_cfg *cfg, uint64_t unit_ns)
{
	struct cyccb *c = calloc(1, sizeof(*c));

	if (c == NULL)
		return E_NOMEM;
	c->cfg = cfg;
	c->unit_ns = unit_ns;
	c->ev.heap_index = UINT32_MAX;
	c->ev.callback = cyc_fire;
	cyc_table[cfg->cycid] = c;
	return E_OK;
}

/* Registers a checked CRE_ALM row. */
ER alm_register(const struct rtos_alm_cfg *cfg)
{
	struct almcb *a = calloc(1, sizeof(*a));

	if (a == NULL)
		return E_NOMEM;
	a->cfg = cfg;
	a->ev.heap_index = UINT32_MAX;
	a->ev.callback = alm_fire;
	alm_table[cfg->almid] = a;
	return E_OK;
}

/* The time left until the event ev runs: its tick's boundary less now. */
static uint64_t tmevt_left_ns(const struct tmevt *ev)
{
	uint64_t at = ev->tick * RTOS_HOST_TICK_NS;

	return at > now_ns ? at - now_ns : 0;
}

/* Whether cycid runs and the time to its next activation. */
ER cyc_state(ID cycid, bool *started, uint64_t *left_ns)
{
	struct cyccb *c;
	ER ercd = E_OK;

	if ((c = cyc_lookup(cycid, &ercd)) == NULL)
		return ercd;
	*started = tmevt_queued(&c->ev);
	*left_ns = *started ? tmevt_left_ns(&c->ev) : 0;
	return E_OK;
}

/* Whether almid is armed and the time until it runs. */
ER alm_state(ID almid, bool *started, uint64_t *left_ns)
{
	struct almcb *a;
	ER ercd = E_OK;

	if ((a = alm_lookup(almid, &ercd)) == NULL)
		return ercd;
	*started = tmevt_queued(&a->ev);
	*left_ns = *started ? tmevt_left_ns(&a->ev) : 0;
	return E_OK;
}

/* True if the cyclic handler ID is taken (boot duplicate check). */
bool cyc_exists(ID cycid)
{
	return cyc_table[cycid] != NULL;
}

/* True if the alarm ID is taken (boot duplicate check). */
bool alm_exists(ID almid)
{
	return alm_table[almid] != NULL;
}

/* Starts TA_STA cyclic handlers: activation k at cycphs + k * cyctim after boot. */
ER cyc_create_all(void)
{
	for (ID id = 1; id <= TNUM_CYCID; id++)
		if (cyc_table[id] != NULL && (cyc_table[id]->cfg->cycatr & TA_STA))
			cyc_start(cyc_table[id], 0, true);
	return E_OK;
}

/* Frees cyclic and alarm control blocks. */
void cyc_reset(void)
{
	for (ID id = 0; id <= TNUM_CYCID; id++) {
		free(cyc_table[id]);
		cyc_table[id] = NULL;
	}
	for (ID id = 0; id <= TNUM_ALMID; id++) {
		free(alm_table[id]);
		alm_table[id] = NULL;
	}
}

/* ---- Time service calls ---- */

/* System time in ms since boot, as the tick counter sees it (whole ticks). */
ER get_tim(SYSTIM *p_systim)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("get_tim", E_CTX);
	if (check_out_ptr(p_systim, sizeof(*p_systim)) != E_OK)
		return svc_result("get_tim", E_MACV);
	*p_systim = (SYSTIM)((now_ns / RTOS_HOST_TICK_NS) * RTOS_HOST_TICK_NS / NS_PER_MS);
	return E_OK;
}

/* Performance time in us since boot (any context; wraps at 2^32 us). */
ER get_utm(SYSUTM *p_sysutm)
{
	svc_charge();
	if (p_sysutm == NULL)
		return svc_result("get_utm", E_MACV);
	*p_sysutm = (SYSUTM)(now_ns / 1000U);
	return E_OK;
}

/* Virtual time in ns since boot. */
uint64_t rtos_host_now(void)
{
	return now_ns;
}

/* ns as a relative time of the running call's profile (ms, or us), rounded down. */
static RELTIM svc_reltim_of_ns(uint64_t ns)
{
	return (RELTIM)(ns / (svc_in_us() ? NS_PER_US : NS_PER_MS));
}

/* Reports whether a cyclic handler runs and the time to its next activation. */
ER ref_cyc(ID cycid, T_RCYC *pk_rcyc)
{
	bool started;
	uint64_t left;
	ER ercd;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ref_cyc", E_CTX);
	if ((ercd = cyc_state(cycid, &started, &left)) != E_OK)
		return svc_result("ref_cyc", ercd);
	if (check_out_ptr(pk_rcyc, sizeof(*pk_rcyc)) != E_OK)
		return svc_result("ref_cyc", E_MACV);
	pk_rcyc->cycstat = started ? TCYC_STA : TCYC_STP;
	pk_rcyc->lefttim = svc_reltim_of_ns(left);
	return E_OK;
}

/* Reports whether an alarm is armed and the time until it runs. */
ER ref_alm(ID almid, T_RALM *pk_ralm)
{
	bool started;
	uint64_t left;
	ER ercd;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ref_alm", E_CTX);
	if ((ercd = alm_state(almid, &started, &left)) != E_OK)
		return svc_result("ref_alm", ercd);
	if (check_out_ptr(pk_ralm, sizeof(*pk_ralm)) != E_OK)
		return svc_result("ref_alm", E_MACV);
	pk_ralm->almstat = started ? TALM_STA : TALM_STP;
	pk_ralm->lefttim = svc_reltim_of_ns(left);
	return E_OK;
}
