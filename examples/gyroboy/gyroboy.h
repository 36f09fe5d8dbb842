/*
 * gyroboy.h — gyroboy's settings and counters, shared by the app and the
 * programs that launch it and read what it observed (ev3sim's balance run).
 */
#ifndef GYROBOY_H
#define GYROBOY_H

#ifdef __cplusplus
extern "C" {
#endif

#include "t_stddef.h"

/* The control period, ms; the logger's tick, ms. */
#define BALANCE_PERIOD_MS 4
#define LOGGER_TICK_MS    1
#define LOGGER_MAX_HZ     1000

/* A control step that starts later than this after its release misses its deadline. */
#define START_BOUND_US    1000U

/* An API call longer than this waited somewhere: it is counted as blocked. */
#define GYROBOY_BLOCKED_US 200U

#ifndef TOPPERS_MACRO_ONLY

/* The app's tasks, as its call timing counts them. */
enum { GYROBOY_IN_MAIN, GYROBOY_IN_BALANCE, GYROBOY_IN_LOGGER, GYROBOY_TASKS };

/* What the app does: its defaults, which a launcher may set before it starts. */
struct gyroboy_params {
	bool_t balancer;            /* false: calibrate, never drive (the negative control) */
	uint32_t logger_hz;         /* gyro lines to the default serial port per second, 0..LOGGER_MAX_HZ */
	bool_t logger_above;        /* the logger runs above the balancer */
};

/* What the app observed (zeroed when it starts). */
struct gyroboy_stats {
	bool_t calibrated;
	float gyro_offset_dps;
	float tilt_est_deg;         /* the controller's body angle */
	int power;                  /* the last power set on both motors */
	uint32_t releases;          /* releases of the control step */
	uint32_t runs;              /* finished control steps */
	uint32_t deadline_misses;   /* overlapping releases + late starts */
	uint32_t overlaps;          /* released while the previous step was unfinished */
	uint32_t late_starts;       /* started more than START_BOUND_US after the release */
	uint32_t max_start_delay_us;
	uint32_t api_errors;        /* API calls while balancing that failed (motor commands: the
	                             * EV3RT reads return 0 on an error, which the app cannot tell) */
	uint32_t api_blocked;       /* API calls while balancing, in any task, that took over 200 us */
	uint32_t max_api_call_us;   /* the longest of those calls */
	uint64_t call_since_us[GYROBOY_TASKS];  /* start of the call each task is in (get_utm), 0: none */
	uint32_t logger_lines;      /* lines written to the serial port */
	uint32_t logger_skipped;    /* logger periods lost because it was still busy */
};

extern struct gyroboy_params gyroboy_params;
extern struct gyroboy_stats gyroboy_stats;

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif

#endif /* GYROBOY_H */
