/*
 * live.h — `ev3sim run --live`: the run watched and steered from a browser.
 * Host only.
 *
 * Two halves.  The simulation's (live.c, in the library): at every step of
 * the run (ev3sim_run's 10 ms chunks of virtual time) it applies what the
 * page asked for since the last step — a button pressed or released, the
 * pace, pause, a single step, stop — and records what the page shows: the
 * robot's pose and the mat, the display, the LEDs and buttons, each port's
 * device and value, and a row of signals for the plot.  Inputs take effect
 * only there, at a step boundary, so a run stays in virtual time: one in
 * which nothing is clicked computes what the same run without --live does.
 * The server's (live_http.c, in the program only: libmicrohttpd): it serves
 * the page and its JSON on 127.0.0.1 from a thread of its own, through the
 * calls below.  Without --live neither half runs: no thread, no socket, one
 * test per step.
 */
#ifndef EV3SIM_LIVE_H
#define EV3SIM_LIVE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "kernel.h"

struct ev3sim_run_opts;

#define EV3SIM_LIVE_DEFAULT_PORT 8033U
/* --pace N: at most this many times real time; 0 is as fast as possible. */
#define EV3SIM_LIVE_MAX_PACE     1000.0

/* The HTTP server (live_http.c sets it; NULL: this program has none). */
struct ev3sim_live_server {
	/* Listens on 127.0.0.1:port (0: a free port) and serves from a thread;
	 * the port it got in *bound.  E_OK, or E_SYS with the reason in err. */
	ER (*start)(unsigned port, unsigned *bound, char *err, size_t errlen);
	/* Stops serving and joins the thread. */
	void (*stop)(void);
};
extern const struct ev3sim_live_server *ev3sim_live_server;

/* ---- the simulation's half (ev3sim_run calls them) ---- */

/* Starts the live view of the run o: the server on o's port, the pace o
 * asks for; prints the page's address on stderr.  E_OK, or E_SYS (no
 * server in this program, the port busy: the reason in err). */
ER ev3sim_live_begin(const struct ev3sim_run_opts *o, char *err, size_t errlen);
/* At a step boundary: applies the page's inputs, records the state, then
 * waits as the pace, a pause or a single step asks.  False once the page
 * asked the run to stop. */
bool ev3sim_live_step(void);
/* The run's last state, when its steps are over (before the power-off). */
void ev3sim_live_record(void);
/* The run ended (summary: its line, or NULL): stops the server. */
void ev3sim_live_end(const char *summary);

/* ---- the server's half (any thread) ---- */

/* The state as JSON: the latest snapshot, and the plot's rows after row
 * number since (at most a few thousand).  Returns the length written
 * (truncated to len - 1, NUL-terminated). */
size_t ev3sim_live_status_json(uint64_t since, char *buf, size_t len);
/* The mat and the robot's layout as JSON (constant during a run). */
size_t ev3sim_live_world_json(char *buf, size_t len);
/* One command from the page: "press" / "release" with arg a button name
 * (left right up down enter back), "pace" with arg N (0: as fast as
 * possible), "pause", "resume", "step", "stop".  E_OK, or E_PAR. */
ER ev3sim_live_command(const char *cmd, const char *arg);

#endif /* EV3SIM_LIVE_H */
