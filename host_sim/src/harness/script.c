/*
 * script.c — scenario scripts (scenario.h): a line-based description of
 * stimuli, runs and expectations for tests and ev3sim.  Host only.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/intc.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define MAX_PENDING 256U

/* A command scheduled with "at". */
struct action {
	bool used;
	bool is_irq;
	unsigned arg;          /* pin or system interrupt */
	enum hs_pin_ext ext;
};

static struct action pending[MAX_PENDING];

/* Parses "<number>[unit]" into ns; false if malformed. */
static bool parse_time(const char *s, uint64_t *ns)
{
	char *end;
	unsigned long long v = strtoull(s, &end, 10);
	uint64_t mul = 1;

	if (end == s)
		return false;
	if (*end == '\0' || strcmp(end, "ns") == 0)
		mul = 1;
	else if (strcmp(end, "us") == 0)
		mul = 1000ULL;
	else if (strcmp(end, "ms") == 0)
		mul = 1000000ULL;
	else if (strcmp(end, "s") == 0)
		mul = 1000000000ULL;
	else
		return false;
	*ns = (uint64_t)v * mul;
	return true;
}

static bool parse_ext(const char *s, enum hs_pin_ext *ext)
{
	static const struct { const char *name; enum hs_pin_ext ext; } names[] = {
		{ "high", HS_EXT_HIGH }, { "low", HS_EXT_LOW }, { "float", HS_EXT_FLOAT },
		{ "pullup", HS_EXT_PULL_UP }, { "pulldown", HS_EXT_PULL_DOWN },
	};

	for (unsigned i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
		if (strcmp(s, names[i].name) == 0) {
			*ext = names[i].ext;
			return true;
		}
	}
	return false;
}

/* Performs an action now. */
static void act(const struct action *a)
{
	if (a->is_irq)
		hs_intc_raise(a->arg);
	else
		hs_gpio_drive(a->arg, a->ext);
}

static void scheduled(void *arg)
{
	struct action *a = arg;

	act(a);
	a->used = false;
}

/* Runs or schedules an action; false if no slot is left. */
static bool do_or_schedule(const struct action *a, bool at, uint64_t when)
{
	if (!at) {
		act(a);
		return true;
	}
	for (unsigned i = 0; i < MAX_PENDING; i++) {
		if (!pending[i].used) {
			pending[i] = *a;
			pending[i].used = true;
			hs_event_at(when, scheduled, &pending[i]);
			return true;
		}
	}
	return false;
}

/* Runs one line; returns 0, or -1 (syntax: message in err) or 1 (expectation failed: message in err). */
static int run_line(char *line, unsigned no, char *err, size_t errlen)
{
	char *w[6] = { 0 };
	unsigned n = 0, i = 0;
	bool at = false;
	uint64_t when = 0, t;
	struct action a = { 0 };
	char *hash = strchr(line, '#');

	if (hash)
		*hash = '\0';
	/* cppcheck-suppress strtokCalled ; one thread, and the line is split before anything else runs */
	for (char *tok = strtok(line, " \t\r"); tok && n < 6U; tok = strtok(NULL, " \t\r"))
		w[n++] = tok;
	if (n == 0)
		return 0;
	if (strcmp(w[0], "at") == 0) {
		if (n < 3 || !parse_time(w[1], &when)) {
			snprintf(err, errlen, "line %u: at <time> <command>", no);
			return -1;
		}
		at = true;
		i = 2;
	}
	n -= i;
	if (strcmp(w[i], "drive") == 0 && n == 3) {
		int pin = hs_gpio_parse(w[i + 1]);

		if (pin < 0 || !parse_ext(w[i + 2], &a.ext)) {
			snprintf(err, errlen, "line %u: drive GP<bank>_<bit> high|low|float|pullup|pulldown", no);
			return -1;
		}
		a.arg = (unsigned)pin;
	} else if (strcmp(w[i], "irq") == 0 && n == 2) {
		char *end;
		unsigned long v = strtoul(w[i + 1], &end, 10);

		if (*end || v >= HS_INTC_NSYSINT) {
			snprintf(err, errlen, "line %u: irq <system interrupt 0..%u>", no, HS_INTC_NSYSINT - 1U);
			return -1;
		}
		a.is_irq = true;
		a.arg = (unsigned)v;
	} else if (at) {
		snprintf(err, errlen, "line %u: only drive and irq can be scheduled with at", no);
		return -1;
	} else if (strcmp(w[i], "run") == 0 && n == 2 && parse_time(w[i + 1], &t)) {
		hs_sim_run_for(t);
		return 0;
	} else if (strcmp(w[i], "until") == 0 && n == 2 && parse_time(w[i + 1], &t)) {
		if (t > hs_now())
			hs_sim_run_until(t);
		return 0;
	} else if (strcmp(w[i], "expect-bugs") == 0 && n == 2) {
		unsigned long want = strtoul(w[i + 1], NULL, 10);

		if (rtos_host_bug_count() != want) {
			snprintf(err, errlen, "line %u: expected %lu bug reports, got %u", no, want, rtos_host_bug_count());
			return 1;
		}
		return 0;
	} else if (strcmp(w[i], "expect") == 0 && n == 3) {
		int pin = hs_gpio_parse(w[i + 1]);
		unsigned long long want = strtoull(w[i + 2], NULL, 0);
		uint64_t got;

		if (pin >= 0) {
			got = hs_gpio_level((unsigned)pin);
		} else {
			char *dot = strchr(w[i + 1], '.');
			struct hs_signal *s;

			if (!dot) {
				snprintf(err, errlen, "line %u: expect <pin>|<scope>.<name> <value>", no);
				return -1;
			}
			*dot = '\0';
			s = hs_trace_find(w[i + 1], dot + 1);
			*dot = '.';
			if (!s) {
				snprintf(err, errlen, "line %u: no trace signal %s", no, w[i + 1]);
				return 1;
			}
			got = hs_signal_value(s);
		}
		if (got != want) {
			snprintf(err, errlen, "line %u: %s is %" PRIu64 " at %" PRIu64 " ns, expected %llu",
				 no, w[i + 1], got, hs_now(), want);
			return 1;
		}
		return 0;
	} else {
		snprintf(err, errlen, "line %u: unknown or malformed command '%s'", no, w[i]);
		return -1;
	}
	if (!do_or_schedule(&a, at, when)) {
		snprintf(err, errlen, "line %u: more than %u scheduled commands pending", no, MAX_PENDING);
		return -1;
	}
	return 0;
}

ER hs_sim_script(const char *text, char *err, size_t errlen)
{
	char line[256];
	char first[256] = "";
	unsigned no = 0;
	ER result = E_OK;
	char scratch[1];

	if (!err || errlen == 0) {
		err = scratch;
		errlen = sizeof(scratch);
	}
	err[0] = '\0';
	if (!text)
		return E_PAR;
	while (*text) {
		size_t len = strcspn(text, "\n");
		int r;

		no++;
		if (len >= sizeof(line)) {
			snprintf(err, errlen, "line %u: longer than %zu characters", no, sizeof(line) - 1U);
			return E_PAR;
		}
		memcpy(line, text, len);
		line[len] = '\0';
		text += len + (text[len] == '\n');
		r = run_line(line, no, first, sizeof(first));
		if (r < 0) {
			snprintf(err, errlen, "%s", first);
			return E_PAR;
		}
		if (r > 0 && result == E_OK) {
			snprintf(err, errlen, "%s", first);
			result = E_OBJ;
		}
	}
	return result;
}
