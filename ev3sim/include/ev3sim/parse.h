/*
 * parse.h — strict parsers for ev3sim's command-line values: the whole
 * string must be consumed, ranges are checked, and false means "bad value"
 * (the caller names the option in its message).
 */
#ifndef EV3SIM_PARSE_H
#define EV3SIM_PARSE_H

#include <stdbool.h>
#include <stdint.h>

/* A finite decimal number (strtod syntax). */
bool ev3sim_parse_double(const char *s, double *out);
/* An unsigned decimal integer up to max. */
bool ev3sim_parse_uint(const char *s, uint64_t max, uint64_t *out);
/* A time with an optional unit: ns, us, ms, s (default s), not negative,
 * at most a day; "2.5", "500ms", "5s". */
bool ev3sim_parse_time(const char *s, uint64_t *ns);
/* An output port "A".."D" (or "a".."d") as 0..3. */
bool ev3sim_parse_output_port(const char *s, unsigned *port);
/* An input port "1".."4" as 0..3. */
bool ev3sim_parse_input_port(const char *s, unsigned *port);

#endif /* EV3SIM_PARSE_H */
