/*
 * balance_run.h — one run of the balancing experiment: boots the simulated
 * brick with the EV3RT app examples/gyroboy (a 4 ms control step and a gyro
 * logger on the default serial port, which is the simulated polled UART of
 * serial_log.h), plugs in the robot (large motors on A and D, gyro on port
 * 2), holds it upright while the app calibrates, lets go at
 * EV3SIM_RELEASE_NS and runs for the requested virtual time or until the
 * robot falls; then presses BACK, which ends the app.  Host only.
 *
 * Times in options (pushes, faults) and in results count from the release.
 */
#ifndef EV3SIM_BALANCE_RUN_H
#define EV3SIM_BALANCE_RUN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "kernel.h"
#include "ev3sim/fault_spec.h"
#include "ev3sim/robot.h"

#define EV3SIM_RELEASE_NS     3000000000ULL   /* the hand lets go 3 s after boot */
#define EV3SIM_LOGGER_MAX_HZ  1000U

/* What the app does (its settings, set before boot). */
struct ev3sim_balance_cfg {
	bool balancer;              /* false: calibrate, never drive (negative control) */
	unsigned logger_hz;         /* 0..EV3SIM_LOGGER_MAX_HZ; 0: no logger */
	bool logger_above;          /* the logger's priority above the balancer's */
};

/* What the app counted, and d_uart's link counters of the gyro's port (lms_uart.h). */
struct ev3sim_balance_stats {
	bool calibrated;
	double gyro_offset_dps, tilt_est_deg;
	int power;
	uint32_t releases, runs, deadline_misses, overlaps, late_starts;
	uint64_t max_start_delay_ns;
	uint32_t api_errors, api_blocked, logger_lines, logger_skipped;
	uint32_t max_api_call_us;   /* the longest API call while balancing, any task */
	uint32_t gyro_frames;       /* valid DATA frames */
	uint32_t gyro_check_errors; /* losses of sync on a bad check byte */
	uint32_t gyro_size_errors;  /* losses of sync on a header of impossible length */
	uint32_t gyro_resyncs;      /* losses of frame sync, each ended by the next valid frame */
	uint32_t gyro_reconnects;   /* handshakes restarted after errors, unplug or silence */
};
#define EV3SIM_MAX_FAULTS     16U
#define EV3SIM_MAX_SECONDS    3600.0

struct ev3sim_balance_opts {
	double seconds;             /* virtual seconds after the release, > 0 */
	uint64_t seed;
	struct ev3sim_balance_cfg app;
	uint32_t log_baud;          /* 0: SERIAL_LOG_DEFAULT_BAUD */
	double start_tilt_deg;
	double gyro_noise_dps;      /* the gyro's sample noise (a gyro-noise fault overrides it) */
	struct ev3sim_push pushes[EV3SIM_MAX_PUSHES];   /* t_ns from the release */
	unsigned npushes;
	struct ev3sim_fault_spec faults[EV3SIM_MAX_FAULTS];
	unsigned nfaults;
	const char *trace_path;     /* VCD, NULL: none */
	FILE *log_out;              /* the serial log's far end, NULL: dropped */
	FILE *series_out;           /* the series as CSV, one row per physics step after the
	                             * release, streamed as the run goes (NULL: none) */
	bool progress;              /* progress bar on stderr (if it is a terminal) */
};

struct ev3sim_balance_result {
	bool fell;
	double fell_at_s;           /* from the release */
	double seconds;             /* the requested duration */
	double max_tilt_deg, rms_tilt_deg;
	double max_travel_cm;       /* farthest the axle got from where it was let go */
	struct ev3sim_balance_stats app;
	uint64_t log_bytes;
	uint64_t log_spin_ms;       /* CPU time the logger spent waiting for the port */
	unsigned bugs;              /* rtos_host bug reports */
	double wall_s;
	double sim_virtual_s;      /* virtual time simulated, boot to end */
	bool trace_failed;          /* the VCD trace could not be written completely */
};

/* Runs the experiment.  E_OK, or E_PAR for bad options (message in err),
 * E_SYS if the simulation could not boot (message in err). */
ER ev3sim_balance_run(const struct ev3sim_balance_opts *opts, struct ev3sim_balance_result *res,
		      char *err, size_t errlen);
/* The one-line key=value summary; sim_speed (the only field that depends
 * on the host) comes last. */
void ev3sim_balance_summary(const struct ev3sim_balance_opts *opts,
			    const struct ev3sim_balance_result *res, char *buf, size_t len);

/* The series' CSV columns (the header line series_out starts with). */
#define EV3SIM_SERIES_HEADER \
	"t_s,tilt_deg,tilt_rate_dps,wheel_deg,tilt_est_deg,power_pct,duty_a_pct,duty_d_pct\n"

#endif /* EV3SIM_BALANCE_RUN_H */
