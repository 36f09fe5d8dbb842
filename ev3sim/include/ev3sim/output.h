/*
 * output.h — ev3sim's output files and standard output: every write error is
 * found and reported naming the output, and no output can hang a run.
 *
 * A FIFO no process reads would block open() for ever: outputs are opened
 * with O_NONBLOCK, so such a FIFO is refused at once ("no process is reading
 * it").  A FIFO with a reader takes the outputs written as the run goes
 * (balance --csv and --log, run --csv and --audio); outputs another writer
 * opens by name later (--trace, --plot, --lcd, --lcd-video) need a regular
 * file or a device, and a FIFO there is refused before the run.  Host only.
 */
#ifndef EV3SIM_OUTPUT_H
#define EV3SIM_OUTPUT_H

#include <stdbool.h>
#include <stdio.h>

/* Opens path for writing (created, truncated) without ever blocking; NULL
 * with errno set if it cannot. */
FILE *ev3sim_fopen_output(const char *path);

/* Why an output could not be opened (errno err), in words a user can act on. */
const char *ev3sim_output_error(int err);

/* ev3sim_fopen_output, and on failure "ev3sim CMD: cannot write PATH:
 * reason" on stderr. */
FILE *ev3sim_open_output(const char *cmd, const char *path);

/* Closes f (opened for path): false, after "ev3sim CMD: cannot write PATH
 * completely: reason" on stderr, if any of it could not be written. */
bool ev3sim_close_output(const char *cmd, FILE *f, const char *path);

/* Whether an output another writer opens by name later can be created at
 * path (it is created, empty; a FIFO is refused); if not, says so on stderr
 * as "ev3sim CMD: cannot write PATH: reason".  Outputs are checked before a
 * run, so that an hour of simulation is not lost at its end. */
bool ev3sim_can_create(const char *cmd, const char *path);

/* The end of a command whose exit status is status: flushes standard
 * output; if anything written to it was lost (a full disk, a closed
 * pipe), says so on stderr and returns EV3SIM_EXIT_FAIL, else status. */
int ev3sim_finish_stdout(const char *cmd, int status);

#endif /* EV3SIM_OUTPUT_H */
