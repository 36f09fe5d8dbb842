/*
 * world.h — a driving robot in a world: the mat it drives on, the walls and
 * obstacles around it, its build (wheels, motors, sensor mounts) and its
 * start pose.  Host only.
 *
 * Each physics step (a host event every EV3SIM_WORLD_STEP_NS) turns the
 * wheels' shaft angle changes into motion over the mat (differential drive,
 * optionally with wheel slip), stops the robot at obstacles (a move that would
 * put its body or a touch sensor's tip into one is not made, and the wheels
 * then slip on the floor), and sets what each mounted sensor physically
 * measures in host_sim's device models: the colour sensor the mat under its
 * spot, the ultrasonic and infrared sensors the nearest obstacle in their
 * beam (ray casting), the touch sensor its contact, the gyro the robot's yaw
 * rate (its own noise, drift and integration are the model's).  Nothing here
 * reads or writes the API: the app sees the world only through the drivers.
 *
 * Coordinates are metres on the mat, x to the right, y up (the mat image's
 * top row is the far edge, y largest); headings are radians counter-clockwise
 * from +x.  A mount's position is in the robot's frame: x forward from the
 * axle's centre, y to the left.
 *
 * Worlds come from the built-ins (ev3sim_world_builtin) or a world file
 * (world_file.c, the program only: it needs json-c and libpng).
 */
#ifndef EV3SIM_WORLD_H
#define EV3SIM_WORLD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "kernel.h"
#include "ev3sim/apps.h"

#define EV3SIM_WORLD_STEP_NS       1000000ULL   /* physics step: 1 ms */
#define EV3SIM_WORLD_TRAIL_NS      10000000ULL  /* the trail keeps a pose every 10 ms */
#define EV3SIM_WORLD_MAX_MOUNTS    4U
#define EV3SIM_WORLD_MAX_OBSTACLES 256U
#define EV3SIM_WORLD_MAX_PLACEMENTS 16U

/*
 * EV3 ultrasonic sensor (45504): it measures 3 to 250 cm (LEGO's product
 * description) and reads 255 cm when nothing is in range (MathWorks, "LEGO
 * MINDSTORMS EV3 Support: Ultrasonic Sensor": "When the nearest object is
 * beyond the maximum range ... the sensor outputs the maximum value, 255";
 * ev3dev's lego-ev3-us: US-DIST-CM 0..2550 in mm).  Closer than its minimum
 * it reads the minimum.  LEGO publishes no beam width; the default cone
 * (EV3SIM_US_BEAM_DEG, full angle) is an estimate.
 */
#define EV3SIM_US_MIN_M            0.03
#define EV3SIM_US_NOTHING_M        2.55
#define EV3SIM_US_BEAM_DEG         30.0
/* EV3 infrared sensor (45509): proximity up to about 70 cm (LEGO's product
 * description), reported 0..100 (host_sim: mm / 7). */
#define EV3SIM_IR_RANGE_M          0.70
#define EV3SIM_IR_BEAM_DEG         40.0
/* Reflected light (COL-REFLECT, %) of a white and a black surface. */
#define EV3SIM_WHITE_PCT           64
#define EV3SIM_BLACK_PCT           5

enum ev3sim_mat_kind {
	EV3SIM_MAT_PLAIN,       /* one colour */
	EV3SIM_MAT_STADIUM,     /* white with a black line laid as a stadium (the tribot's mat) */
	EV3SIM_MAT_IMAGE,       /* an RGB image */
};

struct ev3sim_world_mat {
	enum ev3sim_mat_kind kind;
	double x0, y0, width, height;   /* the mat's lower-left corner and size, m */
	uint8_t rgb[3];                 /* plain: its colour */
	/* stadium: two straights of `straight` joined by half circles of `radius`,
	 * centred on (cx, cy), the line `line_width` wide */
	double cx, cy, straight, radius, line_width;
	/* image: px_w x px_h pixels, 3 bytes each, rows from the top (far) edge */
	unsigned px_w, px_h;
	const uint8_t *pixels;
};

enum ev3sim_obstacle_kind { EV3SIM_OBST_SEGMENT, EV3SIM_OBST_BOX, EV3SIM_OBST_CIRCLE };

struct ev3sim_obstacle {
	enum ev3sim_obstacle_kind kind;
	double x0, y0, x1, y1;          /* segment: its ends; box: two opposite corners (axis-aligned) */
	double r;                       /* circle: centre (x0, y0), radius r */
	double height;                  /* m: a sensor mounted higher sees over it */
};

struct ev3sim_world_mount {
	unsigned port;                  /* input port 0..3 */
	enum ev3sim_input_device device; /* touch, gyro, color, ultrasonic or ir */
	double x, y;                    /* robot frame, m */
	double direction;               /* ultrasonic, ir: facing, rad from forward, + to the left */
	double height;                  /* above the mat, m (colour: of its lens) */
	double footprint;               /* colour: diameter of the spot it sees at 8 mm, m */
	double beam;                    /* ultrasonic, ir: full cone angle, rad */
	bool pitch_axis;                /* gyro: measures pitch (a balancer's), not yaw */
	bool inverted;                  /* gyro: mounted upside down (counter-clockwise positive) */
};

struct ev3sim_world_robot {
	double wheel_radius, track, mass, body_radius;   /* m, m, kg, m */
	double rolling_crr;             /* rolling resistance, fraction of the weight */
	unsigned left_port, right_port; /* output ports 0..3 of the wheel motors */
	enum ev3sim_output_device motor;
	double slip;                    /* 0..0.5: mean fraction of the wheels' travel lost to slip */
	struct ev3sim_world_mount mounts[EV3SIM_WORLD_MAX_MOUNTS];
	unsigned nmounts;
};

struct ev3sim_world {
	char name[64];
	struct ev3sim_world_mat mat;
	struct ev3sim_obstacle obstacles[EV3SIM_WORLD_MAX_OBSTACLES];
	unsigned nobstacles;
	struct ev3sim_world_robot robot;
	double start_x, start_y, start_heading;      /* m, m, rad */
	bool has_goal;
	double goal_x, goal_y, goal_r;               /* reached when the axle's centre is within goal_r */
};

/* A pose on the trail. */
struct ev3sim_world_point {
	double t_s, x, y, heading_deg;
};

/* The world now, for observers (the run's statistics, plots, a live view). */
struct ev3sim_world_state {
	uint64_t t_ns;
	double x, y, heading_deg, pitch_deg;         /* axle centre, m; heading from +x */
	double travel_m;                             /* distance the axle travelled */
	enum ev3sim_input_device port_device[4];     /* the sensor the world drives on each port (or none) */
	double port_value[4];                        /* what each port's sensor measures: reflect %,
						      * distance mm, pressed 0/1, yaw or pitch deg (clockwise +) */
	double spot_x, spot_y;                       /* the first colour sensor's spot */
	double clearance_m;                          /* the body's distance to the nearest obstacle */
	double min_clearance_m;                      /* its least since the start */
	unsigned contacts;                           /* moves stopped by an obstacle */
	bool touching;                               /* the last move was stopped */
	bool goal_reached;
	double goal_at_s;
	const struct ev3sim_world_point *trail;      /* a pose every EV3SIM_WORLD_TRAIL_NS */
	size_t ntrail;
};

/* The hand lifts the robot and puts it down left_m to its left (negative:
 * right) at t_ns, same heading. */
struct ev3sim_world_placement {
	uint64_t t_ns;
	double left_m;
};

struct ev3sim_world_run {
	const struct ev3sim_world *world;            /* copied; an image's pixels must outlive the run */
	enum ev3sim_input_device in[4];              /* the devices plugged in: a mount is driven when its port has its device */
	const struct ev3sim_world_placement *placements;  /* any order, at most EV3SIM_WORLD_MAX_PLACEMENTS */
	unsigned nplacements;
	/* called after every step (NULL: none); placed: the hand moved the robot in it */
	void (*on_step)(const struct ev3sim_world_state *s, bool placed, void *ctx);
	void *ctx;
};

/* Checks a world's numbers: NULL if usable, else what is wrong. */
const char *ev3sim_world_check(const struct ev3sim_world *w);

/* Starts the physics on a booted board with the robot's motors and sensors
 * attached: E_OBJ if a wheel motor is missing, E_PAR for a bad world or
 * placements.  A mounted sensor whose port has another device (or none) is
 * not driven. */
ER ev3sim_world_start(const struct ev3sim_world_run *run);
/* Stops the physics events (before hs_sim_shutdown); the state stays readable. */
void ev3sim_world_stop(void);
/* Whether a world runs (or ran, until the next start). */
bool ev3sim_world_active(void);
/* The latest step's state (read-only; valid until the next start). */
const struct ev3sim_world_state *ev3sim_world_now(void);
/* The world that runs (or ran). */
const struct ev3sim_world *ev3sim_world_current(void);

/* The mat's colour at (x, y) (white off the mat). */
void ev3sim_world_mat_rgb(const struct ev3sim_world_mat *m, double x, double y, uint8_t rgb[3]);
/* Stadium mat: signed distance from (x, y) to the line's centre, + outside. */
double ev3sim_stadium_error(const struct ev3sim_world_mat *m, double x, double y);
/* Distance from (x, y) to an obstacle's outline (0 inside a box or circle). */
double ev3sim_obstacle_distance(const struct ev3sim_obstacle *o, double x, double y);
/* Distance along the ray from (x, y) in direction a to the obstacle, or a
 * negative number when it misses. */
double ev3sim_obstacle_ray(const struct ev3sim_obstacle *o, double x, double y, double a);

/* The built-in worlds: "line" (the tribot's line mat), "arena" (an open
 * walled floor), "maze" (walls and obstacles); NULL for another name. */
const struct ev3sim_world *ev3sim_world_builtin(const char *name);
/* Their names, comma-separated, for messages. */
extern const char ev3sim_world_builtin_names[];

/* Reads a world file (world_file.c: the program only, NULL where it is not
 * linked in): a new world (free with ev3sim_world_free), or NULL with the
 * message "FILE:LINE:COL: reason" or "FILE: key: reason" in err. */
extern struct ev3sim_world *(*ev3sim_world_file_reader)(const char *path, char *err, size_t errlen);
/* Frees a world the reader made (its image too). */
void ev3sim_world_free(struct ev3sim_world *w);

#endif /* EV3SIM_WORLD_H */
