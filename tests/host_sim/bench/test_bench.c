/*
 * test_bench.c — the full brick (4 motors, 4 UART sensors streaming) in
 * quick form: it runs, everything streams, and the virtual-to-wall speed is
 * printed (the 500x goal is checked by `make bench` on 60 s; here only a
 * loose floor, since sanitizers and qemu are slow).
 */
#include "tap.h"
#include "host_sim/bench.h"

int main(void)
{
	struct ev3_bench_result r;

	tap_plan(5);
	is_int(ev3_bench_full_brick(0, 1, &r), E_PAR, "zero duration refused");
	is_int(ev3_bench_full_brick(10.0, 1, &r), E_OK, "10 virtual seconds of the full brick");
	tap_diag("full brick: %.1f virtual s in %.3f wall s / %.3f CPU s = %.0fx / %.0fx real time; "
		 "%llu sensor bytes, %llu DATA frames", r.virtual_s, r.wall_s, r.cpu_s, r.speedup,
		 r.cpu_speedup, (unsigned long long)r.sensor_bytes,
		 (unsigned long long)r.data_frames);
	ok(r.data_frames > 3000, "the sensors streamed (%llu DATA frames)", (unsigned long long)r.data_frames);
	ok(r.tacho_counts[0] > 5000 && r.tacho_counts[1] < -3000 && r.tacho_counts[2] > 3000 &&
	   r.tacho_counts[3] < -5000, "the motors turned both ways (%lld %lld %lld %lld)",
	   (long long)r.tacho_counts[0], (long long)r.tacho_counts[1], (long long)r.tacho_counts[2],
	   (long long)r.tacho_counts[3]);
	ok(r.cpu_speedup > 2, "faster than real time even under sanitizers or qemu (%.0fx per CPU second)", r.cpu_speedup);
	return tap_done();
}
