/*
 * example_test.h — running an EV3RT example app (examples/NAME, configured
 * from its app.cfg and linked into this test as ev3rt_app_cfg) in ev3sim's
 * robots, and reading what it logged.
 */
#ifndef EV3LX_TESTS_EXAMPLE_TEST_H
#define EV3LX_TESTS_EXAMPLE_TEST_H

#include <stdio.h>
#include <string.h>
#include "tap.h"
#include "ev3sim/run.h"

/* The app's configuration, generated from its app.cfg. */
extern const struct rtos_cfg ev3rt_app_cfg;

#define EX_MAX_LINES 64

static struct {
	char lines[EX_MAX_LINES][160];
	unsigned n;
} ex_log;

/* Keeps the NOTICE lines the app and the drivers log. */
static void ex_log_sink(const char *line, void *ctx)
{
	(void)ctx;
	if (strncmp(line, "NOTICE: ", 8) == 0 && ex_log.n < EX_MAX_LINES)
		snprintf(ex_log.lines[ex_log.n++], sizeof(ex_log.lines[0]), "%s", line + 8);
}

/* The last logged NOTICE line that starts with prefix, or NULL. */
static inline const char *ex_logged(const char *prefix)
{
	for (unsigned i = ex_log.n; i-- > 0;)
		if (strncmp(ex_log.lines[i], prefix, strlen(prefix)) == 0)
			return ex_log.lines[i];
	return NULL;
}

/* How many logged NOTICE lines start with prefix and contain what. */
static inline unsigned ex_count(const char *prefix, const char *what)
{
	unsigned n = 0;

	for (unsigned i = 0; i < ex_log.n; i++)
		n += strncmp(ex_log.lines[i], prefix, strlen(prefix)) == 0 &&
		     strstr(ex_log.lines[i], what) != NULL;
	return n;
}

/* Runs the app with o (its log captured); false if the run could not be done. */
static inline bool ex_run(struct ev3sim_run_opts *o, struct ev3sim_run_result *r)
{
	char err[256], line[1024];

	memset(&ex_log, 0, sizeof(ex_log));
	o->log_sink = ex_log_sink;
	if (ev3sim_run(o, &ev3rt_app_cfg, r, err, sizeof(err)) != E_OK) {
		tap_diag("run failed: %s", err);
		return false;
	}
	ev3sim_run_summary(o, r, line, sizeof(line));
	tap_diag("%s", line);
	return true;
}

#endif /* EV3LX_TESTS_EXAMPLE_TEST_H */
