/*
 * trace.c — signals and their VCD/CSV outputs.  Host only.
 *
 * The VCD body is written to a temporary file as values change, and the
 * header (which must list every signal, including ones declared late) is
 * written in front of it when the file is closed.  Output contains no dates
 * or paths, so the same run gives the same bytes.  A pulse (1 ns high) is
 * recorded as its rise at now and its fall due at now+1.  While a VCD is
 * open the fall is queued and flushed before any later change, so the body
 * stays in time order; without one (the common case: interrupt requests
 * pulse thousands of times per virtual second) the fall is settled lazily,
 * by the signal's own next use, which leaves the same value and counts.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/trace.h"
#include "core_parts.h"
#include "space_internal.h"

struct hs_signal {
	char *scope;
	char *name;
	unsigned width;          /* bits; 0 for real */
	char id[6];              /* VCD identifier */
	bool known;              /* set at least once */
	bool z;
	uint64_t value;
	double real;
	uint64_t changes;
	uint64_t last_change;
	char *initial;           /* VCD value at the time the file was opened (NULL: 'x') */
	bool pulse_pending;      /* high for a pulse whose fall is due at fall_t */
	bool plain;              /* 1 bit, known, not z, no pulse pending: see plain_update */
	bool fall_queued;        /* that fall is in tr.falls (a VCD was open), not settled lazily */
	uint64_t fall_t;
};

static struct {
	struct hs_signal **sigs;
	unsigned nsigs, cap;
	FILE *vcd;               /* final file */
	FILE *body;              /* temporary body */
	uint64_t vcd_t;          /* last timestamp written to the body */
	uint64_t vcd_open_t;
	FILE *csv;
	struct hs_signal **falls; /* pulses whose fall is queued for fall_t */
	unsigned nfalls, falls_cap;
	uint64_t fall_t;
} tr;

/* VCD identifier for signal number i: base-94 over '!'..'~'. */
static void make_id(unsigned i, char *id)
{
	unsigned k = 0;

	do {
		id[k++] = (char)('!' + i % 94U);
		i /= 94U;
	} while (i && k < 5U);
	id[k] = '\0';
}

/* Formats the VCD value change of s (without the identifier separator rules applied). */
static void vcd_value(const struct hs_signal *s, char *buf, size_t n)
{
	if (s->width == 0U) {
		snprintf(buf, n, "r%.17g %s", s->real, s->id);
	} else if (s->width == 1U) {
		snprintf(buf, n, "%c%s", !s->known ? 'x' : s->z ? 'z' : s->value ? '1' : '0', s->id);
	} else if (!s->known || s->z) {
		snprintf(buf, n, "b%c %s", !s->known ? 'x' : 'z', s->id);
	} else {
		char bits[65];
		unsigned k = 0;
		int top = 63;

		while (top > 0 && !((s->value >> top) & 1U))
			top--;
		for (int b = top; b >= 0; b--)
			bits[k++] = (char)('0' + ((s->value >> b) & 1U));
		bits[k] = '\0';
		snprintf(buf, n, "b%s %s", bits, s->id);
	}
}

/* Writes the timestamp if time moved on. */
static void vcd_time(uint64_t t)
{
	if (t != tr.vcd_t) {
		fprintf(tr.body, "#%" PRIu64 "\n", t);
		tr.vcd_t = t;
	}
}

/* Notes whether s is a plain bit, which hs_trace_set changes by its fast path while no
 * file is open (GPIO pins and level interrupt requests change thousands of times per
 * virtual second); called after each change of width, known, z or pulse_pending. */
static inline void plain_update(struct hs_signal *s)
{
	s->plain = s->width == 1U && s->known && !s->z && !s->pulse_pending;
}

/* Ends the pending pulse of s at its fall_t (every queued fall is of tr.fall_t);
 * false if the signal had changed again meanwhile and so does not fall. */
static inline bool apply_fall(struct hs_signal *s)
{
	s->pulse_pending = false;
	s->fall_queued = false;
	plain_update(s);
	if (s->value == 0U || s->z)
		return false;
	s->value = 0;
	s->changes++;
	s->last_change = s->fall_t;
	return true;
}

/* Emits queued pulse falls if the clock has reached them. */
static void flush_falls(uint64_t now)
{
	if (!tr.nfalls || now < tr.fall_t)
		return;
	for (unsigned i = 0; i < tr.nfalls; i++) {
		struct hs_signal *s = tr.falls[i];
		char buf[96];

		if (apply_fall(s) && tr.body) {
			vcd_time(tr.fall_t);
			vcd_value(s, buf, sizeof(buf));
			fprintf(tr.body, "%s\n", buf);
		}
	}
	tr.nfalls = 0;
}

/* True if s has a lazily kept pulse fall (no VCD was open) that is due by now
 * and still lowers it: flush_falls's work for that signal alone. */
static inline bool lazy_fall_due(const struct hs_signal *s, uint64_t now)
{
	return s->pulse_pending && !s->fall_queued && now >= s->fall_t && s->value != 0U && !s->z;
}

/* Applies the lazily kept pulse fall of s if now has reached it. */
static inline void settle_fall(struct hs_signal *s, uint64_t now)
{
	if (s->pulse_pending && !s->fall_queued && now >= s->fall_t)
		(void)apply_fall(s);
}

/* Writes the current value of s at now to the open files. */
static void record_files(struct hs_signal *s, uint64_t now)
{
	char buf[96];

	if (tr.body) {
		vcd_time(now);
		vcd_value(s, buf, sizeof(buf));
		fprintf(tr.body, "%s\n", buf);
	}
	if (tr.csv && s->width != 1U) {
		if (s->width == 0U)
			fprintf(tr.csv, "%" PRIu64 ",%s.%s,%.17g\n", now, s->scope, s->name, s->real);
		else if (s->z)
			fprintf(tr.csv, "%" PRIu64 ",%s.%s,z\n", now, s->scope, s->name);
		else
			fprintf(tr.csv, "%" PRIu64 ",%s.%s,%" PRIu64 "\n", now, s->scope, s->name, s->value);
	}
}

/* Records the current value of s at now: counted, and written if a file is open
 * (without one, a change costs the count: GPIO pins change on every tacho edge). */
static inline void record(struct hs_signal *s, uint64_t now)
{
	s->changes++;
	s->last_change = now;
	if (tr.body || tr.csv)
		record_files(s, now);
}

/* Makes room for one more pointer in the array *arr holding n of *cap (doubling,
 * first_cap at first); false if out of memory (the array is kept). */
static bool room_for_one(struct hs_signal ***arr, unsigned n, unsigned *cap, unsigned first_cap)
{
	unsigned new_cap;
	struct hs_signal **p;

	if (n < *cap)
		return true;
	new_cap = *cap ? 2U * *cap : first_cap;
	/* NOLINTNEXTLINE(bugprone-sizeof-expression): an array of pointers */
	p = realloc(*arr, new_cap * sizeof(*p));
	if (!p)
		return false;
	*arr = p;
	*cap = new_cap;
	return true;
}

static struct hs_signal *declare(const char *scope, const char *name, unsigned width)
{
	struct hs_signal *s = hs_trace_find(scope, name);

	if (s) {
		if (s->width != width)
			rtos_host_bug("host_sim", "trace signal %s.%s declared with width %u and %u",
				      scope, name, s->width, width);
		return s;
	}
	if (!room_for_one(&tr.sigs, tr.nsigs, &tr.cap, 64U))
		return NULL;
	s = calloc(1, sizeof(*s));
	if (!s)
		return NULL;
	s->scope = strdup(scope);
	s->name = strdup(name);
	s->width = width;
	make_id(tr.nsigs, s->id);
	tr.sigs[tr.nsigs++] = s;
	return s;
}

struct hs_signal *hs_trace_signal(const char *scope, const char *name, unsigned width)
{
	if (!scope || !name || width < 1U || width > 64U) {
		rtos_host_bug("host_sim", "hs_trace_signal(%s, %s, %u): scope, name and width 1..64 required",
			      scope ? scope : "NULL", name ? name : "NULL", width);
		return NULL;
	}
	return declare(scope, name, width);
}

struct hs_signal *hs_trace_signal_real(const char *scope, const char *name)
{
	if (!scope || !name) {
		rtos_host_bug("host_sim", "hs_trace_signal_real: scope and name required");
		return NULL;
	}
	return declare(scope, name, 0);
}

struct hs_signal *hs_trace_find(const char *scope, const char *name)
{
	for (unsigned i = 0; scope && name && i < tr.nsigs; i++)
		if (strcmp(tr.sigs[i]->name, name) == 0 && strcmp(tr.sigs[i]->scope, scope) == 0)
			return tr.sigs[i];
	return NULL;
}

/* Sets a signal of width 1..64 to value at now (the falls due are flushed). */
static inline void set_bits(struct hs_signal *s, uint64_t value, uint64_t now)
{
	if (s->width < 64U)
		value &= (1ULL << s->width) - 1U;
	if (s->known && !s->z && s->value == value)
		return;
	s->known = true;
	s->z = false;
	plain_update(s);
	s->value = value;
	record(s, now);
}

void hs_trace_set(struct hs_signal *s, uint64_t value)
{
	uint64_t now;

	if (!s)
		return;
	if (s->plain && !tr.body) {
		/* the general path's work for a plain bit without a VCD (the CSV has no 1-bit
		 * signals): no fall to flush or settle, only the count */
		value &= 1U;
		if (s->value != value) {
			s->value = value;
			s->changes++;
			s->last_change = rtos_host_now();
		}
		return;
	}
	if (s->width == 0U) {
		hs_trace_set_real(s, (double)value);
		return;
	}
	now = rtos_host_now();
	flush_falls(now);
	settle_fall(s, now);
	set_bits(s, value, now);
}

void hs_trace_set_z(struct hs_signal *s)
{
	uint64_t now;

	if (!s)
		return;
	now = rtos_host_now();
	flush_falls(now);
	settle_fall(s, now);
	if (s->known && s->z)
		return;
	s->known = true;
	s->z = true;
	s->plain = false;
	s->value = 0;
	record(s, now);
}

/* Sets real-valued signal s to value at now, the falls due by now flushed. */
static inline void set_real(struct hs_signal *s, double value, uint64_t now)
{
	if (s->known && s->real == value)
		return;
	s->known = true;
	s->real = value;
	record(s, now);
}

void hs_trace_set_real(struct hs_signal *s, double value)
{
	uint64_t now;

	if (!s)
		return;
	if (s->width != 0U) {
		hs_trace_set(s, (uint64_t)value);
		return;
	}
	now = rtos_host_now();
	flush_falls(now);
	set_real(s, value, now);
}

/* One look at the clock and the falls for both (a motor's angle and speed at each step). */
void hs_trace_set_real_pair(struct hs_signal *a, double va, struct hs_signal *b, double vb)
{
	uint64_t now;

	if (!a || !b || a->width != 0U || b->width != 0U) {
		hs_trace_set_real(a, va);
		hs_trace_set_real(b, vb);
		return;
	}
	now = rtos_host_now();
	flush_falls(now);
	set_real(a, va, now);
	set_real(b, vb, now);
}

/* Puts the pending fall of s into the queue written to the VCD; false if out of memory. */
static bool queue_fall(struct hs_signal *s)
{
	if (!room_for_one(&tr.falls, tr.nfalls, &tr.falls_cap, 16U))
		return false;
	tr.falls[tr.nfalls++] = s;
	tr.fall_t = s->fall_t;
	s->fall_queued = true;
	return true;
}

void hs_trace_pulse(struct hs_signal *s)
{
	uint64_t now;

	if (!s)
		return;
	if (s->width != 1U) {
		rtos_host_bug("host_sim", "hs_trace_pulse(%s.%s): not a 1-bit signal", s->scope, s->name);
		return;
	}
	now = rtos_host_now();
	flush_falls(now);
	if (lazy_fall_due(s, now) && !tr.body) {
		/* the common train of requests: the last pulse's fall and this rise, as counts */
		s->changes += 2U;
		s->last_change = now;
		s->fall_t = now + 1U;
		return;
	}
	settle_fall(s, now);
	if (s->pulse_pending)
		return;         /* already high in this nanosecond */
	set_bits(s, 1, now);
	s->fall_t = now + 1U;
	s->pulse_pending = !tr.body || queue_fall(s);
	plain_update(s);
}

uint64_t hs_signal_value(const struct hs_signal *s)
{
	if (s && s->pulse_pending)
		flush_falls(rtos_host_now());
	return s ? (lazy_fall_due(s, rtos_host_now()) ? 0U : s->value) : 0U;
}

double hs_signal_real(const struct hs_signal *s)
{
	return s ? (s->width == 0U ? s->real : (double)s->value) : 0.0;
}

bool hs_signal_is_z(const struct hs_signal *s)
{
	return s && s->z;
}

uint64_t hs_signal_changes(const struct hs_signal *s)
{
	if (s && s->pulse_pending)
		flush_falls(rtos_host_now());
	return s ? s->changes + (lazy_fall_due(s, rtos_host_now()) ? 1U : 0U) : 0U;
}

uint64_t hs_signal_last_change(const struct hs_signal *s)
{
	if (s && s->pulse_pending)
		flush_falls(rtos_host_now());
	return s ? (lazy_fall_due(s, rtos_host_now()) ? s->fall_t : s->last_change) : 0U;
}

int hs_trace_open_vcd(const char *path)
{
	FILE *f, *body;
	char buf[96];

	if (tr.vcd) {
		errno = EBUSY;
		return -1;
	}
	f = fopen(path, "w");
	if (!f)
		return -1;
	body = tmpfile();
	if (!body) {
		fclose(f);
		return -1;
	}
	tr.vcd = f;
	tr.body = body;
	tr.vcd_open_t = tr.vcd_t = rtos_host_now();
	for (unsigned i = 0; i < tr.nsigs; i++) {
		struct hs_signal *s = tr.sigs[i];

		/* a pulse of this nanosecond falls in the file; an older one has fallen */
		settle_fall(s, tr.vcd_open_t);
		if (s->pulse_pending && !s->fall_queued) {
			s->pulse_pending = queue_fall(s);
			plain_update(s);
		}
		free(s->initial);
		vcd_value(s, buf, sizeof(buf));
		s->initial = strdup(buf);
	}
	hs_kernel_timeline_start();
	return 0;
}

int hs_trace_open_csv(const char *path)
{
	if (tr.csv) {
		errno = EBUSY;
		return -1;
	}
	tr.csv = fopen(path, "w");
	if (!tr.csv)
		return -1;
	fputs("time_ns,signal,value\n", tr.csv);
	return 0;
}

/* Writes the VCD header, the initial values and the body into the final file. */
static void vcd_finish(void)
{
	char buf[4096];
	size_t n;
	const char *cur = NULL;

	fputs("$version ev3lx host_sim $end\n$timescale 1ns $end\n$scope module ev3 $end\n", tr.vcd);
	/* Signals grouped by scope, scopes in order of first declaration. */
	for (unsigned i = 0; i < tr.nsigs; i++) {
		bool seen = false;

		for (unsigned j = 0; j < i; j++)
			if (strcmp(tr.sigs[j]->scope, tr.sigs[i]->scope) == 0)
				seen = true;
		if (seen)
			continue;
		cur = tr.sigs[i]->scope;
		fprintf(tr.vcd, "$scope module %s $end\n", cur);
		for (unsigned j = i; j < tr.nsigs; j++) {
			const struct hs_signal *s = tr.sigs[j];

			if (strcmp(s->scope, cur) != 0)
				continue;
			if (s->width == 0U)
				fprintf(tr.vcd, "$var real 64 %s %s $end\n", s->id, s->name);
			else
				fprintf(tr.vcd, "$var wire %u %s %s $end\n", s->width, s->id, s->name);
		}
		fputs("$upscope $end\n", tr.vcd);
	}
	fputs("$upscope $end\n$enddefinitions $end\n", tr.vcd);
	fprintf(tr.vcd, "#%" PRIu64 "\n$dumpvars\n", tr.vcd_open_t);
	for (unsigned i = 0; i < tr.nsigs; i++) {
		const struct hs_signal *s = tr.sigs[i];

		if (s->initial) {
			fprintf(tr.vcd, "%s\n", s->initial);
		} else if (s->width == 0U) {
			fprintf(tr.vcd, "r0 %s\n", s->id);
		} else if (s->width == 1U) {
			fprintf(tr.vcd, "x%s\n", s->id);
		} else {
			fprintf(tr.vcd, "bx %s\n", s->id);
		}
	}
	fputs("$end\n", tr.vcd);
	rewind(tr.body);
	while ((n = fread(buf, 1, sizeof(buf), tr.body)) > 0)
		fwrite(buf, 1, n, tr.vcd);
}

int hs_trace_close(void)
{
	int status = 0;

	if (tr.nfalls)
		flush_falls(tr.fall_t);
	for (unsigned i = 0; i < tr.nsigs; i++)
		settle_fall(tr.sigs[i], UINT64_MAX);
	if (tr.vcd) {
		hs_kernel_timeline_stop();
		vcd_finish();
		if (ferror(tr.vcd) || ferror(tr.body))
			status = -1;
		if (fclose(tr.vcd) != 0)
			status = -1;
		fclose(tr.body);
		tr.vcd = tr.body = NULL;
	}
	if (tr.csv) {
		if (ferror(tr.csv))
			status = -1;
		if (fclose(tr.csv) != 0)
			status = -1;
		tr.csv = NULL;
	}
	for (unsigned i = 0; i < tr.nsigs; i++) {
		free(tr.sigs[i]->initial);
		tr.sigs[i]->initial = NULL;
	}
	return status;
}

void hs_trace_reglog(const char *filter, FILE *out)
{
	hs_space_set_reglog(filter, out);
}

void hs_trace_reset(void)
{
	hs_trace_close();
	for (unsigned i = 0; i < tr.nsigs; i++) {
		free(tr.sigs[i]->scope);
		free(tr.sigs[i]->name);
		free(tr.sigs[i]->initial);
		free(tr.sigs[i]);
	}
	free(tr.sigs);
	free(tr.falls);
	memset(&tr, 0, sizeof(tr));
}
