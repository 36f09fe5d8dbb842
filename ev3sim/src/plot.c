/*
 * plot.c — the balance plot through gnuplot (plot.h).  The series goes to a
 * temporary data file; gnuplot reads a script from a pipe.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/wait.h>
#include "ev3sim/plot.h"

bool ev3sim_have_gnuplot(void)
{
	const char *path = getenv("PATH");
	char dir[4096];

	while (path && *path) {
		size_t n = strcspn(path, ":");

		if (n > 0 && n + sizeof("/gnuplot") < sizeof(dir)) {
			memcpy(dir, path, n);
			strcpy(dir + n, "/gnuplot");
			if (access(dir, X_OK) == 0)
				return true;
		}
		path += n + (path[n] == ':');
	}
	return false;
}

/* Writes t, tilt, wheel, power, duty A, duty D, one row per 2 ms (enough for a PNG). */
static int write_data(const struct ev3sim_balance_result *res, FILE *f)
{
	for (size_t i = 0; i < res->nrows; i += 2) {
		const struct ev3sim_series_row *w = &res->rows[i];

		fprintf(f, "%.3f %.4f %.3f %d %.2f %.2f\n", w->t_s, w->tilt_deg, w->wheel_deg, w->power,
			w->duty_a, w->duty_d);
	}
	return ferror(f) ? -1 : 0;
}

int ev3sim_plot(const struct ev3sim_balance_result *res, const char *title, const char *png_path,
		char *err, size_t errlen)
{
	char data[] = "/tmp/ev3sim-plot-XXXXXX";
	FILE *f, *gp;
	int fd, status;

	if (!ev3sim_have_gnuplot()) {
		snprintf(err, errlen, "gnuplot not found on PATH (install gnuplot-nox: make deps)");
		return -1;
	}
	fd = mkstemp(data);
	if (fd < 0 || (f = fdopen(fd, "w")) == NULL) {
		snprintf(err, errlen, "cannot create a temporary file: %s", strerror(errno));
		if (fd >= 0)
			close(fd);
		return -1;
	}
	if (write_data(res, f) != 0 || fclose(f) != 0) {
		snprintf(err, errlen, "cannot write %s", data);
		unlink(data);
		return -1;
	}
	gp = popen("gnuplot", "w");
	if (gp == NULL) {
		snprintf(err, errlen, "cannot run gnuplot: %s", strerror(errno));
		unlink(data);
		return -1;
	}
	fprintf(gp,
		"set terminal pngcairo size 1200,900 font 'sans,10'\n"
		"set output '%s'\n"
		"set datafile separator whitespace\n"
		"set multiplot layout 3,1 title '%s'\n"
		"set grid\n"
		"set lmargin 12\n"
		"set ylabel 'tilt (deg)'\n"
		"plot '%s' using 1:2 with lines lw 1.5 title 'body tilt'\n"
		"set ylabel 'wheel angle (deg)'\n"
		"plot '%s' using 1:3 with lines lw 1.5 title 'wheel rotation'\n"
		"set ylabel 'motor power (%%)'\n"
		"set xlabel 'time after release (s)'\n"
		"set yrange [-105:105]\n"
		"plot '%s' using 1:4 with steps title 'commanded power', "
		"'' using 1:5 with lines title 'H-bridge A', '' using 1:6 with lines title 'H-bridge D'\n"
		"unset multiplot\n",
		png_path, title, data, data, data);
	status = pclose(gp);
	unlink(data);
	if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		snprintf(err, errlen, "gnuplot failed writing %s", png_path);
		return -1;
	}
	return 0;
}
