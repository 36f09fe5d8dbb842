/*
 * bench.h — the full-brick speed run: four motors turning and four UART
 * sensors streaming (colour, gyro, ultrasonic, IR), with a register-level
 * host polling each sensor's UART every millisecond, ACKing the handshake
 * and sending the 100 ms keep-alive.  `make bench` and the quick test call
 * it.  Host only.
 */
#ifndef HOST_SIM_DEVICES_EV3_BENCH_H
#define HOST_SIM_DEVICES_EV3_BENCH_H

#include <stdint.h>
#include "kernel.h"

struct ev3_bench_result {
	double virtual_s;           /* simulated time */
	double wall_s;              /* host wall-clock time it took (boot to shutdown) */
	double cpu_s;               /* host CPU time of the process meanwhile (one core) */
	double speedup;             /* virtual_s / wall_s */
	double cpu_speedup;         /* virtual_s / cpu_s: what one unshared core achieves */
	uint64_t sensor_bytes;      /* bytes the host side received */
	uint64_t data_frames;       /* DATA frames the sensors sent */
	int64_t tacho_counts[4];    /* final tacho positions of motors A-D */
};

/* Boots the board, runs the full brick for virtual_s seconds of virtual
 * time with the given seed, shuts down.  Returns E_OK, E_PAR for a bad
 * duration, or the boot error. */
ER ev3_bench_full_brick(double virtual_s, uint64_t seed, struct ev3_bench_result *r);

#endif /* HOST_SIM_DEVICES_EV3_BENCH_H */
