/*
 * world_plot.h — `ev3sim run --plot FILE.png` for a world: the robot's path
 * drawn on the mat with the walls and obstacles, above chosen signals
 * against time, drawn by gnuplot (package gnuplot-nox) as the balance plot is
 * (plot.h).  The series is kept in memory every 10 ms of the run.
 */
#ifndef EV3SIM_WORLD_PLOT_H
#define EV3SIM_WORLD_PLOT_H

#include <stdbool.h>
#include <stddef.h>

/* The signals a plot can show, as bits. */
enum {
	EV3SIM_SIGNAL_HEADING   = 1U << 0,     /* heading, deg (counter-clockwise) */
	EV3SIM_SIGNAL_IN1       = 1U << 1,     /* what port 1's sensor measures (world.h) */
	EV3SIM_SIGNAL_IN2       = 1U << 2,
	EV3SIM_SIGNAL_IN3       = 1U << 3,
	EV3SIM_SIGNAL_IN4       = 1U << 4,
	EV3SIM_SIGNAL_LEFT      = 1U << 5,     /* the left wheel's shaft angle, deg */
	EV3SIM_SIGNAL_RIGHT     = 1U << 6,
	EV3SIM_SIGNAL_CLEARANCE = 1U << 7,     /* the body's distance to the nearest obstacle, mm */
};

/* Parses a comma-separated list of heading, in1..in4, left, right,
 * clearance into bits; false (with the bad name in err) for another. */
bool ev3sim_plot_signals_parse(const char *list, unsigned *bits, char *err, size_t errlen);

/* Starts an empty series. */
void ev3sim_world_series_begin(void);
/* Adds the running world's state now (ev3sim_world_now) and its wheels' angles. */
void ev3sim_world_series_add(void);

/* Draws the series over the world that ran (ev3sim_world_current) into the
 * PNG; signals 0: the heading and every port whose sensor the world drives.
 * 0, or -1 with a message in err. */
int ev3sim_world_plot(const char *png_path, unsigned signals, const char *title, char *err, size_t errlen);

#endif /* EV3SIM_WORLD_PLOT_H */
