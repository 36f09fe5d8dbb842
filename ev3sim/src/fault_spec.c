/*
 * fault_spec.c — parsing --fault values (fault_spec.h).
 */
#include <stdio.h>
#include <string.h>
#include "ev3sim/fault_spec.h"
#include "ev3sim/parse.h"

#define MAX_FIELDS 5

enum port_kind { NO_PORT, OUTPUT_PORT, ANY_PORT };

static const struct fault_kind {
	const char *name;
	enum ev3sim_fault_target target;
	enum ev3_fault_kind kind;
	enum port_kind port;
	bool has_value;
	bool timed;
	const char *usage;
} kinds[] = {
	{ "gyro-noise", EV3SIM_FAULT_GYRO_NOISE, 0, NO_PORT, true, false, "gyro-noise:SIGMA" },
	{ "gyro-drift", EV3SIM_FAULT_GYRO_DRIFT, 0, NO_PORT, true, false, "gyro-drift:DPS" },
	{ "uart-bit-errors", EV3SIM_FAULT_BRICK, EV3_FAULT_UART_BIT_ERRORS, NO_PORT, true, true,
	  "uart-bit-errors:P[:T[:D]]" },
	{ "uart-drop", EV3SIM_FAULT_BRICK, EV3_FAULT_UART_DROP, NO_PORT, true, true, "uart-drop:P[:T[:D]]" },
	{ "uart-dup", EV3SIM_FAULT_BRICK, EV3_FAULT_UART_DUPLICATE, NO_PORT, true, true, "uart-dup:P[:T[:D]]" },
	{ "adc-noise", EV3SIM_FAULT_BRICK, EV3_FAULT_ADC_NOISE, NO_PORT, true, true, "adc-noise:MV[:T[:D]]" },
	{ "encoder-noise", EV3SIM_FAULT_BRICK, EV3_FAULT_ENCODER_NOISE, OUTPUT_PORT, true, true,
	  "encoder-noise:PORT:RATE[:T[:D]]" },
	{ "encoder-stuck", EV3SIM_FAULT_BRICK, EV3_FAULT_ENCODER_STUCK, OUTPUT_PORT, false, true,
	  "encoder-stuck:PORT[:T[:D]]" },
	{ "motor-stall", EV3SIM_FAULT_BRICK, EV3_FAULT_MOTOR_STALL, OUTPUT_PORT, false, true,
	  "motor-stall:PORT[:T[:D]]" },
	{ "unplug", EV3SIM_FAULT_BRICK, EV3_FAULT_UNPLUG, ANY_PORT, false, true, "unplug:PORT[:T[:D]]" },
};

/* The limits of a fault's value. */
static bool value_ok(const struct fault_kind *k, double v)
{
	switch (k->target) {
	case EV3SIM_FAULT_GYRO_NOISE:
		return v >= 0 && v <= 1000;
	case EV3SIM_FAULT_GYRO_DRIFT:
		return v >= -1000 && v <= 1000;
	default:
		break;
	}
	switch (k->kind) {
	case EV3_FAULT_UART_BIT_ERRORS:
	case EV3_FAULT_UART_DROP:
	case EV3_FAULT_UART_DUPLICATE:
		return v >= 0 && v <= 1;
	case EV3_FAULT_ENCODER_NOISE:
		return v >= 0 && v <= 1e6;
	case EV3_FAULT_ADC_NOISE:
		return v >= 0 && v <= 5000;
	default:
		return true;
	}
}

bool ev3sim_fault_parse(const char *spec, unsigned gyro_port, struct ev3sim_fault_spec *out,
			char *err, size_t errlen)
{
	char buf[128], *field[MAX_FIELDS + 1];
	unsigned n = 0, next = 1;
	const struct fault_kind *k = NULL;

	if (spec == NULL || strlen(spec) >= sizeof(buf)) {
		snprintf(err, errlen, "fault spec too long");
		return false;
	}
	strcpy(buf, spec);
	field[n++] = buf;
	for (char *p = buf; *p; p++) {
		if (*p != ':')
			continue;
		if (n > MAX_FIELDS) {
			snprintf(err, errlen, "'%s': too many fields", spec);
			return false;
		}
		*p = '\0';
		field[n++] = p + 1;
	}
	for (size_t i = 0; i < sizeof(kinds) / sizeof(kinds[0]); i++)
		if (strcmp(field[0], kinds[i].name) == 0)
			k = &kinds[i];
	if (k == NULL) {
		snprintf(err, errlen, "'%s': unknown fault kind '%s' (see --help)", spec, field[0]);
		return false;
	}
	memset(out, 0, sizeof(*out));
	out->target = k->target;
	out->fault.kind = k->kind;
	out->fault.port = gyro_port;
	if (k->port != NO_PORT) {
		unsigned port;

		if (n <= next) {
			snprintf(err, errlen, "'%s': missing port (%s)", spec, k->usage);
			return false;
		}
		if (ev3sim_parse_output_port(field[next], &port)) {
			out->fault.port = port;
			if (k->kind == EV3_FAULT_UNPLUG)
				out->fault.kind = EV3_FAULT_MOTOR_UNPLUG;
		} else if (k->port == ANY_PORT && ev3sim_parse_input_port(field[next], &port)) {
			out->fault.port = port;
		} else {
			snprintf(err, errlen, "'%s': bad port '%s' (%s)", spec, field[next], k->usage);
			return false;
		}
		next++;
	}
	if (k->has_value) {
		if (n <= next || !ev3sim_parse_double(field[next], &out->value) || !value_ok(k, out->value)) {
			snprintf(err, errlen, "'%s': missing or bad value (%s)", spec, k->usage);
			return false;
		}
		out->fault.value = out->value;
		next++;
	}
	if (k->timed && n > next) {
		if (!ev3sim_parse_time(field[next], &out->at_ns)) {
			snprintf(err, errlen, "'%s': bad start time '%s'", spec, field[next]);
			return false;
		}
		next++;
		if (n > next) {
			if (!ev3sim_parse_time(field[next], &out->fault.duration_ns)) {
				snprintf(err, errlen, "'%s': bad duration '%s'", spec, field[next]);
				return false;
			}
			next++;
		}
	}
	if (n > next) {
		snprintf(err, errlen, "'%s': too many fields (%s)", spec, k->usage);
		return false;
	}
	return true;
}

ER ev3sim_fault_check_wheels(const struct ev3sim_fault_spec *faults, unsigned n, unsigned left,
			     unsigned right, char *err, size_t errlen)
{
	for (unsigned i = 0; i < n; i++) {
		const struct ev3_fault *f = &faults[i].fault;

		if (faults[i].target == EV3SIM_FAULT_BRICK && f->kind == EV3_FAULT_MOTOR_UNPLUG &&
		    (f->port == left || f->port == right)) {
			snprintf(err, errlen, "--fault unplug:%c would take a wheel off the robot (its motor "
				 "is the wheel's shaft); stall it or stick its encoder instead", 'A' + (int)f->port);
			return E_PAR;
		}
	}
	return E_OK;
}
