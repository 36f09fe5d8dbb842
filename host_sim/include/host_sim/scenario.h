/*
 * scenario.h — running a simulated EV3 from tests and from ev3sim.  Host only.
 *
 *   struct hs_scenario scn = { .rtos = &app_cfg, .seed = 42, .vcd_path = "run.vcd" };
 *   if (hs_sim_boot(&scn) != E_OK) ...
 *   hs_sim_at(5000000, push_button, NULL);   inject an event at 5 ms
 *   hs_sim_run_for(100000000);               100 ms of virtual time
 *   ok(hs_signal_value(hs_trace_find("gpio", "GP5_11")) == 1, ...);
 *   hs_sim_shutdown();
 *
 * Models draw randomness from hs_rng streams seeded from the scenario seed
 * and their own name, so adding a model does not change the others' numbers.
 */
#ifndef HOST_SIM_SCENARIO_H
#define HOST_SIM_SCENARIO_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include "rtos_cfg.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/rng.h"

struct hs_scenario {
	const struct rtos_cfg *rtos;         /* the application's configuration (required) */
	const struct hs_board_cfg *board;    /* NULL: defaults, core peripherals only */
	uint64_t seed;                       /* for hs_rng_stream */
	const char *vcd_path;                /* NULL: no VCD */
	const char *csv_path;                /* NULL: no CSV */
	const char *reglog_filter;           /* NULL: no register log; "*" or "GPIO,SPI0" */
	FILE *reglog;                        /* NULL: register log to rtos_host_trace */
};

/* hs_board_init + traces + rtos_host_boot + hs_board_start.  Returns E_OK or
 * the first error (the board is shut down again on error); E_SYS with errno
 * if a trace file cannot be created. */
ER hs_sim_boot(const struct hs_scenario *scn);
/* Runs the system for ns / until absolute t_ns of virtual time. */
void hs_sim_run_for(uint64_t ns);
void hs_sim_run_until(uint64_t t_ns);
/* Injects fn(arg) at absolute virtual time t_ns (in the hardware's context). */
hs_event_t hs_sim_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg);
/* rtos_host_shutdown + hs_board_shutdown (closes the trace files).  E_OK, or
 * E_SYS if a trace file could not be written completely (a full disk). */
ER hs_sim_shutdown(void);
/* The scenario seed (0 without a scenario). */
uint64_t hs_sim_seed(void);

/*
 * Scenario scripts: one command per line, '#' starts a comment.  Times and
 * durations take a unit (ns, us, ms, s; none = ns).  "at <time>" before a
 * command schedules it at that absolute virtual time instead of running it
 * now.
 *   run <duration>                 run the system that long
 *   until <time>                   run until the absolute time
 *   drive <pin> high|low|float|pullup|pulldown
 *   irq <sysint>                   a request on an AINTC system interrupt
 *   expect <pin> 0|1               the pin's level now
 *   expect <scope>.<name> <value>  a trace signal's value now
 *   expect-bugs <n>                bug reports since boot
 * Pins are named GP<bank>_<bit>.  Returns E_OK; E_PAR with "line N: ..." in
 * err for a malformed line (nothing after it runs); E_OBJ with the first
 * failed expectation in err (the script runs to its end).
 */
ER hs_sim_script(const char *text, char *err, size_t errlen);

#endif /* HOST_SIM_SCENARIO_H */
