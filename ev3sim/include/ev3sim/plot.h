/*
 * plot.h — the balance run's PNG: tilt, wheel angle and motor power against
 * time, drawn by gnuplot (package gnuplot-nox, installed by `make deps`).
 */
#ifndef EV3SIM_PLOT_H
#define EV3SIM_PLOT_H

#include <stdbool.h>
#include <stddef.h>

/* Whether a gnuplot executable is on the PATH. */
bool ev3sim_have_gnuplot(void);

/* Draws the series CSV file (EV3SIM_SERIES_HEADER's columns) into the PNG; 0, or -1 with a
 * message in err (gnuplot missing or failing, the PNG not written completely). */
int ev3sim_plot(const char *csv_path, const char *title, const char *png_path, char *err, size_t errlen);

/* Copies the file at from to the path to, every write checked; 0 or -1 (errno). */
int ev3sim_copy_file(const char *from, const char *to);

#endif /* EV3SIM_PLOT_H */
