/*
 * scenario.c — booting and running a simulated EV3 in one call each, and
 * the deterministic PRNG models draw from.  Host only.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

static struct {
	bool booted;
	uint64_t seed;
} sim;

ER hs_sim_boot(const struct hs_scenario *scn)
{
	ER er;

	if (!scn || !scn->rtos) {
		rtos_host_bug("host_sim", "hs_sim_boot: a scenario with an rtos configuration is required");
		return E_PAR;
	}
	if (sim.booted || hs_board_active())
		return E_OBJ;
	er = hs_board_init(scn->board);
	if (er != E_OK)
		return er;
	/* an output file that cannot be written is the user's error, not a bug: E_SYS with errno */
	if ((scn->vcd_path && hs_trace_open_vcd(scn->vcd_path) != 0) ||
	    (scn->csv_path && hs_trace_open_csv(scn->csv_path) != 0)) {
		int saved = errno;

		hs_board_shutdown();
		errno = saved;
		return E_SYS;
	}
	if (scn->reglog_filter)
		hs_trace_reglog(scn->reglog_filter, scn->reglog);
	sim.seed = scn->seed;
	hs_rng_set_base_seed(scn->seed);
	er = rtos_host_boot(scn->rtos);
	if (er != E_OK) {
		hs_board_shutdown();
		return er;
	}
	hs_board_start();
	sim.booted = true;
	return E_OK;
}

void hs_sim_run_for(uint64_t ns)
{
	rtos_host_run_for(ns);
}

void hs_sim_run_until(uint64_t t_ns)
{
	rtos_host_run_until(t_ns);
}

hs_event_t hs_sim_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg)
{
	if (!fn) {
		rtos_host_bug("host_sim", "hs_sim_at: NULL function");
		return 0;
	}
	return hs_event_at(t_ns, fn, arg);
}

ER hs_sim_shutdown(void)
{
	ER written;

	if (sim.booted)
		rtos_host_shutdown();
	written = hs_trace_close() == 0 ? E_OK : E_SYS;
	hs_board_shutdown();
	memset(&sim, 0, sizeof(sim));
	hs_rng_set_base_seed(0);
	return written;
}

uint64_t hs_sim_seed(void)
{
	return sim.seed;
}
