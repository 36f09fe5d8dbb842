/*
 * balance_app.h — the self-balancing robot's application, written against
 * the EV3 API like any program for the brick:
 *
 *   main task     configures motors A, D and the gyro on port 2, waits for
 *                 the gyro, estimates its offset while the robot is held,
 *                 then starts the two cyclic handlers and exits;
 *   balance task  (high priority) one control step per activation: gyro
 *                 rate and wheel counts through the API, offset tracking,
 *                 state feedback, ev3lx_motor_set_power on both motors;
 *                 activated by a cyclic handler every EV3SIM_BALANCE_PERIOD_MS,
 *                 which also counts deadline misses;
 *   logger task   (low priority) woken at logger_hz by a 1 ms cyclic
 *                 handler: reads the gyro and writes one text line to the
 *                 serial log channel (serial_log.h).
 *
 * docs/ev3sim.md explains the controller and its gains.  Host only (the
 * application charges its own computation as virtual CPU time).
 */
#ifndef EV3SIM_BALANCE_APP_H
#define EV3SIM_BALANCE_APP_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"
#include "rtos_cfg.h"

#define EV3SIM_BALANCE_PERIOD_MS  4U
/* A balance activation that starts later than this after its release is a
 * deadline miss, as is a release while the previous activation is unfinished. */
#define EV3SIM_START_BOUND_NS     1000000ULL
#define EV3SIM_LOGGER_MAX_HZ      1000U

/* Task priorities (1 is the highest; linux_compat's worker runs at 4). */
#define EV3SIM_BALANCE_PRIORITY   2
#define EV3SIM_MAIN_PRIORITY      8
#define EV3SIM_LOGGER_PRIORITY    10
#define EV3SIM_LOGGER_ABOVE_PRIORITY 1    /* the ablation: logger above the balancer */

/* What the application does (set before boot). */
struct ev3sim_balance_cfg {
	bool balancer;              /* false: configure and calibrate, never drive (negative control) */
	unsigned logger_hz;         /* 0..EV3SIM_LOGGER_MAX_HZ; 0: no logger */
	bool logger_above;          /* the logger's priority above the balancer's */
};

/* What the application observed (read by the harness). */
struct ev3sim_balance_stats {
	bool calibrated;            /* the gyro offset is known and the loop runs */
	uint64_t calibrated_ns;
	double gyro_offset_dps;     /* the current offset estimate */
	double tilt_est_deg;        /* the controller's body angle */
	int power;                  /* the last power set on both motors */
	uint32_t releases;          /* cyclic releases of the balance task */
	uint32_t runs;              /* finished balance activations */
	uint32_t deadline_misses;   /* overlapping releases + late starts */
	uint32_t overlaps;          /* released while the previous activation was unfinished */
	uint32_t late_starts;       /* started later than EV3SIM_START_BOUND_NS after release */
	uint64_t max_start_delay_ns;
	uint32_t api_errors;        /* API calls of the balance task that did not return E_OK */
	uint32_t api_blocked;       /* API calls of the balance task that waited (> 200 us) */
	uint32_t logger_lines;      /* lines written to the serial log */
	uint32_t logger_skipped;    /* logger periods lost because the logger was still busy */
	/* d_uart's link counters of the gyro's port (lms_uart.h), at the end of the run */
	uint32_t gyro_frames;       /* valid DATA frames */
	uint32_t gyro_check_errors; /* losses of sync on a bad check byte */
	uint32_t gyro_size_errors;  /* losses of sync on a header of impossible length */
	uint32_t gyro_resyncs;      /* losses of frame sync, each ended by the next valid frame */
	uint32_t gyro_reconnects;   /* handshakes restarted after errors, unplug or silence */
};

/* The application's configuration (INCLUDEs ev3api_cfg and serial_log_cfg). */
extern const struct rtos_cfg ev3sim_balance_app_cfg;

/* Sets what the application does at the next boot; E_PAR for a bad logger rate. */
ER ev3sim_balance_setup(const struct ev3sim_balance_cfg *cfg);
/* Ends the application's activity: its cyclic handlers release nothing
 * more, so its tasks go idle once their current work is done (the harness
 * then runs the system a few ms and shuts down; the drivers unload in
 * ATT_TER before the application's own termination, so nothing may still
 * be reading their shared memory). */
void ev3sim_balance_stop(void);
/* The application's counters (reset at boot). */
const struct ev3sim_balance_stats *ev3sim_balance_stats(void);

#endif /* EV3SIM_BALANCE_APP_H */
