/*
 * lx_log_test.h — what linux_compat tests of logged and reported behaviour share: the kernel log captured
 * line by line, and running a statement that must report exactly one bug.
 */
#ifndef EV3LX_TESTS_LX_LOG_TEST_H
#define EV3LX_TESTS_LX_LOG_TEST_H

#include "lx_test.h"
#include <string.h>

static char dc_log[4096];

/* Appends one syslog line to dc_log. */
static void dc_log_sink(const char *line, void *ctx)
{
	(void)ctx;
	strncat(dc_log, line, sizeof(dc_log) - strlen(dc_log) - 2);
	strcat(dc_log, "\n");
}

/* Starts capturing the kernel log afresh. */
static inline void dc_log_start(void)
{
	dc_log[0] = '\0';
	rtos_host_trace_set_source_sink("syslog", dc_log_sink, NULL);
}

/* Whether the captured log has a line containing text. */
static inline bool dc_logged(const char *text)
{
	return strstr(dc_log, text) != NULL;
}

static char dc_bug[320] __attribute__((unused));

/* Runs stmt, which must report exactly one bug; its text is in dc_bug and
 * the statement's value is the count of bugs it reported. */
#define DC_EXPECT_BUG(stmt) ({						\
	uint_t before_ = rtos_host_bug_count();				\
	rtos_host_expect_bugs(true);					\
	stmt;								\
	rtos_host_expect_bugs(false);					\
	snprintf(dc_bug, sizeof(dc_bug), "%s", rtos_host_last_bug());	\
	rtos_host_bug_count() - before_;				\
})

#endif /* EV3LX_TESTS_LX_LOG_TEST_H */
