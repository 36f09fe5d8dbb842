/*
 * world_plot.c — a world run's PNG (world_plot.h).  gnuplot reads three
 * temporary files — the mat as raw RGB pixels, the obstacles' outlines and
 * the series — and a script from a pipe, and draws into a temporary PNG that
 * is then copied to the output with every write checked (plot.c's way).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/wait.h>
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_motor.h"
#include "ev3sim/plot.h"
#include "ev3sim/world.h"
#include "ev3sim/world_plot.h"

#define PI 3.14159265358979323846
#define MAT_MAX_PX 800          /* the mat's raster: its longer side */
#define NSIGNALS 8

/* One row of the series: time, pose, the ports, the wheels, the clearance. */
struct row {
	double t, x, y, heading, in[4], left, right, clearance_mm;
};

static struct {
	struct row *rows;
	size_t n, cap;
} series;

static const struct {
	const char *name, *label;
	unsigned column;                /* in the series file, from 1 */
} signals[NSIGNALS] = {
	{ "heading", "heading (deg)", 4 },
	{ "in1", "port 1", 5 }, { "in2", "port 2", 6 }, { "in3", "port 3", 7 }, { "in4", "port 4", 8 },
	{ "left", "left wheel (deg)", 9 }, { "right", "right wheel (deg)", 10 },
	{ "clearance", "clearance (mm)", 11 },
};

bool ev3sim_plot_signals_parse(const char *list, unsigned *bits, char *err, size_t errlen)
{
	const char *p = list;

	*bits = 0;
	while (*p) {
		size_t n = strcspn(p, ",");
		unsigned i;

		for (i = 0; i < NSIGNALS; i++)
			if (strlen(signals[i].name) == n && strncmp(p, signals[i].name, n) == 0)
				break;
		if (i == NSIGNALS) {
			snprintf(err, errlen, "unknown signal '%.*s' (heading, in1..in4, left, right, clearance)",
				 (int)n, p);
			return false;
		}
		*bits |= 1U << i;
		p += n + (p[n] == ',');
	}
	if (*bits == 0) {
		snprintf(err, errlen, "no signal named (heading, in1..in4, left, right, clearance)");
		return false;
	}
	return true;
}

void ev3sim_world_series_begin(void)
{
	free(series.rows);
	memset(&series, 0, sizeof(series));
}

/* A wheel motor's shaft angle, 0 when it is gone. */
static double wheel_deg(unsigned port)
{
	struct hs_motor *m = ev3_output_motor(port);

	return m ? hs_motor_angle_deg(m) : 0.0;
}

void ev3sim_world_series_add(void)
{
	const struct ev3sim_world_state *s = ev3sim_world_now();
	const struct ev3sim_world *w = ev3sim_world_current();
	struct row *r;

	if (series.n == series.cap) {
		size_t cap = series.cap ? series.cap * 2 : 4096;
		struct row *p = realloc(series.rows, cap * sizeof(*p));

		if (p == NULL)
			return;     /* the plot shows what it has */
		series.rows = p;
		series.cap = cap;
	}
	r = &series.rows[series.n++];
	*r = (struct row){ s->t_ns * 1e-9, s->x, s->y, s->heading_deg, { 0 }, wheel_deg(w->robot.left_port),
			   wheel_deg(w->robot.right_port), s->clearance_m < 1e29 ? s->clearance_m * 1000.0 : NAN };
	memcpy(r->in, s->port_value, sizeof(r->in));
}

/* Writes the mat as raw RGB rows, the lowest (y0) first, as gnuplot's binary
 * array reads them; its size in *cols x *rows.  0 or -1. */
static int write_mat(FILE *f, const struct ev3sim_world_mat *m, unsigned *cols, unsigned *rows)
{
	double scale = MAT_MAX_PX / fmax(m->width, m->height);

	*cols = (unsigned)ceil(m->width * scale);
	*rows = (unsigned)ceil(m->height * scale);
	for (unsigned j = 0; j < *rows; j++)
		for (unsigned i = 0; i < *cols; i++) {
			uint8_t px[3];

			ev3sim_world_mat_rgb(m, m->x0 + (i + 0.5) * m->width / *cols,
					     m->y0 + (j + 0.5) * m->height / *rows, px);
			if (fwrite(px, 1, 3, f) != 3)
				return -1;
		}
	return 0;
}

/* Writes every obstacle's outline as a polyline, blank lines between. */
static void write_obstacles(FILE *f, const struct ev3sim_world *w)
{
	for (unsigned i = 0; i < w->nobstacles; i++) {
		const struct ev3sim_obstacle *o = &w->obstacles[i];

		if (o->kind == EV3SIM_OBST_SEGMENT) {
			fprintf(f, "%g,%g\n%g,%g\n", o->x0, o->y0, o->x1, o->y1);
		} else if (o->kind == EV3SIM_OBST_BOX) {
			fprintf(f, "%g,%g\n%g,%g\n%g,%g\n%g,%g\n%g,%g\n", o->x0, o->y0, o->x1, o->y0, o->x1, o->y1,
				o->x0, o->y1, o->x0, o->y0);
		} else {
			for (int k = 0; k <= 32; k++)
				fprintf(f, "%g,%g\n", o->x0 + o->r * cos(k * PI / 16), o->y0 + o->r * sin(k * PI / 16));
		}
		fprintf(f, "\n");
	}
	/* gnuplot refuses an empty file: one point far outside the view */
	if (w->nobstacles == 0)
		fprintf(f, "1e9,1e9\n");
}

/* Closes f; false if any write to it failed. */
static bool close_ok(FILE *f)
{
	bool ok = !ferror(f);

	return fclose(f) == 0 && ok;
}

/* Creates a temporary file from template tmpl, opened for writing. */
static FILE *temp_file(char *tmpl)
{
	int fd = mkstemp(tmpl);

	return fd < 0 ? NULL : fdopen(fd, "wb");
}

/* Signal i's value in row r. */
static double signal_value(const struct row *r, unsigned i)
{
	switch (i) {
	case 0: return r->heading;
	case 5: return r->left;
	case 6: return r->right;
	case 7: return r->clearance_mm;
	default: return r->in[i - 1];
	}
}

/* Signal i's range over the series with a margin (gnuplot warns of an empty one). */
static void signal_range(unsigned i, double *lo, double *hi)
{
	*lo = INFINITY;
	*hi = -INFINITY;
	for (size_t k = 0; k < series.n; k++) {
		double v = signal_value(&series.rows[k], i);

		if (isfinite(v)) {
			*lo = fmin(*lo, v);
			*hi = fmax(*hi, v);
		}
	}
	if (!(*lo <= *hi))
		*lo = *hi = 0;
	double pad = (*hi - *lo) * 0.05 + (*hi == *lo ? 1.0 : 0.0);

	*lo -= pad;
	*hi += pad;
}

/* Signal i's axis label: a port's with what its sensor measures. */
static const char *port_label(const struct ev3sim_world *w, unsigned i)
{
	static char label[64];

	if (i < 1 || i > 4)
		return signals[i].label;
	snprintf(label, sizeof(label), "port %u", i);
	for (unsigned k = 0; k < w->robot.nmounts; k++) {
		const struct ev3sim_world_mount *mt = &w->robot.mounts[k];
		const char *what;

		if (mt->port != i - 1)
			continue;
		switch (mt->device) {
		case EV3SIM_IN_COLOR:      what = "reflect (%)"; break;
		case EV3SIM_IN_ULTRASONIC: what = "distance (mm)"; break;
		case EV3SIM_IN_IR:         what = "distance (mm)"; break;
		case EV3SIM_IN_TOUCH:      what = "pressed"; break;
		default:                   what = mt->pitch_axis ? "pitch (deg)" : "yaw (deg, cw)"; break;
		}
		snprintf(label, sizeof(label), "port %u %s", i, what);
	}
	return label;
}

/* The gnuplot script: the mat with the path on top, then one panel per signal. */
static void script(FILE *gp, const char *png, const char *title, const char *mat, unsigned cols,
		   unsigned rows, const char *obst, const char *data, unsigned bits)
{
	const struct ev3sim_world *w = ev3sim_world_current();
	const struct ev3sim_world_mat *m = &w->mat;
	unsigned nsig = 0, k = 0;
	double dx = m->width / cols, dy = m->height / rows;

	for (unsigned i = 0; i < NSIGNALS; i++)
		nsig += (bits >> i) & 1U;
	fprintf(gp,
		"set terminal pngcairo size 1000,%u font 'sans,10'\n"
		"set output '%s'\n"
		"set datafile separator ','\n"
		"set multiplot title '%s in the world %s'\n"
		"set origin 0,%g\nset size 1,%g\n"
		"set size ratio -1\n"
		"set xrange [%g:%g]\nset yrange [%g:%g]\n"
		"set xlabel 'x (m)'\nset ylabel 'y (m)'\n"
		"set key outside right top\n",
		700 + 180 * nsig, png, title ? title : "app", w->name,
		(double)(180 * nsig) / (700 + 180 * nsig), 700.0 / (700 + 180 * nsig),
		m->x0, m->x0 + m->width, m->y0, m->y0 + m->height);
	fprintf(gp,
		"plot '%s' binary array=(%u,%u) dx=%g dy=%g origin=(%g,%g) format='%%uchar%%uchar%%uchar' "
		"with rgbimage notitle, "
		"'%s' using 1:2 with lines lc rgb '#8b4513' lw 3 title 'walls', "
		"'%s' using 2:3 with lines lc rgb '#1060e0' lw 1.5 title 'path', "
		"'%s' every ::0::0 using 2:3 with points pt 7 ps 1.5 lc rgb '#20a020' title 'start', "
		"'%s' every ::%zu::%zu using 2:3 with points pt 7 ps 1.5 lc rgb '#e02020' title 'end'",
		mat, cols, rows, dx, dy, m->x0 + dx / 2, m->y0 + dy / 2, obst, data, data, data,
		series.n ? series.n - 1 : 0, series.n ? series.n - 1 : 0);
	if (w->has_goal)
		fprintf(gp, ", '+' using (%g+%g*cos(2*pi*$0/64)):(%g+%g*sin(2*pi*$0/64)) every ::0::64 "
			"with lines lc rgb '#20a020' dt 2 title 'goal'", w->goal_x, w->goal_r, w->goal_y, w->goal_r);
	fprintf(gp, "\nset size noratio\nset autoscale\nset xrange [0:%g]\nset xlabel ''\n",
		series.n ? series.rows[series.n - 1].t : 1.0);
	for (unsigned i = 0; i < NSIGNALS; i++) {
		double lo, hi;

		if (!((bits >> i) & 1U))
			continue;
		k++;
		signal_range(i, &lo, &hi);
		fprintf(gp, "set yrange [%g:%g]\n", lo, hi);
		fprintf(gp, "set origin 0,%g\nset size 1,%g\nset ylabel '%s'\n%s"
			"plot '%s' using 1:%u with lines lw 1.5 title '%s'\n",
			(double)(180 * (nsig - k)) / (700 + 180 * nsig), 180.0 / (700 + 180 * nsig),
			port_label(w, i), k == nsig ? "set xlabel 'time (s)'\n" : "", data, signals[i].column,
			signals[i].name);
	}
	fprintf(gp, "unset multiplot\n");
}

int ev3sim_world_plot(const char *png_path, unsigned bits, const char *title, char *err, size_t errlen)
{
	const struct ev3sim_world *w = ev3sim_world_current();
	char png[] = "/tmp/ev3sim-wplot-XXXXXX", mat[] = "/tmp/ev3sim-wmat-XXXXXX";
	char obst[] = "/tmp/ev3sim-wobst-XXXXXX", data[] = "/tmp/ev3sim-wdata-XXXXXX";
	FILE *fm = NULL, *fo = NULL, *fd = NULL, *fp = NULL, *gp;
	unsigned cols = 0, rows = 0;
	int status, ret = -1;
	bool ok;

	if (!ev3sim_have_gnuplot()) {
		snprintf(err, errlen, "gnuplot not found on PATH (install gnuplot-nox: make deps)");
		return -1;
	}
	if (bits == 0) {
		bits = EV3SIM_SIGNAL_HEADING;
		for (unsigned p = 0; p < 4; p++)
			if (ev3sim_world_now()->port_device[p] != EV3SIM_IN_NONE)
				bits |= EV3SIM_SIGNAL_IN1 << p;
	}
	fm = temp_file(mat);
	fo = fm ? temp_file(obst) : NULL;
	fd = fo ? temp_file(data) : NULL;
	fp = fd ? temp_file(png) : NULL;
	if (fp == NULL) {
		snprintf(err, errlen, "cannot create a temporary file: %s", strerror(errno));
		goto out;
	}
	fclose(fp);
	fp = NULL;
	ok = write_mat(fm, &w->mat, &cols, &rows) == 0;
	write_obstacles(fo, w);
	for (size_t i = 0; i < series.n; i++) {
		const struct row *r = &series.rows[i];

		fprintf(fd, "%.3f,%.5f,%.5f,%.3f,%g,%g,%g,%g,%.2f,%.2f,%.1f\n", r->t, r->x, r->y, r->heading,
			r->in[0], r->in[1], r->in[2], r->in[3], r->left, r->right, r->clearance_mm);
	}
	ok = close_ok(fm) & ok;
	ok = close_ok(fo) & ok;
	ok = close_ok(fd) & ok;
	fm = fo = fd = NULL;
	if (!ok) {
		snprintf(err, errlen, "cannot write the plot's temporary files in /tmp");
		goto out;
	}
	gp = popen("gnuplot", "w");
	if (gp == NULL) {
		snprintf(err, errlen, "cannot run gnuplot: %s", strerror(errno));
		goto out;
	}
	script(gp, png, title, mat, cols, rows, obst, data, bits);
	status = pclose(gp);
	if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		snprintf(err, errlen, "gnuplot failed drawing %s", png_path);
		goto out;
	}
	if (ev3sim_copy_file(png, png_path) != 0) {
		snprintf(err, errlen, "cannot write %s: %s", png_path, strerror(errno ? errno : EIO));
		goto out;
	}
	ret = 0;
out:
	if (fm)
		fclose(fm);
	if (fo)
		fclose(fo);
	if (fd)
		fclose(fd);
	unlink(mat);
	unlink(obst);
	unlink(data);
	unlink(png);
	return ret;
}
