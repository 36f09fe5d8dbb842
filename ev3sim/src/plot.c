/*
 * plot.c — the balance plot through gnuplot (plot.h).  gnuplot reads the
 * series' CSV file and a script from a pipe, and draws into a temporary file
 * that is then copied to the output with every write checked.
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

int ev3sim_copy_file(const char *from, const char *to)
{
	char buf[8192];
	FILE *in = fopen(from, "rb"), *out;
	size_t n;
	int status = 0;

	if (in == NULL)
		return -1;
	out = fopen(to, "wb");
	if (out == NULL) {
		fclose(in);
		return -1;
	}
	while ((n = fread(buf, 1, sizeof(buf), in)) > 0)
		if (fwrite(buf, 1, n, out) != n)
			status = -1;
	if (ferror(in) || ferror(out))
		status = -1;
	fclose(in);
	if (fclose(out) != 0)
		status = -1;
	return status;
}

int ev3sim_plot(const char *csv_path, const char *title, const char *png_path, char *err, size_t errlen)
{
	char png[] = "/tmp/ev3sim-plot-XXXXXX";
	FILE *gp;
	int fd, status;

	if (!ev3sim_have_gnuplot()) {
		snprintf(err, errlen, "gnuplot not found on PATH (install gnuplot-nox: make deps)");
		return -1;
	}
	/* gnuplot draws into a temporary file: whatever happens, no PNG bytes reach a terminal,
	 * and writing the real output is checked here */
	fd = mkstemp(png);
	if (fd < 0) {
		snprintf(err, errlen, "cannot create a temporary file: %s", strerror(errno));
		return -1;
	}
	close(fd);
	gp = popen("gnuplot", "w");
	if (gp == NULL) {
		snprintf(err, errlen, "cannot run gnuplot: %s", strerror(errno));
		unlink(png);
		return -1;
	}
	/* the series' columns: EV3SIM_SERIES_HEADER; every other 1 ms row is enough for a PNG */
	fprintf(gp,
		"set terminal pngcairo size 1200,900 font 'sans,10'\n"
		"set output '%s'\n"
		"set datafile separator ','\n"
		"set multiplot layout 3,1 title '%s'\n"
		"set grid\n"
		"set lmargin 12\n"
		"set ylabel 'tilt (deg)'\n"
		"plot '%s' every 2::1 using 1:2 with lines lw 1.5 title 'body tilt'\n"
		"set ylabel 'wheel angle (deg)'\n"
		"plot '%s' every 2::1 using 1:4 with lines lw 1.5 title 'wheel rotation'\n"
		"set ylabel 'motor power (%%)'\n"
		"set xlabel 'time after release (s)'\n"
		"set yrange [-105:105]\n"
		"plot '%s' every 2::1 using 1:6 with steps title 'commanded power', "
		"'' every 2::1 using 1:7 with lines title 'H-bridge A', "
		"'' every 2::1 using 1:8 with lines title 'H-bridge D'\n"
		"unset multiplot\n",
		png, title, csv_path, csv_path, csv_path);
	status = pclose(gp);
	if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		snprintf(err, errlen, "gnuplot failed drawing %s", png_path);
		unlink(png);
		return -1;
	}
	if (ev3sim_copy_file(png, png_path) != 0) {
		snprintf(err, errlen, "cannot write %s: %s", png_path, strerror(errno ? errno : EIO));
		unlink(png);
		return -1;
	}
	unlink(png);
	return 0;
}
