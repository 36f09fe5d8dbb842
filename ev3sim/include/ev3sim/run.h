/*
 * run.h — `ev3sim run`: an EV3RT-style application (its configuration from
 * app.cfg) on the simulated brick, inside a robot and its world.  Host only.
 *
 *   bare     nothing plugged in but what --in/--out name
 *   gyroboy  LEGO's gyro boy: large motors on A (left) and D (right), gyro on
 *            port 2; held upright until the release, then balanced by the
 *            application or falls (robot.h)
 *   tribot   a driving base: large motors on B (left) and C (right), touch on
 *            port 1, colour on port 3 looking down at a line-following mat,
 *            ultrasonic on port 4 (tribot.h: the built-in world "line")
 *   a world  a driving robot in a world of its own (world.h): a built-in one
 *            or a world file (--world); its build gives the ports' devices
 *
 * The application's syslog lines go to the console (NOTICE and worse) and
 * to an optional sink; the run ends after the requested virtual time.
 */
#ifndef EV3SIM_RUN_H
#define EV3SIM_RUN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "kernel.h"
#include "rtos_cfg.h"
#include "ev3sim/apps.h"
#include "ev3sim/fault_spec.h"
#include "ev3sim/robot.h"
#include "ev3sim/tribot.h"
#include "ev3sim/world.h"

#define EV3SIM_RUN_MAX_FAULTS   16U
#define EV3SIM_RUN_MAX_ACTIONS  16U

enum ev3sim_robot_kind { EV3SIM_ROBOT_BARE, EV3SIM_ROBOT_GYROBOY, EV3SIM_ROBOT_TRIBOT };

/* Something the user does with the brick: presses the touch sensor (on the
 * first port with one) or a button, at t_ns for hold_ns. */
struct ev3sim_action {
	bool touch;                 /* else a button */
	unsigned button;            /* button_t: LEFT_BUTTON..BACK_BUTTON */
	uint64_t t_ns, hold_ns;
};

struct ev3sim_run_opts {
	const char *app_name;
	enum ev3sim_robot_kind robot;
	/* devices per port: the robot's by default (ev3sim_run_defaults) */
	enum ev3sim_input_device in[4];
	enum ev3sim_output_device out[4];
	double seconds;             /* virtual seconds from boot, > 0 */
	uint64_t seed;
	struct ev3sim_fault_spec faults[EV3SIM_RUN_MAX_FAULTS];   /* at_ns from boot */
	unsigned nfaults;
	struct ev3sim_action actions[EV3SIM_RUN_MAX_ACTIONS];
	unsigned nactions;
	uint64_t release_ns;        /* gyroboy: the hand lets go, not before */
	bool release_on_drive;      /* gyroboy: nor before the app drives a wheel (its balancer starts) */
	double start_tilt_deg;      /* gyroboy: tilt when let go */
	double gyro_noise_dps;      /* the gyro's sample noise (a gyro-noise fault overrides it) */
	struct ev3sim_push pushes[EV3SIM_MAX_PUSHES];              /* gyroboy, t_ns from boot */
	unsigned npushes;
	struct ev3sim_placement placements[EV3SIM_MAX_PLACEMENTS]; /* tribot, t_ns from boot */
	unsigned nplacements;
	const char *trace_path;     /* VCD, NULL: none */
	const char *audio_path;     /* WAV of what the speaker played, NULL: none */
	const char *lcd_path;       /* PNG of the display's last frame, NULL: none */
	const char *lcd_video_path; /* animated GIF of the display over time, NULL: none */
	const char *sd_dir;         /* the SD card's directory, NULL: no card (brick_io.h) */
	const char *serial_path;    /* the serial port's far end, NULL: not connected */
	const char *bt_path;        /* Bluetooth SPP's far end: a Unix socket there (brick_io.h), NULL: none */
	const char *bt_master_path; /* the SPP master's remote slave: a Unix socket there, NULL: none */
	const char *usb_path;       /* USB CDC's far end: a Unix socket there, NULL: none */
	const struct ev3sim_world *world;   /* the robot and its world (robot bare), NULL: none */
	FILE *csv;                  /* the robot's state every 10 ms, NULL: none */
	const char *plot_path;      /* a world's PNG: the path on the mat and signals, NULL: none */
	unsigned plot_signals;      /* which signals (EV3SIM_SIGNAL_* bits), 0: the default */
	bool live;                  /* the live view (live.h): served on 127.0.0.1:live_port (0: any free port) */
	unsigned live_port;
	double pace;                /* with live: times real time at most (default 1), 0: as fast as possible */
	bool quiet;                 /* the console shows warnings and worse only */
	/* every syslog line of the run ("WARNING: text"), NULL: none */
	void (*log_sink)(const char *line, void *ctx);
	void *log_ctx;
};

struct ev3sim_run_result {
	double seconds;             /* virtual time run */
	unsigned log_lines, warnings, errors;   /* syslog lines; WARNING; ERROR and worse */
	unsigned bugs;              /* rtos_host bug reports */
	/* gyroboy */
	bool fell;
	double fell_at_s, max_tilt_deg;
	/* tribot */
	double progress_m, travel_m, max_line_error_mm, rms_line_error_mm, on_line_pct;
	/* a world (travel_m too) */
	double x_m, y_m, heading_deg, min_clearance_mm;    /* min_clearance_mm < 0: no obstacles */
	unsigned contacts;
	bool goal_reached;
	double goal_at_s;
	double wall_s;
	bool stopped;               /* the live view's page stopped the run before its end */
	unsigned lcd_dark;          /* dark pixels of the display at the end (with lcd_path) */
	int end_status;             /* 0, or why the app ended the system: RTOS_HOST_EXIT_STALL, _STACK */
	char end_report[1024];      /* then: the kernel's report (task, PC and source line, or sizes) */
};

/* Writes what the display shows as a 178 x 128 8-bit grey PNG (0 dark, 255
 * light): E_OK or E_SYS.  The ev3sim program sets it (libpng is linked into
 * the program only); NULL: --lcd is not available. */
extern ER (*ev3sim_lcd_png_writer)(const char *path);

/* The --lcd-video recorder (lcd_gif.c, giflib: the program only); NULL: not available.
 * begin(path), then frame(now) at every step of the run, then end(now) writes the file. */
struct ev3sim_lcd_video {
	ER (*begin)(const char *path);
	void (*frame)(uint64_t now_ns);
	ER (*end)(uint64_t end_ns);
};
extern const struct ev3sim_lcd_video *ev3sim_lcd_video;

/* The robot's devices on the ports, no faults, actions or pushes; for the
 * tribot a touch press at 3 s; the gyro boy let go at 4 s with a 0.5 degree
 * tilt, its gyro's noise an EV3 gyro's at rest (UART_SENSOR_GYRO_NOISE_AT_REST_DPS). */
void ev3sim_run_defaults(struct ev3sim_run_opts *o, enum ev3sim_robot_kind robot);

/* A world's robot: its devices on the ports (a gyro's noise an EV3 gyro's
 * at rest), no faults or actions. */
void ev3sim_run_defaults_world(struct ev3sim_run_opts *o, const struct ev3sim_world *w);

/* Boots app (a configuration INCLUDEing ev3api_cfg), plugs in the robot,
 * runs.  E_OK, E_PAR (bad options, message in err), E_SYS (boot failure). */
ER ev3sim_run(const struct ev3sim_run_opts *o, const struct rtos_cfg *app,
	      struct ev3sim_run_result *r, char *err, size_t errlen);

/* The one-line key=value summary (sim_speed last). */
void ev3sim_run_summary(const struct ev3sim_run_opts *o, const struct ev3sim_run_result *r,
			char *buf, size_t len);

/* The robot names as the command line spells them, and back. */
const char *ev3sim_robot_name(enum ev3sim_robot_kind k);
bool ev3sim_robot_parse(const char *s, enum ev3sim_robot_kind *k);

/* The command line of an application runner (`ev3sim run` execs it with
 * the options after the app directory): parses, runs app, prints the
 * summary.  Returns the exit status. */
int ev3sim_run_main(int argc, char **argv, const char *app_name, const struct rtos_cfg *app);

/* `ev3sim run APP_DIR [options]` (argv[0] is APP_DIR): builds the app's
 * runner with make in the source tree ev3sim was built in and executes it
 * with the options.  Returns the exit status if it cannot. */
int ev3sim_run_command(int argc, char **argv);

#endif /* EV3SIM_RUN_H */
