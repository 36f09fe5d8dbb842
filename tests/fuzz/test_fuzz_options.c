/*
 * test_fuzz_options.c — fuzz harness: ev3sim's option value parsers, as the
 * command line feeds them (numbers, times, ports, robots, fault specs, built-in
 * worlds, plot signals).  The
 * input is split at NUL bytes into strings; each goes through every parser.
 * A parser accepts a value only if it is in range, and never reads past the
 * string.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ev3sim/fault_spec.h"
#include "ev3sim/parse.h"
#include "ev3sim/run.h"
#include "ev3sim/world_plot.h"

#define FUZZ_NAME "options"

static void parse_all(const char *s)
{
	struct ev3sim_fault_spec spec;
	enum ev3sim_robot_kind robot;
	char err[256];
	double d;
	uint64_t u, ns;
	unsigned port, bits;
	const struct ev3sim_world *w;

	if (ev3sim_parse_double(s, &d) && !isfinite(d))
		abort();
	if (ev3sim_parse_uint(s, 1000, &u) && u > 1000)
		abort();
	if (ev3sim_parse_time(s, &ns) && ns > 86400ULL * 1000000000ULL)
		abort();
	if (ev3sim_parse_output_port(s, &port) && port > 3)
		abort();
	if (ev3sim_parse_input_port(s, &port) && port > 3)
		abort();
	(void)ev3sim_robot_parse(s, &robot);
	if ((w = ev3sim_world_builtin(s)) != NULL && strcmp(w->name, s) != 0)
		abort();
	if (ev3sim_plot_signals_parse(s, &bits, err, sizeof(err)) ? bits == 0 || bits > 0xFF :
	    memchr(err, '\0', sizeof(err)) == NULL)
		abort();
	if (!ev3sim_fault_parse(s, 1, &spec, err, sizeof(err)) && memchr(err, '\0', sizeof(err)) == NULL)
		abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *copy = malloc(size + 1);
	size_t start = 0;

	if (copy == NULL)
		return 0;
	memcpy(copy, data, size);
	copy[size] = '\0';
	for (size_t i = 0; i <= size; i++) {
		if (copy[i] == '\0') {
			parse_all(copy + start);
			start = i + 1;
		}
	}
	free(copy);
	return 0;
}

#include "fuzz_replay.h"
