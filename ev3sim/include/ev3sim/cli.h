/*
 * cli.h — ev3sim's command line: `ev3sim balance|motor|sensors|run [options]`.
 * Exit status: 0 done (for balance: whatever the result), 1 the run failed
 * (boot, output files, gnuplot), 2 bad command line; an app that ends the
 * system on a fault (docs/ev3sim.md): 3 a task stalled (a loop that makes no
 * service call), 4 a crash (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT), 5 a
 * task overran its stack (used more than its configured size, or ran off
 * its host stack).
 */
#ifndef EV3SIM_CLI_H
#define EV3SIM_CLI_H

#include "rtos_host.h"

#define EV3SIM_EXIT_OK     0
#define EV3SIM_EXIT_FAIL   1
#define EV3SIM_EXIT_USAGE  2
#define EV3SIM_EXIT_STALL  RTOS_HOST_EXIT_STALL
#define EV3SIM_EXIT_CRASH  RTOS_HOST_EXIT_CRASH
#define EV3SIM_EXIT_STACK  RTOS_HOST_EXIT_STACK

/* The largest --gyro-noise (deg/s) balance and run accept. */
#define EV3SIM_MAX_GYRO_NOISE_DPS 1000.0

/* Runs ev3sim with its arguments (argv[0] is the program name). */
int ev3sim_main(int argc, char **argv);

#endif /* EV3SIM_CLI_H */
