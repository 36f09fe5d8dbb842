/*
 * test_world_file.c — world files (ev3sim/world_file.c, docs/ev3sim.md's
 * "World files"): a whole file with a PNG mat, walls, the robot's build and
 * a goal reads into the world it describes (millimetres to metres, the
 * image's pixels from its top row, the border's walls); every bad file is
 * refused with the file's name and the line and column of a syntax error or
 * the key of a bad value, and its reason.  The reader links json-c and
 * libpng, which only the 64-bit host configurations have: elsewhere the test
 * skips.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "tap.h"
#include "ev3sim/world.h"

static char dir[] = "/tmp/ev3lx-worlds-XXXXXX";

/* Writes text to dir/name; the path in path. */
static void put(const char *name, const char *text, char *path, size_t len)
{
	FILE *f;

	snprintf(path, len, "%s/%s", dir, name);
	f = fopen(path, "w");
	if (f) {
		fputs(text, f);
		fclose(f);
	}
}

/* CRC-32 of a PNG chunk's type and data (ISO 3309, as the PNG specification gives it). */
static uint32_t crc32_of(const uint8_t *p, size_t n)
{
	uint32_t c = 0xFFFFFFFFu;

	while (n--) {
		c ^= *p++;
		for (int k = 0; k < 8; k++)
			c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
	}
	return c ^ 0xFFFFFFFFu;
}

/* Appends a big-endian 32-bit number. */
static void be32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)(v >> 24);
	p[1] = (uint8_t)(v >> 16);
	p[2] = (uint8_t)(v >> 8);
	p[3] = (uint8_t)v;
}

/* Writes one PNG chunk. */
static void chunk(FILE *f, const char *type, const uint8_t *data, uint32_t n)
{
	uint8_t *buf = malloc(n + 8);

	be32(buf, n);
	memcpy(buf + 4, type, 4);
	if (n > 0)
		memcpy(buf + 8, data, n);
	fwrite(buf, 1, n + 8, f);
	be32(buf, crc32_of(buf + 4, n + 4));
	fwrite(buf, 1, 4, f);
	free(buf);
}

/* A 4 x 2 RGB PNG, left half black, right half red, top row only; the bottom
 * row blue — written with one stored (uncompressed) deflate block. */
static void put_png(const char *name)
{
	static const uint8_t rows[2][1 + 12] = {
		{ 0, 0, 0, 0, 0, 0, 0, 255, 0, 0, 255, 0, 0 },
		{ 0, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0, 0, 255 },
	};
	uint8_t ihdr[13] = { 0 }, idat[2 + 5 + sizeof(rows) + 4];
	uint32_t a = 1, b = 0;
	char path[256];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "wb");
	if (f == NULL)
		return;
	fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
	be32(ihdr, 4);
	be32(ihdr + 4, 2);
	ihdr[8] = 8;            /* bits per channel */
	ihdr[9] = 2;            /* RGB */
	chunk(f, "IHDR", ihdr, sizeof(ihdr));
	idat[0] = 0x78;         /* zlib: deflate, 32 KiB window */
	idat[1] = 0x01;
	idat[2] = 1;            /* the last block, stored */
	idat[3] = sizeof(rows) & 0xFF;
	idat[4] = sizeof(rows) >> 8;
	idat[5] = (uint8_t)~idat[3];
	idat[6] = (uint8_t)~idat[4];
	memcpy(idat + 7, rows, sizeof(rows));
	for (size_t i = 0; i < sizeof(rows); i++) {
		a = (a + ((const uint8_t *)rows)[i]) % 65521;
		b = (b + a) % 65521;
	}
	be32(idat + 7 + sizeof(rows), b << 16 | a);
	chunk(f, "IDAT", idat, sizeof(idat));
	chunk(f, "IEND", NULL, 0);
	fclose(f);
}

static const char good[] =
	"{\n"
	"  \"name\": \"tiles\",\n"
	"  \"mat\": { \"image\": \"tiles.png\", \"width_mm\": 400, \"height_mm\": 200, \"origin_mm\": [-200, 0] },\n"
	"  \"border\": true,\n"
	"  \"walls\": [\n"
	"    { \"segment\": [0, 0, 0, 100] },\n"
	"    { \"box\": [100, 100, 150, 150], \"height_mm\": 50 },\n"
	"    { \"circle\": [-100, 150, 30] }\n"
	"  ],\n"
	"  \"robot\": {\n"
	"    \"wheel_radius_mm\": 21, \"track_mm\": 110, \"mass_kg\": 0.6, \"body_radius_mm\": 40, \"slip\": 0.1,\n"
	"    \"motors\": { \"left\": \"A\", \"right\": \"D\", \"type\": \"medium\" },\n"
	"    \"sensors\": [\n"
	"      { \"port\": 3, \"type\": \"color\", \"at_mm\": [50, 0], \"height_mm\": 10, \"footprint_mm\": 8 },\n"
	"      { \"port\": 4, \"type\": \"ultrasonic\", \"at_mm\": [40, 0], \"direction_deg\": 90, \"beam_deg\": 20 },\n"
	"      { \"port\": 2, \"type\": \"gyro\", \"inverted\": true },\n"
	"      { \"port\": 1, \"type\": \"ir\" }\n"
	"    ]\n"
	"  },\n"
	"  \"start\": { \"x_mm\": -100, \"y_mm\": 50, \"heading_deg\": 90 },\n"
	"  \"goal\": { \"x_mm\": 150, \"y_mm\": 40, \"radius_mm\": 30 }\n"
	"}\n";

/* A bad file and the message it must give after "<path>" (its start). */
static const struct bad {
	const char *what, *text, *message;
} bad[] = {
	{ "a syntax error names its line and column",
	  "{\n  \"mat\": { \"color\": [1, 2, 3] \n  \"robot\": {}\n}\n", ":3:3: " },
	{ "a file cut short", "{\n  \"mat\": {\n", ":3:1: unexpected end of file" },
	{ "text after the world", "{}\n}\n", ":2:1: text after the world's object" },
	{ "a misspelt key names its path",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 },"
	  " \"robot\": { \"whee_radius_mm\": 28 }, \"start\": { \"x_mm\": 500, \"y_mm\": 500 } }",
	  ": robot.whee_radius_mm: unknown key (a misspelling?)" },
	{ "a missing key", "{ \"robot\": {} }", ": mat: missing" },
	{ "a number out of its range",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 },"
	  " \"robot\": { \"track_mm\": 5 }, \"start\": { \"x_mm\": 500, \"y_mm\": 500 } }",
	  ": robot.track_mm: 5 is out of range (20..1000)" },
	{ "a string for a number",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": \"1 m\", \"height_mm\": 1000 } }",
	  ": mat.width_mm: must be a number" },
	{ "two kinds of mat",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"image\": \"x.png\", \"width_mm\": 1000, \"height_mm\": 1000 } }",
	  ": mat: needs exactly one of image, color or stadium" },
	{ "a missing image",
	  "{ \"mat\": { \"image\": \"missing.png\", \"width_mm\": 1000, \"height_mm\": 1000 } }",
	  ": mat.image: cannot read '" },
	{ "a text file as the image",
	  "{ \"mat\": { \"image\": \"bad.json\", \"width_mm\": 1000, \"height_mm\": 1000 } }",
	  ": mat.image: cannot read '" },
	{ "a wall with two shapes",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 },"
	  " \"walls\": [ { \"circle\": [1, 1, 1] }, { \"box\": [0, 0, 1, 1], \"segment\": [0, 0, 1, 1] } ] }",
	  ": walls[1]: needs exactly one of segment, box or circle" },
	{ "a circle of radius 0",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 },"
	  " \"walls\": [ { \"circle\": [1, 1, 0] } ] }",
	  ": walls[0].circle: the radius (element 3) must be > 0" },
	{ "an unknown sensor type",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 },"
	  " \"robot\": { \"sensors\": [ { \"port\": 1, \"type\": \"sonar\" } ] } }",
	  ": robot.sensors[0].type: 'sonar' is not a sensor type (touch, gyro, color, ultrasonic, ir)" },
	{ "two sensors on a port",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 },"
	  " \"robot\": { \"sensors\": [ { \"port\": 1, \"type\": \"touch\" }, { \"port\": 1, \"type\": \"gyro\" } ] } }",
	  ": robot.sensors[1]: port 1 has a sensor already" },
	{ "a motor port E",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 },"
	  " \"robot\": { \"motors\": { \"left\": \"E\" } } }",
	  ": robot.motors.left: 'E' is not an output port (A..D)" },
	{ "a start inside a wall",
	  "{ \"mat\": { \"color\": [255, 255, 255], \"width_mm\": 1000, \"height_mm\": 1000 }, \"border\": true,"
	  " \"robot\": {}, \"start\": { \"x_mm\": 50, \"y_mm\": 500 } }",
	  ": the robot starts inside an obstacle (its body radius reaches one)" },
	{ "an array at the top", "[1, 2]", ": (top): must be an object { ... }" },
};

int main(void)
{
	char path[256], err[1024], want[512];
	struct ev3sim_world *w;
	unsigned nbad = sizeof(bad) / sizeof(bad[0]);

	if (ev3sim_world_file_reader == NULL)
		return tap_skip_all("this configuration links no world file reader (json-c and libpng: the 64-bit hosts)");
	tap_plan(16 + (int)nbad + 2);
	if (mkdtemp(dir) == NULL)
		tap_bail_out("cannot make a temporary directory");
	put_png("tiles.png");
	put("tiles.json", good, path, sizeof(path));
	w = ev3sim_world_file_reader(path, err, sizeof(err));
	if (!ok(w != NULL, "a whole world file reads: %s", w ? "" : err)) {
		tap_skip(15, "no world");
	} else {
		const struct ev3sim_world_robot *r = &w->robot;
		uint8_t rgb[3];

		is_str(w->name, "tiles", "its name");
		ok(w->mat.kind == EV3SIM_MAT_IMAGE && w->mat.px_w == 4 && w->mat.px_h == 2,
		   "the mat is the 4 x 2 image");
		ok(w->mat.x0 == -0.2 && w->mat.width == 0.4 && w->mat.height == 0.2, "400 x 200 mm from (-200, 0)");
		ev3sim_world_mat_rgb(&w->mat, -0.15, 0.15, rgb);
		ok(rgb[0] == 0 && rgb[1] == 0 && rgb[2] == 0, "the top row's left is black");
		ev3sim_world_mat_rgb(&w->mat, 0.15, 0.15, rgb);
		ok(rgb[0] == 255 && rgb[1] == 0 && rgb[2] == 0, "the top row's right is red");
		ev3sim_world_mat_rgb(&w->mat, 0.15, 0.05, rgb);
		ok(rgb[0] == 0 && rgb[1] == 0 && rgb[2] == 255, "the bottom row is blue");
		is_int(w->nobstacles, 7, "the border's four walls and three more");
		ok(w->obstacles[4].kind == EV3SIM_OBST_SEGMENT && w->obstacles[5].kind == EV3SIM_OBST_BOX &&
		   w->obstacles[5].height == 0.05 && w->obstacles[6].kind == EV3SIM_OBST_CIRCLE &&
		   w->obstacles[6].r == 0.03 && w->obstacles[4].height == 0.2,
		   "a segment, a 50 mm box, a can of radius 30 mm; walls 200 mm high by default");
		ok(r->wheel_radius == 0.021 && r->track == 0.11 && r->mass == 0.6 && r->body_radius == 0.04 &&
		   r->slip == 0.1, "the robot's wheels, track, mass, body and slip");
		ok(r->left_port == 0 && r->right_port == 3 && r->motor == EV3SIM_OUT_MEDIUM, "medium motors on A and D");
		is_int(r->nmounts, 4, "four sensors");
		ok(r->mounts[0].port == 2 && r->mounts[0].device == EV3SIM_IN_COLOR && r->mounts[0].x == 0.05 &&
		   r->mounts[0].height == 0.01 && r->mounts[0].footprint == 0.008, "the colour sensor's mount");
		ok(r->mounts[1].device == EV3SIM_IN_ULTRASONIC && r->mounts[1].direction > 1.57 &&
		   r->mounts[1].direction < 1.58 && r->mounts[1].beam > 0.349 && r->mounts[1].beam < 0.35,
		   "the ultrasonic sensor looks left with a 20 degree beam");
		ok(r->mounts[2].device == EV3SIM_IN_GYRO && r->mounts[2].inverted && r->mounts[3].device == EV3SIM_IN_IR &&
		   r->mounts[3].beam > 0.69 && r->mounts[3].beam < 0.70, "an inverted gyro, an IR sensor with its 40 degree beam");
		ok(w->start_x == -0.1 && w->start_y == 0.05 && w->start_heading > 1.5707 && w->start_heading < 1.5708 &&
		   w->has_goal && w->goal_x == 0.15 && w->goal_r == 0.03, "the start pose and the goal");
		ev3sim_world_free(w);
	}
	put("bad.json", "not json", path, sizeof(path));
	for (unsigned i = 0; i < nbad; i++) {
		put("case.json", bad[i].text, path, sizeof(path));
		w = ev3sim_world_file_reader(path, err, sizeof(err));
		snprintf(want, sizeof(want), "%s%s", path, bad[i].message);
		ok(w == NULL && strncmp(err, want, strlen(want)) == 0, "%s: %s", bad[i].what, w ? "read!" : err);
		ev3sim_world_free(w);
	}
	snprintf(path, sizeof(path), "%s/none.json", dir);
	w = ev3sim_world_file_reader(path, err, sizeof(err));
	snprintf(want, sizeof(want), "%s: cannot open: No such file or directory", path);
	ok(w == NULL && strcmp(err, want) == 0, "a missing file: %s", err);
	w = ev3sim_world_file_reader(dir, err, sizeof(err));
	ok(w == NULL && strstr(err, dir) == err, "a directory: %s", err);
	ev3sim_world_free(w);
	snprintf(path, sizeof(path), "%s/tiles.png", dir);
	unlink(path);
	snprintf(path, sizeof(path), "%s/tiles.json", dir);
	unlink(path);
	snprintf(path, sizeof(path), "%s/bad.json", dir);
	unlink(path);
	snprintf(path, sizeof(path), "%s/case.json", dir);
	unlink(path);
	rmdir(dir);
	return tap_done();
}
