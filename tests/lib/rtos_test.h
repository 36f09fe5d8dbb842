/*
 * rtos_test.h — small helpers for the rtos_stub tests: an event log that
 * records what ran in which order and at what virtual time.
 */
#ifndef EV3LX_TESTS_RTOS_TEST_H
#define EV3LX_TESTS_RTOS_TEST_H

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "rtos_host.h"

static char rt_log_buf[8192];

/* Clears the log. */
static inline void rt_log_reset(void)
{
	rt_log_buf[0] = '\0';
}

/* Appends one space-separated word to the log. */
static inline void __attribute__((format(printf, 1, 2))) rt_log(const char *fmt, ...)
{
	size_t len = strlen(rt_log_buf);
	va_list ap;

	if (len > 0 && len < sizeof(rt_log_buf) - 1)
		rt_log_buf[len++] = ' ';
	va_start(ap, fmt);
	vsnprintf(rt_log_buf + len, sizeof(rt_log_buf) - len, fmt, ap);
	va_end(ap);
}

/* The log so far. */
static inline const char *rt_log_text(void)
{
	return rt_log_buf;
}

#define RT_TASK(id, fn, pri, act) { (id), (act) ? TA_ACT : TA_NULL, 0, (fn), (pri), 4096, TDOM_KERNEL, #fn }

#endif /* EV3LX_TESTS_RTOS_TEST_H */
