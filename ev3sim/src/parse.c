/*
 * parse.c — strict value parsers for the command line (parse.h).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ev3sim/parse.h"

#define NS_PER_DAY (86400ULL * 1000000000ULL)

bool ev3sim_parse_double(const char *s, double *out)
{
	char *end;
	double v;

	if (s == NULL || *s == '\0')
		return false;
	errno = 0;
	v = strtod(s, &end);
	if (errno != 0 || *end != '\0' || !isfinite(v))
		return false;
	*out = v;
	return true;
}

bool ev3sim_parse_uint(const char *s, uint64_t max, uint64_t *out)
{
	char *end;
	unsigned long long v;

	if (s == NULL || *s < '0' || *s > '9')
		return false;
	errno = 0;
	v = strtoull(s, &end, 10);
	if (errno != 0 || *end != '\0' || v > max)
		return false;
	*out = v;
	return true;
}

bool ev3sim_parse_time(const char *s, uint64_t *ns)
{
	static const struct { const char *unit; double scale; } units[] = {
		{ "ns", 1.0 }, { "us", 1e3 }, { "ms", 1e6 }, { "s", 1e9 },
	};
	char num[64];
	size_t len;
	double scale = 1e9, v;

	if (s == NULL || (len = strlen(s)) == 0 || len >= sizeof(num))
		return false;
	memcpy(num, s, len + 1);
	for (size_t i = 0; i < sizeof(units) / sizeof(units[0]); i++) {
		size_t ul = strlen(units[i].unit);

		if (len > ul && strcmp(num + len - ul, units[i].unit) == 0 &&
		    !(ul == 1 && strchr("num", num[len - 2]) != NULL)) {
			num[len - ul] = '\0';
			scale = units[i].scale;
			break;
		}
	}
	if (!ev3sim_parse_double(num, &v) || v < 0 || v * scale > (double)NS_PER_DAY)
		return false;
	*ns = (uint64_t)llround(v * scale);
	return true;
}

bool ev3sim_parse_output_port(const char *s, unsigned *port)
{
	if (s == NULL || s[0] == '\0' || s[1] != '\0')
		return false;
	if (s[0] >= 'A' && s[0] <= 'D')
		*port = (unsigned)(s[0] - 'A');
	else if (s[0] >= 'a' && s[0] <= 'd')
		*port = (unsigned)(s[0] - 'a');
	else
		return false;
	return true;
}

bool ev3sim_parse_input_port(const char *s, unsigned *port)
{
	if (s == NULL || s[0] < '1' || s[0] > '4' || s[1] != '\0')
		return false;
	*port = (unsigned)(s[0] - '1');
	return true;
}
