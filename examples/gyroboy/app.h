/*
 * app.h — gyroboy: IDs, priorities and stack sizes (read by app.cfg and
 * app.c), and the app's settings and counters.
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"

/*
 * Priorities, all in the app's range (TMIN_APP_TPRI and below; the drivers'
 * work runs above it, as on EV3RT): the control step first, then the main
 * task, then the logger.  The EV3_CRE_CYC handlers, which only wake the
 * tasks, run at TMIN_APP_TPRI.  The logger-above-balancer experiment raises
 * the logger to LOGGER_ABOVE_PRIORITY.
 */
#define BALANCE_PRIORITY      (TMIN_APP_TPRI + 1)
#define MAIN_PRIORITY         (TMIN_APP_TPRI + 2)
#define LOGGER_PRIORITY       (TMIN_APP_TPRI + 4)
#define LOGGER_ABOVE_PRIORITY TMIN_APP_TPRI

#ifndef STACK_SIZE
#define STACK_SIZE        4096
#endif

/* The control period, ms; the logger's tick, ms. */
#define BALANCE_PERIOD_MS 4
#define LOGGER_TICK_MS    1
#define LOGGER_MAX_HZ     1000

/* A control step that starts later than this after its release misses its deadline. */
#define START_BOUND_US    1000U

#ifndef TOPPERS_MACRO_ONLY

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
	uint32_t api_errors;        /* API calls of the control step that failed */
	uint32_t api_blocked;       /* API calls of the control step that took over 200 us */
	uint32_t logger_lines;      /* lines written to the serial port */
	uint32_t logger_skipped;    /* logger periods lost because it was still busy */
};

extern struct gyroboy_params gyroboy_params;
extern struct gyroboy_stats gyroboy_stats;

extern void main_task(intptr_t exinf);
extern void balance_task(intptr_t exinf);
extern void logger_task(intptr_t exinf);
extern void balance_cyc(intptr_t exinf);
extern void logger_cyc(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif
