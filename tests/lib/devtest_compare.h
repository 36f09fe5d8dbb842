/*
 * devtest_compare.h — for device-model tests that run one register sequence
 * twice, with a model setting changed (a frame's end deferred or queued, the
 * register log on or off), and assert that the driver's side saw the same:
 * the observations (what was read, its value, the virtual time and the
 * interrupt lines then) and, when the register log is on, how much it logged.
 * The including test defines _XOPEN_SOURCE 700 (or _POSIX_C_SOURCE 200809L)
 * before its first include (open_memstream).
 */
#ifndef TESTS_HOST_SIM_DEVICES_DEVTEST_COMPARE_H
#define TESTS_HOST_SIM_DEVICES_DEVTEST_COMPARE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tap.h"
#include "host_sim/clock.h"
#include "host_sim/trace.h"

#define DEVTEST_MAX_NOTES 512

/* One observation: what was seen, its value, when, and the interrupt lines
 * then (a bit per line the test watches). */
struct devtest_note {
	const char *what;
	uint32_t value;
	uint64_t at;
	uint32_t lines;
};

struct devtest_notes {
	struct devtest_note note[DEVTEST_MAX_NOTES];
	unsigned count;
};

/* Records an observation in n, now (nothing once n is full: the count then tells). */
static inline void devtest_note(struct devtest_notes *n, const char *what, uint32_t value, uint32_t lines)
{
	if (n->count < DEVTEST_MAX_NOTES)
		n->note[n->count++] = (struct devtest_note){ what, value, hs_now(), lines };
}

/* The number of b's observations the same as a's at the same place, with a
 * diagnostic naming both runs for each that differs. */
static inline unsigned devtest_same_notes(const struct devtest_notes *a, const struct devtest_notes *b,
					  const char *a_name, const char *b_name)
{
	unsigned same = 0;

	for (unsigned i = 0; i < a->count && i < b->count; i++) {
		const struct devtest_note *e = &a->note[i], *d = &b->note[i];

		if (strcmp(e->what, d->what) == 0 && e->value == d->value && e->at == d->at && e->lines == d->lines) {
			same++;
			continue;
		}
		tap_diag("%s: %s 0x%08x at %llu lines 0x%x, %s %s 0x%08x at %llu lines 0x%x", e->what, a_name,
			 e->value, (unsigned long long)e->at, e->lines, b_name, d->what, d->value,
			 (unsigned long long)d->at, d->lines);
	}
	return same;
}

/* The first observation named what in n, or NULL. */
static inline const struct devtest_note *devtest_find_note(const struct devtest_notes *n, const char *what)
{
	for (unsigned i = 0; i < n->count; i++)
		if (strcmp(n->note[i].what, what) == 0)
			return &n->note[i];
	return NULL;
}

/* The register log of the regions filter names, kept in memory. */
struct devtest_reglog {
	FILE *f;
	char *text;
	size_t len;
};

/* Starts logging the registers of the regions filter names into l. */
static inline void devtest_reglog_begin(struct devtest_reglog *l, const char *filter)
{
	l->text = NULL;
	l->len = 0;
	l->f = open_memstream(&l->text, &l->len);
	if (l->f == NULL)
		tap_bail_out("open_memstream");
	hs_trace_reglog(filter, l->f);
}

/* Stops the register log l began; returns the number of lines it logged. */
static inline unsigned devtest_reglog_end(struct devtest_reglog *l)
{
	unsigned lines = 0;

	hs_trace_reglog(NULL, NULL);
	fclose(l->f);
	for (const char *c = l->text; *c; c++)
		lines += *c == '\n';
	free(l->text);
	return lines;
}

#endif /* TESTS_HOST_SIM_DEVICES_DEVTEST_COMPARE_H */
