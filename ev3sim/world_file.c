/*
 * world_file.c — ev3sim run --world FILE: a world file (JSON, read with
 * json-c) and its mat image (PNG, read with libpng) into a world (world.h).
 * The program only, as lcd_png.c: the test configurations, ARM ones
 * included, link the library without it.  The format is docs/ev3sim.md's
 * "World files"; every error names the file and the line (a syntax error) or
 * the key (a bad value) and the reason.
 */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <png.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <json-c/json.h>
#include "ev3sim/world.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define MM 0.001
#define MAX_FILE_BYTES (4U << 20)
#define MAX_IMAGE_SIDE 8192U
#define COORD_LIMIT_MM 100000.0     /* 100 m: any floor */

struct reader {
	const char *path;
	char *err;
	size_t errlen;
};

/* Writes "FILE: KEY: reason" into the error; false. */
static bool fail(struct reader *rd, const char *key, const char *fmt, ...)
{
	char reason[512];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(reason, sizeof(reason), fmt, ap);
	va_end(ap);
	snprintf(rd->err, rd->errlen, "%s: %s: %s", rd->path, key, reason);
	return false;
}

/* Whether every key of obj is in allowed (NULL-terminated); else the error names the first other. */
static bool known_keys(struct reader *rd, json_object *obj, const char *where, const char *const *allowed)
{
	json_object_object_foreach(obj, key, val) {
		bool ok = false;

		(void)val;
		for (const char *const *a = allowed; *a && !ok; a++)
			ok = strcmp(key, *a) == 0;
		if (!ok) {
			char k[256];

			snprintf(k, sizeof(k), "%s%s%s", where, *where ? "." : "", key);
			return fail(rd, k, "unknown key (a misspelling?)");
		}
	}
	return true;
}

/* The object at key name of obj, which must be one (or absent when not required). */
static bool get_object(struct reader *rd, json_object *obj, const char *where, const char *name,
		       bool required, json_object **out)
{
	char k[256];

	snprintf(k, sizeof(k), "%s%s%s", where, *where ? "." : "", name);
	*out = NULL;
	if (!json_object_object_get_ex(obj, name, out) || *out == NULL)
		return required ? fail(rd, k, "missing") : true;
	if (!json_object_is_type(*out, json_type_object))
		return fail(rd, k, "must be an object { ... }");
	return true;
}

/* A number at key name (its default def when absent and not required), within lo..hi. */
static bool get_number(struct reader *rd, json_object *obj, const char *where, const char *name, bool required,
		       double def, double lo, double hi, double *out)
{
	json_object *v;
	char k[256];

	snprintf(k, sizeof(k), "%s%s%s", where, *where ? "." : "", name);
	if (!json_object_object_get_ex(obj, name, &v) || v == NULL) {
		if (required)
			return fail(rd, k, "missing");
		*out = def;
		return true;
	}
	if (!json_object_is_type(v, json_type_double) && !json_object_is_type(v, json_type_int))
		return fail(rd, k, "must be a number");
	*out = json_object_get_double(v);
	if (!(*out >= lo && *out <= hi))
		return fail(rd, k, "%g is out of range (%g..%g)", *out, lo, hi);
	return true;
}

/* A boolean at key name (def when absent). */
static bool get_bool(struct reader *rd, json_object *obj, const char *where, const char *name, bool def, bool *out)
{
	json_object *v;
	char k[256];

	snprintf(k, sizeof(k), "%s%s%s", where, *where ? "." : "", name);
	if (!json_object_object_get_ex(obj, name, &v) || v == NULL) {
		*out = def;
		return true;
	}
	if (!json_object_is_type(v, json_type_boolean))
		return fail(rd, k, "must be true or false");
	*out = json_object_get_boolean(v);
	return true;
}

/* A string at key name (def when absent; NULL def: required). */
static bool get_string(struct reader *rd, json_object *obj, const char *where, const char *name,
		       const char *def, const char **out)
{
	json_object *v;
	char k[256];

	snprintf(k, sizeof(k), "%s%s%s", where, *where ? "." : "", name);
	if (!json_object_object_get_ex(obj, name, &v) || v == NULL) {
		*out = def;
		return def != NULL || fail(rd, k, "missing");
	}
	if (!json_object_is_type(v, json_type_string))
		return fail(rd, k, "must be a string");
	*out = json_object_get_string(v);
	return true;
}

/* An array of n numbers at key k (named in errors as given), each within lim in magnitude. */
static bool get_numbers(struct reader *rd, json_object *v, const char *k, unsigned n, double lim, double *out)
{
	if (!json_object_is_type(v, json_type_array) || json_object_array_length(v) != n)
		return fail(rd, k, "must be an array of %u numbers", n);
	for (unsigned i = 0; i < n; i++) {
		json_object *e = json_object_array_get_idx(v, i);

		if (!json_object_is_type(e, json_type_double) && !json_object_is_type(e, json_type_int))
			return fail(rd, k, "element %u must be a number", i + 1);
		out[i] = json_object_get_double(e);
		if (!(fabs(out[i]) <= lim))
			return fail(rd, k, "element %u (%g) is out of range (|v| <= %g)", i + 1, out[i], lim);
	}
	return true;
}

/* Reads the PNG at path (relative to the world file's directory) as RGB pixels into the mat. */
static bool read_image(struct reader *rd, const char *name, struct ev3sim_world_mat *m)
{
	char full[PATH_MAX];
	const char *slash = strrchr(rd->path, '/');
	png_image img;
	uint8_t *px;

	if (name[0] == '/' || slash == NULL)
		snprintf(full, sizeof(full), "%s", name);
	else
		snprintf(full, sizeof(full), "%.*s/%s", (int)(slash - rd->path), rd->path, name);
	memset(&img, 0, sizeof(img));
	img.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&img, full))
		return fail(rd, "mat.image", "cannot read '%s': %s", full,
			    errno != 0 && strstr(img.message, "open") ? strerror(errno) : img.message);
	if (img.width == 0 || img.height == 0 || img.width > MAX_IMAGE_SIDE || img.height > MAX_IMAGE_SIDE) {
		png_image_free(&img);
		return fail(rd, "mat.image", "'%s' is %u x %u pixels (1..%u a side)", full, img.width, img.height,
			    MAX_IMAGE_SIDE);
	}
	img.format = PNG_FORMAT_RGB;
	px = malloc(PNG_IMAGE_SIZE(img));
	if (px == NULL) {
		png_image_free(&img);
		return fail(rd, "mat.image", "out of memory for '%s'", full);
	}
	/* a transparent pixel shows the white mat under it */
	png_color white = { 255, 255, 255 };

	if (!png_image_finish_read(&img, &white, px, 0, NULL)) {
		free(px);
		return fail(rd, "mat.image", "cannot decode '%s': %s", full, img.message);
	}
	m->px_w = img.width;
	m->px_h = img.height;
	m->pixels = px;
	return true;
}

/* "mat": its size and origin, and one of image, color or stadium. */
static bool read_mat(struct reader *rd, json_object *o, struct ev3sim_world_mat *m)
{
	static const char *const keys[] = { "image", "color", "stadium", "width_mm", "height_mm", "origin_mm", NULL };
	json_object *v, *st;
	double xy[2] = { 0, 0 }, rgb[3];
	int kinds = 0;
	const char *image;

	if (!known_keys(rd, o, "mat", keys) ||
	    !get_number(rd, o, "mat", "width_mm", true, 0, 1, COORD_LIMIT_MM, &m->width) ||
	    !get_number(rd, o, "mat", "height_mm", true, 0, 1, COORD_LIMIT_MM, &m->height))
		return false;
	m->width *= MM;
	m->height *= MM;
	if (json_object_object_get_ex(o, "origin_mm", &v) && !get_numbers(rd, v, "mat.origin_mm", 2, COORD_LIMIT_MM, xy))
		return false;
	m->x0 = xy[0] * MM;
	m->y0 = xy[1] * MM;
	kinds = json_object_object_get_ex(o, "image", NULL) + json_object_object_get_ex(o, "color", NULL) +
		json_object_object_get_ex(o, "stadium", NULL);
	if (kinds != 1)
		return fail(rd, "mat", "needs exactly one of image, color or stadium");
	m->kind = EV3SIM_MAT_PLAIN;
	memset(m->rgb, 255, 3);
	if (json_object_object_get_ex(o, "color", &v)) {
		if (!get_numbers(rd, v, "mat.color", 3, 255, rgb))
			return false;
		for (int c = 0; c < 3; c++) {
			if (rgb[c] < 0)
				return fail(rd, "mat.color", "components are 0..255");
			m->rgb[c] = (uint8_t)lround(rgb[c]);
		}
		return true;
	}
	if (json_object_object_get_ex(o, "image", NULL)) {
		m->kind = EV3SIM_MAT_IMAGE;
		return get_string(rd, o, "mat", "image", NULL, &image) && read_image(rd, image, m);
	}
	static const char *const skeys[] = { "straight_mm", "radius_mm", "line_mm", "center_mm", NULL };

	m->kind = EV3SIM_MAT_STADIUM;
	if (!get_object(rd, o, "mat", "stadium", true, &st) || !known_keys(rd, st, "mat.stadium", skeys) ||
	    !get_number(rd, st, "mat.stadium", "straight_mm", true, 0, 0, COORD_LIMIT_MM, &m->straight) ||
	    !get_number(rd, st, "mat.stadium", "radius_mm", true, 0, 1, COORD_LIMIT_MM, &m->radius) ||
	    !get_number(rd, st, "mat.stadium", "line_mm", false, 20, 1, 1000, &m->line_width))
		return false;
	xy[0] = xy[1] = 0;
	if (json_object_object_get_ex(st, "center_mm", &v) && !get_numbers(rd, v, "mat.stadium.center_mm", 2, COORD_LIMIT_MM, xy))
		return false;
	m->straight *= MM;
	m->radius *= MM;
	m->line_width *= MM;
	m->cx = xy[0] * MM;
	m->cy = xy[1] * MM;
	return true;
}

/* "walls": segments, boxes and circles. */
static bool read_walls(struct reader *rd, json_object *a, struct ev3sim_world *w)
{
	static const char *const keys[] = { "segment", "box", "circle", "height_mm", NULL };
	size_t n;

	if (!json_object_is_type(a, json_type_array))
		return fail(rd, "walls", "must be an array [ ... ]");
	n = json_object_array_length(a);
	if (w->nobstacles + n > EV3SIM_WORLD_MAX_OBSTACLES)
		return fail(rd, "walls", "%zu walls and obstacles (with the border's), at most %u", w->nobstacles + n,
			    EV3SIM_WORLD_MAX_OBSTACLES);
	for (size_t i = 0; i < n; i++) {
		json_object *o = json_object_array_get_idx(a, i), *v;
		struct ev3sim_obstacle *ob = &w->obstacles[w->nobstacles];
		char where[64], k[96];
		double c[4];

		snprintf(where, sizeof(where), "walls[%zu]", i);
		if (!json_object_is_type(o, json_type_object))
			return fail(rd, where, "must be an object { ... }");
		if (!known_keys(rd, o, where, keys) ||
		    !get_number(rd, o, where, "height_mm", false, 200, 1, 10000, &ob->height))
			return false;
		ob->height *= MM;
		if (json_object_object_get_ex(o, "segment", NULL) + json_object_object_get_ex(o, "box", NULL) +
		    json_object_object_get_ex(o, "circle", NULL) != 1)
			return fail(rd, where, "needs exactly one of segment, box or circle");
		if (json_object_object_get_ex(o, "circle", &v)) {
			snprintf(k, sizeof(k), "%s.circle", where);
			if (!get_numbers(rd, v, k, 3, COORD_LIMIT_MM, c))
				return false;
			if (!(c[2] > 0))
				return fail(rd, k, "the radius (element 3) must be > 0");
			ob->kind = EV3SIM_OBST_CIRCLE;
			ob->x0 = ob->x1 = c[0] * MM;
			ob->y0 = ob->y1 = c[1] * MM;
			ob->r = c[2] * MM;
		} else {
			bool box = json_object_object_get_ex(o, "box", &v);

			if (!box)
				json_object_object_get_ex(o, "segment", &v);
			snprintf(k, sizeof(k), "%s.%s", where, box ? "box" : "segment");
			if (!get_numbers(rd, v, k, 4, COORD_LIMIT_MM, c))
				return false;
			ob->kind = box ? EV3SIM_OBST_BOX : EV3SIM_OBST_SEGMENT;
			ob->x0 = c[0] * MM;
			ob->y0 = c[1] * MM;
			ob->x1 = c[2] * MM;
			ob->y1 = c[3] * MM;
		}
		w->nobstacles++;
	}
	return true;
}

/* An output port letter A..D. */
static bool get_out_port(struct reader *rd, json_object *o, const char *name, const char *def, unsigned *port)
{
	const char *s;
	char k[64];

	snprintf(k, sizeof(k), "robot.motors.%s", name);
	if (!get_string(rd, o, "robot.motors", name, def, &s))
		return false;
	if (strlen(s) != 1 || s[0] < 'A' || s[0] > 'D')
		return fail(rd, k, "'%s' is not an output port (A..D)", s);
	*port = (unsigned)(s[0] - 'A');
	return true;
}

/* One of "sensors": its port, type and mount. */
static bool read_sensor(struct reader *rd, json_object *o, const char *where, struct ev3sim_world_mount *mt)
{
	static const char *const keys[] = { "port", "type", "at_mm", "direction_deg", "height_mm", "footprint_mm",
					     "beam_deg", "axis", "inverted", NULL };
	static const struct { const char *name; enum ev3sim_input_device d; } types[] = {
		{ "touch", EV3SIM_IN_TOUCH }, { "gyro", EV3SIM_IN_GYRO }, { "color", EV3SIM_IN_COLOR },
		{ "ultrasonic", EV3SIM_IN_ULTRASONIC }, { "ir", EV3SIM_IN_IR },
	};
	const char *type, *axis;
	double port, at[2] = { 0, 0 }, deg;
	json_object *v;
	char k[96];
	bool found = false;

	if (!json_object_is_type(o, json_type_object))
		return fail(rd, where, "must be an object { ... }");
	if (!known_keys(rd, o, where, keys) || !get_number(rd, o, where, "port", true, 0, 1, 4, &port) ||
	    !get_string(rd, o, where, "type", NULL, &type))
		return false;
	snprintf(k, sizeof(k), "%s.port", where);
	if (port != floor(port))
		return fail(rd, k, "must be a whole number 1..4");
	mt->port = (unsigned)port - 1;
	for (unsigned i = 0; i < sizeof(types) / sizeof(types[0]); i++)
		if (strcmp(type, types[i].name) == 0) {
			mt->device = types[i].d;
			found = true;
		}
	snprintf(k, sizeof(k), "%s.type", where);
	if (!found)
		return fail(rd, k, "'%s' is not a sensor type (touch, gyro, color, ultrasonic, ir)", type);
	snprintf(k, sizeof(k), "%s.at_mm", where);
	if (json_object_object_get_ex(o, "at_mm", &v) && !get_numbers(rd, v, k, 2, 1000, at))
		return false;
	mt->x = at[0] * MM;
	mt->y = at[1] * MM;
	if (!get_number(rd, o, where, "direction_deg", false, 0, -360, 360, &deg))
		return false;
	mt->direction = deg * DEG;
	if (!get_number(rd, o, where, "height_mm", false, mt->device == EV3SIM_IN_COLOR ? 8 : 50, 0, 1000, &mt->height))
		return false;
	mt->height *= MM;
	if (!get_number(rd, o, where, "footprint_mm", false, 12, 1, 100, &mt->footprint))
		return false;
	mt->footprint *= MM;
	if (!get_number(rd, o, where, "beam_deg", false,
			mt->device == EV3SIM_IN_IR ? EV3SIM_IR_BEAM_DEG : EV3SIM_US_BEAM_DEG, 0, 180, &deg))
		return false;
	mt->beam = deg * DEG;
	if (!get_string(rd, o, where, "axis", "yaw", &axis) || !get_bool(rd, o, where, "inverted", false, &mt->inverted))
		return false;
	snprintf(k, sizeof(k), "%s.axis", where);
	if (strcmp(axis, "yaw") != 0 && strcmp(axis, "pitch") != 0)
		return fail(rd, k, "'%s': yaw or pitch", axis);
	mt->pitch_axis = strcmp(axis, "pitch") == 0;
	return true;
}

/* "robot": the build. */
static bool read_robot(struct reader *rd, json_object *o, struct ev3sim_world_robot *r)
{
	static const char *const keys[] = { "wheel_radius_mm", "track_mm", "mass_kg", "body_radius_mm",
					     "rolling_resistance", "slip", "motors", "sensors", NULL };
	static const char *const mkeys[] = { "left", "right", "type", NULL };
	json_object *motors, *sensors;
	const char *type;

	if (!known_keys(rd, o, "robot", keys) ||
	    !get_number(rd, o, "robot", "wheel_radius_mm", false, 28, 5, 200, &r->wheel_radius) ||
	    !get_number(rd, o, "robot", "track_mm", false, 120, 20, 1000, &r->track) ||
	    !get_number(rd, o, "robot", "mass_kg", false, 0.75, 0.1, 20, &r->mass) ||
	    !get_number(rd, o, "robot", "body_radius_mm", false, 90, 10, 1000, &r->body_radius) ||
	    !get_number(rd, o, "robot", "rolling_resistance", false, 0.03, 0, 0.5, &r->rolling_crr) ||
	    !get_number(rd, o, "robot", "slip", false, 0, 0, 0.5, &r->slip) ||
	    !get_object(rd, o, "robot", "motors", false, &motors))
		return false;
	r->wheel_radius *= MM;
	r->track *= MM;
	r->body_radius *= MM;
	r->left_port = 1;
	r->right_port = 2;
	r->motor = EV3SIM_OUT_LARGE;
	if (motors != NULL) {
		if (!known_keys(rd, motors, "robot.motors", mkeys) || !get_out_port(rd, motors, "left", "B", &r->left_port) ||
		    !get_out_port(rd, motors, "right", "C", &r->right_port) ||
		    !get_string(rd, motors, "robot.motors", "type", "large", &type))
			return false;
		if (strcmp(type, "large") != 0 && strcmp(type, "medium") != 0)
			return fail(rd, "robot.motors.type", "'%s': large or medium", type);
		r->motor = strcmp(type, "large") == 0 ? EV3SIM_OUT_LARGE : EV3SIM_OUT_MEDIUM;
		if (r->left_port == r->right_port)
			return fail(rd, "robot.motors", "left and right are both on %c", 'A' + r->left_port);
	}
	if (!json_object_object_get_ex(o, "sensors", &sensors) || sensors == NULL)
		return true;
	if (!json_object_is_type(sensors, json_type_array))
		return fail(rd, "robot.sensors", "must be an array [ ... ]");
	if (json_object_array_length(sensors) > EV3SIM_WORLD_MAX_MOUNTS)
		return fail(rd, "robot.sensors", "at most %u sensors (one per input port)", EV3SIM_WORLD_MAX_MOUNTS);
	for (size_t i = 0; i < json_object_array_length(sensors); i++) {
		char where[64];

		snprintf(where, sizeof(where), "robot.sensors[%zu]", i);
		if (!read_sensor(rd, json_object_array_get_idx(sensors, i), where, &r->mounts[r->nmounts]))
			return false;
		for (unsigned j = 0; j < r->nmounts; j++)
			if (r->mounts[j].port == r->mounts[r->nmounts].port)
				return fail(rd, where, "port %u has a sensor already", r->mounts[j].port + 1);
		r->nmounts++;
	}
	return true;
}

/* Line and column of byte offset off in text. */
static void line_col(const char *text, size_t off, unsigned *line, unsigned *col)
{
	*line = 1;
	*col = 1;
	for (size_t i = 0; i < off && text[i]; i++) {
		if (text[i] == '\n') {
			(*line)++;
			*col = 1;
		} else {
			(*col)++;
		}
	}
}

/* The whole file into a NUL-terminated buffer (free it), or NULL with the error set. */
static char *slurp(struct reader *rd, size_t *len)
{
	FILE *f = fopen(rd->path, "rb");
	char *buf;

	if (f == NULL) {
		snprintf(rd->err, rd->errlen, "%s: cannot open: %s", rd->path, strerror(errno));
		return NULL;
	}
	buf = malloc(MAX_FILE_BYTES + 1);
	if (buf == NULL) {
		fclose(f);
		snprintf(rd->err, rd->errlen, "%s: out of memory", rd->path);
		return NULL;
	}
	*len = fread(buf, 1, MAX_FILE_BYTES + 1, f);
	if (ferror(f) || *len > MAX_FILE_BYTES) {
		snprintf(rd->err, rd->errlen, "%s: %s", rd->path,
			 ferror(f) ? "cannot read it (a directory?)" : "larger than 4 MiB");
		fclose(f);
		free(buf);
		return NULL;
	}
	fclose(f);
	buf[*len] = '\0';
	if (strlen(buf) != *len) {
		snprintf(rd->err, rd->errlen, "%s: a NUL byte: not a text file", rd->path);
		free(buf);
		return NULL;
	}
	return buf;
}

/* The world in the top object. */
static bool read_world(struct reader *rd, json_object *top, struct ev3sim_world *w)
{
	static const char *const keys[] = { "name", "mat", "border", "walls", "robot", "start", "goal", NULL };
	static const char *const start_keys[] = { "x_mm", "y_mm", "heading_deg", NULL };
	static const char *const goal_keys[] = { "x_mm", "y_mm", "radius_mm", NULL };
	json_object *mat, *robot, *start, *goal, *walls;
	const char *name, *base = strrchr(rd->path, '/');
	bool border;
	const char *why;

	if (!json_object_is_type(top, json_type_object))
		return fail(rd, "(top)", "must be an object { ... }");
	if (!known_keys(rd, top, "", keys) || !get_string(rd, top, "", "name", base ? base + 1 : rd->path, &name) ||
	    !get_object(rd, top, "", "mat", true, &mat) || !read_mat(rd, mat, &w->mat) ||
	    !get_bool(rd, top, "", "border", false, &border))
		return false;
	snprintf(w->name, sizeof(w->name), "%s", name);
	if (border) {
		const struct ev3sim_world_mat *m = &w->mat;
		double xs[5] = { m->x0, m->x0 + m->width, m->x0 + m->width, m->x0, m->x0 };
		double ys[5] = { m->y0, m->y0, m->y0 + m->height, m->y0 + m->height, m->y0 };

		for (int i = 0; i < 4; i++)
			w->obstacles[w->nobstacles++] = (struct ev3sim_obstacle){
				.kind = EV3SIM_OBST_SEGMENT, .x0 = xs[i], .y0 = ys[i], .x1 = xs[i + 1], .y1 = ys[i + 1],
				.height = 0.2 };
	}
	if (json_object_object_get_ex(top, "walls", &walls) && walls != NULL && !read_walls(rd, walls, w))
		return false;
	if (!get_object(rd, top, "", "robot", true, &robot) || !read_robot(rd, robot, &w->robot) ||
	    !get_object(rd, top, "", "start", true, &start) || !known_keys(rd, start, "start", start_keys) ||
	    !get_number(rd, start, "start", "x_mm", true, 0, -COORD_LIMIT_MM, COORD_LIMIT_MM, &w->start_x) ||
	    !get_number(rd, start, "start", "y_mm", true, 0, -COORD_LIMIT_MM, COORD_LIMIT_MM, &w->start_y) ||
	    !get_number(rd, start, "start", "heading_deg", false, 0, -360, 360, &w->start_heading) ||
	    !get_object(rd, top, "", "goal", false, &goal))
		return false;
	w->start_x *= MM;
	w->start_y *= MM;
	w->start_heading *= DEG;
	if (goal != NULL) {
		if (!known_keys(rd, goal, "goal", goal_keys) ||
		    !get_number(rd, goal, "goal", "x_mm", true, 0, -COORD_LIMIT_MM, COORD_LIMIT_MM, &w->goal_x) ||
		    !get_number(rd, goal, "goal", "y_mm", true, 0, -COORD_LIMIT_MM, COORD_LIMIT_MM, &w->goal_y) ||
		    !get_number(rd, goal, "goal", "radius_mm", false, 150, 1, COORD_LIMIT_MM, &w->goal_r))
			return false;
		w->has_goal = true;
		w->goal_x *= MM;
		w->goal_y *= MM;
		w->goal_r *= MM;
	}
	why = ev3sim_world_check(w);
	if (why != NULL) {
		snprintf(rd->err, rd->errlen, "%s: %s", rd->path, why);
		return false;
	}
	return true;
}

/* The reader (world.h's ev3sim_world_file_reader). */
static struct ev3sim_world *read_world_file(const char *path, char *err, size_t errlen)
{
	struct reader rd = { path, err, errlen };
	struct json_tokener *tok;
	struct ev3sim_world *w;
	json_object *top;
	size_t len;
	char *text = slurp(&rd, &len);

	if (text == NULL)
		return NULL;
	tok = json_tokener_new();
	if (tok == NULL) {
		free(text);
		snprintf(err, errlen, "%s: out of memory", path);
		return NULL;
	}
	top = json_tokener_parse_ex(tok, text, (int)len);
	if (top == NULL || json_tokener_get_parse_end(tok) < len) {
		enum json_tokener_error e = json_tokener_get_error(tok);
		size_t end = json_tokener_get_parse_end(tok);
		unsigned line, col;

		/* trailing text after the value: only white space is allowed */
		while (top != NULL && end < len && strchr(" \t\r\n", text[end]))
			end++;
		if (top == NULL || end < len) {
			line_col(text, end, &line, &col);
			snprintf(err, errlen, "%s:%u:%u: %s", path, line, col,
				 top == NULL ? (e == json_tokener_continue ? "unexpected end of file" :
						json_tokener_error_desc(e)) : "text after the world's object");
			json_object_put(top);
			json_tokener_free(tok);
			free(text);
			return NULL;
		}
	}
	json_tokener_free(tok);
	free(text);
	w = calloc(1, sizeof(*w));
	if (w == NULL) {
		json_object_put(top);
		snprintf(err, errlen, "%s: out of memory", path);
		return NULL;
	}
	if (!read_world(&rd, top, w)) {
		json_object_put(top);
		ev3sim_world_free(w);
		return NULL;
	}
	json_object_put(top);
	return w;
}

/* Installs the reader before the command line runs (a constructor: main.c stays the CLI's). */
__attribute__((constructor)) static void world_file_install(void)
{
	ev3sim_world_file_reader = read_world_file;
}
