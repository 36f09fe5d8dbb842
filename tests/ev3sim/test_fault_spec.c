/*
 * test_fault_spec.c — the --fault syntax and the value parsers behind every
 * ev3sim option: what each spec maps to in host_sim's fault injection, and
 * a message for every malformed one.
 */
#include <string.h>
#include "tap.h"
#include "ev3sim/fault_spec.h"
#include "ev3sim/parse.h"

#define S 1000000000ULL

static struct ev3sim_fault_spec f;
static char err[200];

static bool parse(const char *spec)
{
	err[0] = '\0';
	return ev3sim_fault_parse(spec, 1, &f, err, sizeof(err));
}

int main(void)
{
	uint64_t ns = 0, u = 0;
	double d = 0;
	unsigned port = 9;

	tap_plan(44);
	ok(ev3sim_parse_time("5s", &ns) && ns == 5 * S, "5s");
	ok(ev3sim_parse_time("2.5", &ns) && ns == 2500000000ULL, "2.5 (seconds by default)");
	ok(ev3sim_parse_time("500ms", &ns) && ns == 500000000ULL, "500ms");
	ok(ev3sim_parse_time("250us", &ns) && ns == 250000ULL, "250us");
	ok(ev3sim_parse_time("7ns", &ns) && ns == 7, "7ns");
	ok(!ev3sim_parse_time("-1s", &ns) && !ev3sim_parse_time("s", &ns) && !ev3sim_parse_time("5 s", &ns) &&
	   !ev3sim_parse_time("", &ns) && !ev3sim_parse_time("1e30", &ns) && !ev3sim_parse_time("5h", &ns),
	   "negative, empty, spaced, huge and unknown-unit times are refused");
	ok(ev3sim_parse_uint("42", 100, &u) && u == 42 && !ev3sim_parse_uint("101", 100, &u) &&
	   !ev3sim_parse_uint("-1", 100, &u) && !ev3sim_parse_uint("4x", 100, &u) &&
	   !ev3sim_parse_uint("", 100, &u), "unsigned integers with a maximum");
	ok(ev3sim_parse_double("-0.25", &d) && d == -0.25 && !ev3sim_parse_double("nan", &d) &&
	   !ev3sim_parse_double("inf", &d) && !ev3sim_parse_double("1.5x", &d), "finite numbers only");
	ok(ev3sim_parse_output_port("D", &port) && port == 3 && ev3sim_parse_output_port("a", &port) &&
	   port == 0 && !ev3sim_parse_output_port("E", &port) && !ev3sim_parse_output_port("AB", &port),
	   "output ports A..D");
	ok(ev3sim_parse_input_port("4", &port) && port == 3 && !ev3sim_parse_input_port("0", &port) &&
	   !ev3sim_parse_input_port("5", &port), "input ports 1..4");

	ok(parse("gyro-noise:2") && f.target == EV3SIM_FAULT_GYRO_NOISE && f.value == 2.0,
	   "gyro-noise:2 sets the gyro's noise option");
	ok(parse("gyro-drift:-1.5") && f.target == EV3SIM_FAULT_GYRO_DRIFT && f.value == -1.5,
	   "gyro-drift:-1.5 sets its drift");
	ok(parse("uart-bit-errors:1e-4") && f.target == EV3SIM_FAULT_BRICK &&
	   f.fault.kind == EV3_FAULT_UART_BIT_ERRORS && f.fault.port == 1 && f.fault.value == 1e-4 &&
	   f.at_ns == 0 && f.fault.duration_ns == 0, "uart-bit-errors:1e-4 on the gyro's port, from the release on");
	ok(parse("uart-drop:0.01:2s:500ms") && f.fault.kind == EV3_FAULT_UART_DROP && f.at_ns == 2 * S &&
	   f.fault.duration_ns == 500000000ULL, "uart-drop with a start and a duration");
	ok(parse("uart-dup:0.5") && f.fault.kind == EV3_FAULT_UART_DUPLICATE, "uart-dup");
	ok(parse("adc-noise:20:1") && f.fault.kind == EV3_FAULT_ADC_NOISE && f.fault.value == 20 &&
	   f.at_ns == S, "adc-noise:20:1");
	ok(parse("encoder-noise:A:50") && f.fault.kind == EV3_FAULT_ENCODER_NOISE && f.fault.port == 0 &&
	   f.fault.value == 50, "encoder-noise:A:50");
	ok(parse("encoder-stuck:D:3:1") && f.fault.kind == EV3_FAULT_ENCODER_STUCK && f.fault.port == 3 &&
	   f.at_ns == 3 * S && f.fault.duration_ns == S, "encoder-stuck:D:3:1");
	ok(parse("motor-stall:a") && f.fault.kind == EV3_FAULT_MOTOR_STALL && f.fault.port == 0,
	   "motor-stall:a");
	ok(parse("unplug:2:5s") && f.fault.kind == EV3_FAULT_UNPLUG && f.fault.port == 1 && f.at_ns == 5 * S &&
	   f.fault.duration_ns == 0, "unplug:2:5s: input port 2 at 5 s, for good");
	ok(parse("unplug:D:1:250ms") && f.fault.kind == EV3_FAULT_MOTOR_UNPLUG && f.fault.port == 3,
	   "unplug:D: the motor on D");

	ok(!parse("") && strstr(err, "unknown fault kind"), "empty spec: %s", err);
	ok(!parse("meteor:3") && strstr(err, "unknown fault kind 'meteor'"), "unknown kind: %s", err);
	ok(!parse("gyro-noise") && strstr(err, "missing or bad value"), "missing value: %s", err);
	ok(!parse("gyro-noise:-1") && strstr(err, "missing or bad value"), "negative noise: %s", err);
	ok(!parse("gyro-noise:2:5s") && strstr(err, "too many fields"), "gyro options are not timed: %s", err);
	ok(!parse("uart-bit-errors:1.5") && strstr(err, "bad value"), "probability above 1: %s", err);
	ok(!parse("uart-drop:0.1:later") && strstr(err, "bad start time 'later'"), "bad start: %s", err);
	ok(!parse("uart-drop:0.1:1:forever") && strstr(err, "bad duration 'forever'"), "bad duration: %s", err);
	ok(!parse("encoder-noise") && strstr(err, "missing port"), "missing port: %s", err);
	ok(!parse("encoder-noise:2:5") && strstr(err, "bad port '2'"), "an input port for a motor fault: %s", err);
	ok(!parse("encoder-noise:A") && strstr(err, "missing or bad value"), "missing rate: %s", err);
	ok(!parse("encoder-noise:A:-4") && strstr(err, "missing or bad value"), "negative rate: %s", err);
	ok(!parse("unplug:9") && strstr(err, "bad port '9'"), "port 9: %s", err);
	ok(!parse("unplug:2:1:1:1") && strstr(err, "too many fields"), "extra field: %s", err);
	ok(!parse("a:b:c:d:e:f:g") && strstr(err, "too many fields"), "far too many fields: %s", err);
	{
		char longspec[300];

		memset(longspec, 'x', sizeof(longspec) - 1);
		longspec[sizeof(longspec) - 1] = '\0';
		ok(!parse(longspec) && strstr(err, "too long"), "an overlong spec: %s", err);
	}
	ok(!parse("motor-stall:A:1:2:3") && strstr(err, "too many fields"), "motor-stall with extra: %s", err);
	ok(!parse("adc-noise:6000") && strstr(err, "bad value"), "ADC noise above 5 V: %s", err);
	ok(!parse("uart-dup:x") && strstr(err, "bad value"), "not a number: %s", err);
	{
		struct ev3sim_fault_spec specs[3];

		ok(parse("motor-stall:A:1") && (specs[0] = f, parse("unplug:1:1")) && (specs[1] = f, parse("unplug:C:2")),
		   "a stall on A, an input unplug on 1, an output unplug on C");
		specs[2] = f;
		is_int(ev3sim_fault_check_wheels(specs, 3, 0, 3, err, sizeof(err)), E_OK,
		       "wheels on A and D: none of them takes a wheel motor away");
		is_int(ev3sim_fault_check_wheels(specs, 3, 2, 3, err, sizeof(err)), E_PAR,
		       "wheels on C and D: unplug:C would");
		ok(strstr(err, "unplug:C would take a wheel off the robot") != NULL, "and says so: %s", err);
	}
	return tap_done();
}
