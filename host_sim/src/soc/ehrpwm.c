/*
 * ehrpwm.c — eHRPWM0 and eHRPWM1 (AM1808 TRM chapter "eHRPWM"), reduced to what a
 * motor sees: the fraction of each period an output is low, recomputed
 * whenever it can change (a register write that acts at once, or a shadow
 * load at counter zero/period, which is an event at that exact instant).
 * The counter is computed from the virtual clock.
 */
#include <stdlib.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/syscfg.h"
#include "host_sim/trace.h"
#include "host_sim/devices/pwm.h"
#include "pwm_outputs.h"

#define PWM_CLOCK_HZ HS_PLL1_SYSCLK2_HZ

/* ---- action-qualifier simulation ---- */

/* Action codes of AQCTL fields: 0 nothing, 1 clear, 2 set, 3 toggle. */
static bool aq_apply(bool level, unsigned action)
{
	switch (action & 3U) {
	case 1: return false;
	case 2: return true;
	case 3: return !level;
	default: return level;
	}
}

struct aq_event {
	uint32_t pos;               /* TBCLK cycles from the period start */
	uint8_t prio;               /* higher wins at equal positions (applied last) */
	uint8_t action;
	uint8_t tag;                /* index in aq_events' unsorted build */
};

/* True if event a goes before b in aq_sort's order (position, then priority, then build order). */
static bool aq_before(const struct aq_event *a, const struct aq_event *b)
{
	if (a->pos != b->pos)
		return a->pos < b->pos;
	return a->prio != b->prio ? a->prio < b->prio : a->tag < b->tag;
}

/* Sorts events by position, then priority (insertion sort: at most 6; stable, so
 * equal keys keep their build order). */
static void aq_sort(struct aq_event *ev, unsigned n)
{
	for (unsigned i = 1; i < n; i++)
		for (unsigned j = i; j > 0 && (ev[j - 1].pos > ev[j].pos ||
			(ev[j - 1].pos == ev[j].pos && ev[j - 1].prio > ev[j].prio)); j--) {
			struct aq_event t = ev[j];

			ev[j] = ev[j - 1];
			ev[j - 1] = t;
		}
}

/* Appends an event to ev (holding *n), tagged with its index. */
static void aq_add(struct aq_event *ev, unsigned *n, uint32_t pos, uint8_t prio, uint8_t action)
{
	ev[*n] = (struct aq_event){ pos, prio, action, (uint8_t)*n };
	++*n;
}

/* The action events of one period, unsorted (tagged with their index); returns
 * their count, *len the period in TBCLK cycles. */
static unsigned aq_events(unsigned ctrmode, uint32_t prd, uint32_t cmpa, uint32_t cmpb,
			  uint32_t aqctl, struct aq_event ev[6], uint32_t *len)
{
	unsigned n = 0;

	/* AQCTL fields: ZRO 1:0, PRD 3:2, CAU 5:4, CAD 7:6, CBU 9:8, CBD 11:10 */
	if (ctrmode == 0) {                 /* up: 0..PRD */
		*len = prd + 1U;
		aq_add(ev, &n, 0, 0, (uint8_t)(aqctl & 3U));
		aq_add(ev, &n, prd, 1, (uint8_t)((aqctl >> 2) & 3U));
		if (cmpa <= prd)
			aq_add(ev, &n, cmpa, 2, (uint8_t)((aqctl >> 4) & 3U));
		if (cmpb <= prd)
			aq_add(ev, &n, cmpb, 3, (uint8_t)((aqctl >> 8) & 3U));
	} else if (ctrmode == 1) {          /* down: PRD..0 */
		*len = prd + 1U;
		aq_add(ev, &n, 0, 1, (uint8_t)((aqctl >> 2) & 3U));
		aq_add(ev, &n, prd, 0, (uint8_t)(aqctl & 3U));
		if (cmpa <= prd)
			aq_add(ev, &n, prd - cmpa, 2, (uint8_t)((aqctl >> 6) & 3U));
		if (cmpb <= prd)
			aq_add(ev, &n, prd - cmpb, 3, (uint8_t)((aqctl >> 10) & 3U));
	} else {                            /* up-down: 0..PRD..0 */
		uint32_t l = prd ? 2U * prd : 1U;

		*len = l;
		aq_add(ev, &n, 0, 0, (uint8_t)(aqctl & 3U));
		aq_add(ev, &n, prd, 1, (uint8_t)((aqctl >> 2) & 3U));
		if (cmpa < prd) {
			aq_add(ev, &n, cmpa, 2, (uint8_t)((aqctl >> 4) & 3U));
			if (cmpa)
				aq_add(ev, &n, l - cmpa, 2, (uint8_t)((aqctl >> 6) & 3U));
		}
		if (cmpb < prd && n < 6) {
			aq_add(ev, &n, cmpb, 3, (uint8_t)((aqctl >> 8) & 3U));
			if (cmpb && n < 6)
				aq_add(ev, &n, l - cmpb, 3, (uint8_t)((aqctl >> 10) & 3U));
		}
	}
	return n;
}

/* AQCTL's compare-A (CAU, CAD) and compare-B (CBU, CBD) action fields. */
#define AQ_CMPA_ACTIONS 0x0F0U
#define AQ_CMPB_ACTIONS 0xF00U

/* An output's steady periods for one setting of the counter mode, PRD, CMPA, CMPB and
 * AQCTL: worked out when the setting changes, not on every update (a motor's duty is
 * re-evaluated at every shadow load, its setting changes far less often).  A compare
 * value whose actions are all "nothing" only splits a range of equal level, so it is
 * left out of the setting: eHRPWM1's output A does not depend on CMPB, nor B on CMPA. */
struct aq_steady {
	bool valid;
	unsigned ctrmode;
	uint32_t prd, cmpa, cmpb, aqctl;
	unsigned n;
	uint32_t len;               /* TBCLK cycles of a period */
	uint8_t tag[6];             /* the sorted events' indices in aq_events' build */
	uint8_t action[6];          /* their actions */
	uint32_t from[6], to[6];    /* positions where each event's level holds in a period */
	bool period_level[2][6];    /* level after each event in one period entered at level 0, 1 */
	bool period_end[2];         /* level such a period ends at */
	bool level[2][6];           /* that level in a steady period, by the level before the first */
	double low[2];              /* low fraction of the steady periods, likewise */
};

/* The compare value as the setting keeps it (0 when its actions do nothing). */
static uint32_t aq_cmp_key(uint32_t cmp, uint32_t aqctl, uint32_t actions)
{
	return aqctl & actions ? cmp : 0;
}

/* Works out c's levels from its sorted actions: one period from each start level,
 * then the steady ones (a period depends only on the level it starts at, so three
 * periods, the first settling toggles, follow from these two). */
static void aq_steady_fill_levels(struct aq_steady *c)
{
	for (unsigned from = 0; from < 2; from++) {
		bool lvl = from != 0;

		for (unsigned i = 0; i < c->n; i++) {
			lvl = aq_apply(lvl, c->action[i]);
			c->period_level[from][i] = lvl;
		}
		c->period_end[from] = lvl;
	}
	for (unsigned start = 0; start < 2; start++) {
		bool third = c->period_end[c->period_end[start]];

		for (unsigned i = 0; i < c->n; i++)
			c->level[start][i] = c->period_level[third][i];
	}
}

/* Works out c's low fractions from its levels and positions: the mean of the
 * second and third period from each start level. */
static void aq_steady_fill_low(struct aq_steady *c)
{
	uint64_t low[2] = { 0, 0 };
	unsigned n = c->n;

	for (unsigned i = 0; i < n; i++) {
		uint32_t width = c->to[i] - c->from[i];

		if (!c->period_level[0][i])
			low[0] += width;
		if (!c->period_level[1][i])
			low[1] += width;
	}
	for (unsigned start = 0; start < 2; start++) {
		bool second = c->period_end[start], third = c->period_end[second];

		c->low[start] = (double)(low[second] + low[third]) / (2.0 * c->len);
	}
}

/* Takes the positions of c's events from a new build ev (n events) in which only
 * compare values moved, if the events keep their sorted order and actions (the
 * levels then hold); false if they do not. */
static bool aq_steady_move(struct aq_steady *c, const struct aq_event *ev, unsigned n)
{
	uint32_t pos[7];
	const struct aq_event *prev = NULL;

	if (n != c->n)
		return false;
	for (unsigned i = 0; i < n; i++) {
		const struct aq_event *e = &ev[c->tag[i]];

		if (e->action != c->action[i] || (prev != NULL && !aq_before(prev, e)))
			return false;
		pos[i] = e->pos;
		prev = e;
	}
	pos[n] = c->len;
	for (unsigned i = 0; i < n; i++) {
		c->from[i] = pos[i];
		c->to[i] = pos[i + 1];
	}
	return true;
}

/* aq_steady_of when c does not hold the setting: works it out into c (only the
 * positions and fractions when just a compare value moved, as a duty change does).
 * Out of line: a duty change misses once, the updates after it hit. */
static __attribute__((noinline)) const struct aq_steady *aq_steady_fill_setting(
	struct aq_steady *c, unsigned ctrmode, uint32_t prd, uint32_t cmpa, uint32_t cmpb, uint32_t aqctl)
{
	struct aq_event ev[6];
	unsigned n = aq_events(ctrmode, prd, cmpa, cmpb, aqctl, ev, &c->len);
	bool same_frame = c->valid && c->ctrmode == ctrmode && c->prd == prd && c->aqctl == aqctl;

	c->valid = true;
	c->ctrmode = ctrmode;
	c->prd = prd;
	c->cmpa = aq_cmp_key(cmpa, aqctl, AQ_CMPA_ACTIONS);
	c->cmpb = aq_cmp_key(cmpb, aqctl, AQ_CMPB_ACTIONS);
	c->aqctl = aqctl;
	if (!same_frame || !aq_steady_move(c, ev, n)) {
		aq_sort(ev, n);
		c->n = n;
		for (unsigned i = 0; i < n; i++) {
			c->tag[i] = ev[i].tag;
			c->action[i] = ev[i].action;
			c->from[i] = ev[i].pos;
			c->to[i] = (i + 1 < n) ? ev[i + 1].pos : c->len;
		}
		aq_steady_fill_levels(c);
	}
	aq_steady_fill_low(c);
	return c;
}

/* The steady periods of a setting, from c if it holds that setting. */
static inline const struct aq_steady *aq_steady_of(struct aq_steady *c, unsigned ctrmode, uint32_t prd,
						    uint32_t cmpa, uint32_t cmpb, uint32_t aqctl)
{
	if (c->valid && c->ctrmode == ctrmode && c->prd == prd &&
	    c->cmpa == aq_cmp_key(cmpa, aqctl, AQ_CMPA_ACTIONS) &&
	    c->cmpb == aq_cmp_key(cmpb, aqctl, AQ_CMPB_ACTIONS) && c->aqctl == aqctl)
		return c;
	return aq_steady_fill_setting(c, ctrmode, prd, cmpa, cmpb, aqctl);
}

/* Level at position pos of a steady period entered at level start (start
 * itself if pos lies in no event's range).  The ranges tile the period from
 * the first event on (each starts where the one before ends; there are at
 * least two, at zero and period), so the first range ending after pos holds it. */
static bool aq_level_at(const struct aq_steady *c, bool start, uint32_t pos)
{
	if (pos < c->from[0])
		return start;
	for (unsigned i = 0; i < c->n; i++)
		if (pos < c->to[i])
			return c->level[start][i];
	return start;
}

/* ---- eHRPWM1 ---- */

enum {
	TBCTL = 0x00, TBSTS = 0x02, TBPHSHR = 0x04, TBPHS = 0x06, TBCNT = 0x08, TBPRD = 0x0A,
	CMPCTL = 0x0E, CMPAHR = 0x10, CMPA = 0x12, CMPB = 0x14, AQCTLA = 0x16, AQCTLB = 0x18,
	AQSFRC = 0x1A, AQCSFRC = 0x1C, DBCTL = 0x1E, DBRED = 0x20, DBFED = 0x22, TZSEL = 0x24,
	TZCTL = 0x28, TZEINT = 0x2A, TZFLG = 0x2C, TZCLR = 0x2E, TZFRC = 0x30, ETSEL = 0x32,
	ETPS = 0x34, ETFLG = 0x36, ETCLR = 0x38, ETFRC = 0x3A, PCCTL = 0x3C,
};

#define EHRPWM_REG_SLOTS (PCCTL / 2 + 1)

struct ehrpwm {
	struct hs_region *r;
	const uint32_t *value[EHRPWM_REG_SLOTS];   /* stored register values reg() reads, by offset / 2 */
	uint16_t prd, cmpa, cmpb;   /* active registers (the CPU sees the shadows) */
	bool prd_pending, cmpa_pending, cmpb_pending;
	bool running;
	uint64_t t_ref;             /* counter was cnt_ref at t_ref */
	uint32_t cnt_ref;
	bool up;                    /* up-down mode: counting up at t_ref */
	hs_event_t load_ev;
	double low[2];              /* outputs A, B */
	bool level[2];
	struct aq_steady steady[2]; /* outputs A, B */
	int syscfg_watch;
	enum hs_pwm_output out[2];  /* outputs A, B */
	const char *name;
	double freq;                /* time-base frequency last notified (Hz, 0 stopped) */
	uint32_t tbclk_tbctl;       /* the TBCTL tbclk was worked out for (tbclk_of) */
	uint64_t tbclk;
};

/* Stored value of a register (hs_reg_get without the lookup: several are read at every update). */
static uint32_t reg(const struct ehrpwm *e, unsigned offset)
{
	return *e->value[offset / 2U];
}

/* Time-base clock for TBCTL dividers. */
static uint64_t tbclk_hz(uint32_t tbctl)
{
	unsigned hsp = (tbctl >> 7) & 7U, clk = (tbctl >> 10) & 7U;

	return PWM_CLOCK_HZ / ((hsp ? 2U * hsp : 1U) * (1U << clk));
}

/* tbclk_hz of TBCTL value tbctl, remembered: every update and counter
 * read asks, TBCTL's dividers change almost never. */
static uint64_t tbclk_of(struct ehrpwm *e, uint32_t tbctl)
{
	if (tbctl != e->tbclk_tbctl) {
		e->tbclk_tbctl = tbctl;
		e->tbclk = tbclk_hz(tbctl);
	}
	return e->tbclk;
}

/* TBCLK cycles of one counter period (0 while frozen). */
static uint32_t tb_period_cycles(const struct ehrpwm *e, uint32_t tbctl)
{
	unsigned mode = tbctl & 3U;

	if (mode == 3)
		return 0;
	return mode == 2 ? (e->prd ? 2U * e->prd : 1U) : e->prd + 1U;
}

/* Position in the period (TBCLK cycles from the period start) now. */
static uint32_t tb_position(struct ehrpwm *e)
{
	uint32_t tbctl = reg(e, TBCTL);
	uint32_t len = tb_period_cycles(e, tbctl);
	uint64_t pos;

	if (!len)
		return 0;
	pos = e->cnt_ref;
	if (e->running)
		pos += hs_ns_to_cycles(hs_now() - e->t_ref, tbclk_of(e, tbctl));
	return (uint32_t)(pos % len);
}

/* Counter value at a period position. */
static uint32_t tb_counter(const struct ehrpwm *e, uint32_t pos)
{
	switch (reg(e, TBCTL) & 3U) {
	case 1: return e->prd - pos;
	case 2: return pos <= e->prd ? pos : 2U * e->prd - pos;
	default: return pos;
	}
}

/* Recomputes both outputs at period position pos (tb_position now: callers that
 * need it too work it out once); tells the motors if anything changed. */
static void ehrpwm_update(struct ehrpwm *e, uint32_t pos)
{
	uint32_t tbctl = reg(e, TBCTL), csfrc = reg(e, AQCSFRC);
	uint32_t len = tb_period_cycles(e, tbctl);
	static const uint32_t aq[2] = { AQCTLA, AQCTLB };
	double freq = e->running && len ? (double)tbclk_of(e, tbctl) / len : 0;

	for (int o = 0; o < 2; o++) {
		unsigned force = (csfrc >> (2 * o)) & 3U;
		double low;
		bool lvl = e->level[o];

		if (force == 1 || force == 2) {
			lvl = force == 2;
			low = lvl ? 0.0 : 1.0;
		} else if (!e->running) {
			if ((tbctl & 3U) != 3U)
				lvl = aq_level_at(aq_steady_of(&e->steady[o], tbctl & 3U, e->prd, e->cmpa,
							       e->cmpb, reg(e, aq[o])), lvl, pos);
			low = lvl ? 0.0 : 1.0;
		} else {
			const struct aq_steady *c = aq_steady_of(&e->steady[o], tbctl & 3U, e->prd, e->cmpa,
								 e->cmpb, reg(e, aq[o]));

			low = c->low[lvl];
			lvl = aq_level_at(c, lvl, pos);
		}
		e->level[o] = lvl;
		if (low != e->low[o] || freq != e->freq) {
			e->low[o] = low;
			hs_pwm_output_changed(e->out[o]);
		}
	}
	e->freq = freq;
}

static void ehrpwm_schedule_load(struct ehrpwm *e, uint32_t pos);

/* Event: counter at zero or period: shadow loads as CMPCTL/TBCTL say. */
static void ehrpwm_load(void *arg)
{
	struct ehrpwm *e = arg;
	uint32_t cmpctl = reg(e, CMPCTL);
	uint32_t pos = tb_position(e), cnt = tb_counter(e, pos);
	bool at_zero = cnt == 0, at_prd = cnt == e->prd;
	unsigned la = cmpctl & 3U, lb = (cmpctl >> 2) & 3U;

	e->load_ev = 0;
	if (e->prd_pending && at_zero) {
		e->prd = (uint16_t)reg(e, TBPRD);
		e->prd_pending = false;
		pos = tb_position(e);   /* the period length the position is taken in changed */
	}
	if (e->cmpa_pending && ((la == 0 && at_zero) || (la == 1 && at_prd) || (la == 2 && (at_zero || at_prd)))) {
		e->cmpa = (uint16_t)reg(e, CMPA);
		e->cmpa_pending = false;
	}
	if (e->cmpb_pending && ((lb == 0 && at_zero) || (lb == 1 && at_prd) || (lb == 2 && (at_zero || at_prd)))) {
		e->cmpb = (uint16_t)reg(e, CMPB);
		e->cmpb_pending = false;
	}
	hs_reg_update(e->r, CMPCTL, (e->cmpa_pending ? 0U : 1U << 8) | (e->cmpb_pending ? 0U : 1U << 9), 0);
	ehrpwm_update(e, pos);
	ehrpwm_schedule_load(e, pos);
}

/* Schedules the next counter-zero or period instant if a shadow is pending
 * (pos: tb_position now). */
static void ehrpwm_schedule_load(struct ehrpwm *e, uint32_t pos)
{
	uint32_t tbctl = reg(e, TBCTL);
	uint32_t len = tb_period_cycles(e, tbctl), next;

	hs_event_cancel(&e->load_ev);
	if (!e->running || !len || !(e->prd_pending || e->cmpa_pending || e->cmpb_pending))
		return;
	/* zero and period sit at positions 0 (= len) and PRD in every counting mode */
	next = pos < e->prd ? e->prd : len;
	{
		uint64_t hz = tbclk_of(e, tbctl);
		uint64_t elapsed = e->cnt_ref + hs_ns_to_cycles(hs_now() - e->t_ref, hz);

		e->load_ev = hs_event_at(e->t_ref + hs_cycles_to_ns(elapsed - pos + next - e->cnt_ref, hz),
					 ehrpwm_load, e);
	}
}

/* Re-bases the counter at now and re-evaluates whether the time base runs. */
static void ehrpwm_rebase(struct ehrpwm *e)
{
	uint32_t tbctl = reg(e, TBCTL), pos;
	bool run = (tbctl & 3U) != 3U && hs_syscfg_tbclksync();

	e->cnt_ref = tb_position(e);
	e->t_ref = hs_now();
	e->running = run;
	pos = tb_position(e);
	ehrpwm_update(e, pos);
	ehrpwm_schedule_load(e, pos);
}

/* Watcher: TBCLKSYNC starts or stops the time base. */
static void ehrpwm_syscfg_changed(void *ctx, uint32_t offset, uint32_t old, uint32_t now)
{
	if (offset == HS_SYSCFG0_CFGCHIP(1) && ((old ^ now) & HS_CFGCHIP1_TBCLKSYNC))
		ehrpwm_rebase(ctx);
}

/* TBCNT read: the counter now. */
static void ehrpwm_read_tbcnt(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct ehrpwm *e = ctx;

	*value = tb_counter(e, tb_position(e));
}

/* TBSTS read: counting direction now. */
static void ehrpwm_read_tbsts(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct ehrpwm *e = ctx;
	uint32_t tbctl = reg(e, TBCTL), pos = tb_position(e);
	bool up = (tbctl & 3U) == 0U || ((tbctl & 3U) == 2U && pos < e->prd);

	*value = (*value & ~1U) | (up ? 1U : 0U);
}

/* Time-base writes: counter, period (shadowed), software sync. */
static void ehrpwm_write_tb(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv,
			   uint32_t written)
{
	struct ehrpwm *e = ctx;

	switch (a->offset) {
	case TBCTL:
		if (nv & (1U << 6))     /* SWFSYNC: one-shot, reads back 0; loads TBPHS if PHSEN */
			hs_reg_update(e->r, TBCTL, 1U << 6, 0);
		if ((nv & (1U << 2)) && (nv & (1U << 6))) {
			e->cnt_ref = reg(e, TBPHS);
			e->t_ref = hs_now();
		}
		break;
	case TBCNT:
		e->cnt_ref = nv;
		e->t_ref = hs_now();
		break;
	case TBPRD:
		if (reg(e, TBCTL) & (1U << 3))
			e->prd = (uint16_t)nv;
		else
			e->prd_pending = true;
		break;
	default:
		break;
	}
	ehrpwm_rebase(e);
}

/* CMPA/CMPB/CMPCTL writes: shadow or immediate. */
static void ehrpwm_write_cmp(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv,
			    uint32_t written)
{
	struct ehrpwm *e = ctx;
	uint32_t cmpctl = reg(e, CMPCTL), pos = tb_position(e);    /* compare values do not move it */

	if (a->offset == CMPA) {
		if (cmpctl & (1U << 4)) {
			e->cmpa = (uint16_t)nv;
		} else {
			e->cmpa_pending = true;
			hs_reg_update(e->r, CMPCTL, 0, 1U << 8);
		}
	} else if (a->offset == CMPB) {
		if (cmpctl & (1U << 6)) {
			e->cmpb = (uint16_t)nv;
		} else {
			e->cmpb_pending = true;
			hs_reg_update(e->r, CMPCTL, 0, 1U << 9);
		}
	}
	ehrpwm_update(e, pos);
	ehrpwm_schedule_load(e, pos);
}

/* Action-qualifier writes and software forces. */
static void ehrpwm_write_aq(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv,
			   uint32_t written)
{
	struct ehrpwm *e = ctx;

	if (a->offset == AQSFRC && (written & ((1U << 2) | (1U << 5)))) {
		/* one-time software forces: OTSFA (bit 2) applies ACTSFA (1:0), OTSFB (bit 5) ACTSFB (4:3) */
		if (written & (1U << 2))
			e->level[0] = aq_apply(e->level[0], written & 3U);
		if (written & (1U << 5))
			e->level[1] = aq_apply(e->level[1], (written >> 3) & 3U);
		hs_reg_update(e->r, AQSFRC, (1U << 2) | (1U << 5), 0);
	}
	ehrpwm_update(e, tb_position(e));
}

/* Features the model does not implement: a write other than their reset state is loud. */
static void ehrpwm_write_unmodelled(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv,
				   uint32_t written)
{
	if (nv != 0 && a->offset != TZCLR && a->offset != ETCLR)
		rtos_host_bug("host_sim", "%s.%s = 0x%04x: dead band, chopper, trip zones and event "
			      "triggers are not modelled", ((struct ehrpwm *)ctx)->name, a->reg->name,
			      (unsigned)nv);
}

static const struct hs_reg ehrpwm_regs[] = {
	{ .name = "TBCTL", .offset = TBCTL, .width = 2, .kind = HS_RW, .reset = 0x0083,
	  .after_write = ehrpwm_write_tb },
	{ .name = "TBSTS", .offset = TBSTS, .width = 2, .kind = HS_W1C, .reset = 0x0001, .mask = 0x0006,
	  .before_read = ehrpwm_read_tbsts },
	{ .name = "TBPHSHR", .offset = TBPHSHR, .width = 2, .kind = HS_RW },
	{ .name = "TBPHS", .offset = TBPHS, .width = 2, .kind = HS_RW },
	{ .name = "TBCNT", .offset = TBCNT, .width = 2, .kind = HS_RW,
	  .before_read = ehrpwm_read_tbcnt, .after_write = ehrpwm_write_tb },
	{ .name = "TBPRD", .offset = TBPRD, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_tb },
	{ .name = "CMPCTL", .offset = CMPCTL, .width = 2, .kind = HS_RW, .mask = 0x005F,
	  .after_write = ehrpwm_write_cmp },
	{ .name = "CMPAHR", .offset = CMPAHR, .width = 2, .kind = HS_RW },
	{ .name = "CMPA", .offset = CMPA, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_cmp },
	{ .name = "CMPB", .offset = CMPB, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_cmp },
	{ .name = "AQCTLA", .offset = AQCTLA, .width = 2, .kind = HS_RW, .mask = 0x0FFF,
	  .after_write = ehrpwm_write_aq },
	{ .name = "AQCTLB", .offset = AQCTLB, .width = 2, .kind = HS_RW, .mask = 0x0FFF,
	  .after_write = ehrpwm_write_aq },
	{ .name = "AQSFRC", .offset = AQSFRC, .width = 2, .kind = HS_RW, .mask = 0x00FF,
	  .after_write = ehrpwm_write_aq },
	{ .name = "AQCSFRC", .offset = AQCSFRC, .width = 2, .kind = HS_RW, .mask = 0x000F,
	  .after_write = ehrpwm_write_aq },
	{ .name = "DBCTL", .offset = DBCTL, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_unmodelled },
	{ .name = "DBRED", .offset = DBRED, .width = 2, .kind = HS_RW },
	{ .name = "DBFED", .offset = DBFED, .width = 2, .kind = HS_RW },
	{ .name = "TZSEL", .offset = TZSEL, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_unmodelled },
	{ .name = "TZCTL", .offset = TZCTL, .width = 2, .kind = HS_RW },
	{ .name = "TZEINT", .offset = TZEINT, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_unmodelled },
	{ .name = "TZFLG", .offset = TZFLG, .width = 2, .kind = HS_RO },
	{ .name = "TZCLR", .offset = TZCLR, .width = 2, .kind = HS_W1C, .alias = "TZFLG" },
	{ .name = "TZFRC", .offset = TZFRC, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_unmodelled },
	{ .name = "ETSEL", .offset = ETSEL, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_unmodelled },
	{ .name = "ETPS", .offset = ETPS, .width = 2, .kind = HS_RW },
	{ .name = "ETFLG", .offset = ETFLG, .width = 2, .kind = HS_RO },
	{ .name = "ETCLR", .offset = ETCLR, .width = 2, .kind = HS_W1C, .alias = "ETFLG" },
	{ .name = "ETFRC", .offset = ETFRC, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_unmodelled },
	{ .name = "PCCTL", .offset = PCCTL, .width = 2, .kind = HS_RW, .after_write = ehrpwm_write_unmodelled },
};

/* Low fraction of output channel (0 = A, 1 = B). */
static double ehrpwm_low_fraction(const void *ctx, unsigned channel)
{
	const struct ehrpwm *e = ctx;

	return e->low[channel ? 1 : 0];
}

/* PWM frequency in Hz of both outputs (0 if stopped). */
static double ehrpwm_frequency(const void *ctx, unsigned channel)
{
	const struct ehrpwm *e = ctx;
	uint32_t tbctl;

	(void)channel;
	if (!e->running)
		return 0;
	tbctl = reg(e, TBCTL);
	return (double)tbclk_hz(tbctl) / tb_period_cycles(e, tbctl);
}

static const struct hs_pwm_source_ops ehrpwm_ops = { ehrpwm_low_fraction, ehrpwm_frequency };

/* One eHRPWM module: its region name, base and outputs. */
struct ehrpwm_instance {
	const char *name;
	uint32_t phys;
	enum hs_pwm_output out[2];
};

static const struct ehrpwm_instance ehrpwm_instances[] = {
	{ "EHRPWM0", HS_EHRPWM0_BASE, { HS_PWM_EHRPWM0_A, HS_PWM_EHRPWM0_B } },
	{ "EHRPWM1", HS_EHRPWM1_BASE, { HS_PWM_EHRPWM1_A, HS_PWM_EHRPWM1_B } },
};

/* Creates an eHRPWM region and state (both modules share PSC1 LPSC 17). */
static ER ehrpwm_create(const struct ehrpwm_instance *in, void **ctx)
{
	struct ehrpwm *e = calloc(1, sizeof(*e));

	if (!e)
		return E_NOMEM;
	e->tbclk_tbctl = UINT32_MAX;    /* no TBCTL value: tbclk_of works it out on first use */
	e->r = hs_region_add(&(struct hs_region_cfg){ .name = in->name, .phys = in->phys,
		.size = 0x1000, .regs = ehrpwm_regs, .nregs = HS_ARRAY_SIZE(ehrpwm_regs),
		.power = HS_PSC1_MODULE(HS_LPSC1_EHRPWM), .ctx = e });
	if (!e->r) {
		free(e);
		return E_PAR;
	}
	for (unsigned i = 0; i < HS_ARRAY_SIZE(ehrpwm_regs); i++)
		e->value[ehrpwm_regs[i].offset / 2U] = hs_reg_value_ptr(e->r, ehrpwm_regs[i].offset);
	e->name = in->name;
	e->out[0] = in->out[0];
	e->out[1] = in->out[1];
	e->low[0] = e->low[1] = 1.0;    /* outputs low after reset */
	e->syscfg_watch = hs_syscfg_watch(ehrpwm_syscfg_changed, e);
	hs_pwm_output_attach(e->out[0], &ehrpwm_ops, e, 0);
	hs_pwm_output_attach(e->out[1], &ehrpwm_ops, e, 1);
	*ctx = e;
	return E_OK;
}

static ER ehrpwm0_create(const struct hs_board_cfg *cfg, void **ctx)
{
	(void)cfg;
	return ehrpwm_create(&ehrpwm_instances[0], ctx);
}

static ER ehrpwm1_create(const struct hs_board_cfg *cfg, void **ctx)
{
	(void)cfg;
	return ehrpwm_create(&ehrpwm_instances[1], ctx);
}

/* Frees an eHRPWM module. */
static void ehrpwm_destroy(void *ctx)
{
	struct ehrpwm *e = ctx;

	hs_event_cancel(&e->load_ev);
	hs_syscfg_unwatch(e->syscfg_watch);
	hs_pwm_output_attach(e->out[0], NULL, NULL, 0);
	hs_pwm_output_attach(e->out[1], NULL, NULL, 0);
	free(e);
}

const struct hs_device hs_ehrpwm0_device = { "EHRPWM0", ehrpwm0_create, NULL, ehrpwm_destroy };
const struct hs_device hs_ehrpwm1_device = { "EHRPWM1", ehrpwm1_create, NULL, ehrpwm_destroy };
