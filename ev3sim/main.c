/*
 * main.c — build/host/ev3sim: the command line lives in ev3sim/src/cli.c.
 */
#include "ev3sim/cli.h"

int main(int argc, char **argv)
{
	return ev3sim_main(argc, argv);
}
