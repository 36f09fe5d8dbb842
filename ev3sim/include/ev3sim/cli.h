/*
 * cli.h — ev3sim's command line: `ev3sim balance|motor|sensors [options]`.
 * Exit status: 0 done (for balance: whatever the result), 1 the run failed
 * (boot, output files, gnuplot), 2 bad command line.
 */
#ifndef EV3SIM_CLI_H
#define EV3SIM_CLI_H

#define EV3SIM_EXIT_OK     0
#define EV3SIM_EXIT_FAIL   1
#define EV3SIM_EXIT_USAGE  2

/* Runs ev3sim with its arguments (argv[0] is the program name). */
int ev3sim_main(int argc, char **argv);

#endif /* EV3SIM_CLI_H */
