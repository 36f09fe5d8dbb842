/*
 * app_runner.c — main() of an EV3RT app's runner (`ev3sim run APP_DIR`
 * builds it with the app): runs ev3rt_app_cfg, the app's configuration
 * generated from its app.cfg, with the command line's options.
 */
#include "ev3sim/run.h"

#ifndef EV3SIM_APP_NAME
#define EV3SIM_APP_NAME "app"
#endif

extern const struct rtos_cfg ev3rt_app_cfg;

int main(int argc, char **argv)
{
	return ev3sim_run_main(argc, argv, EV3SIM_APP_NAME, &ev3rt_app_cfg);
}
