/*
 * tap.h — a small Test Anything Protocol helper for ev3lx's C tests.
 *
 *   int main(void) {
 *       tap_plan(3);
 *       ok(1 + 1 == 2, "addition");
 *       is_int(f(), 42, "f answers");
 *       tap_skip(1, "needs trapping, unavailable under qemu-arm");
 *       return tap_done();
 *   }
 *
 * Output goes to stdout, diagnostics start with "# ".  tap_done() returns
 * the process exit status: 0 only if every planned test ran and passed.
 */
#ifndef EV3LX_TAP_H
#define EV3LX_TAP_H

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct tap_state {
	int planned;   /* -1: no plan yet */
	int run;
	int failed;
};

static struct tap_state tap_state_ = { -1, 0, 0 };

/* Declares the number of tests (prints "1..n"). */
static inline void tap_plan(int n)
{
	tap_state_.planned = n;
	printf("1..%d\n", n);
	fflush(stdout);
}

/* Prints a diagnostic line. */
static inline void __attribute__((format(printf, 1, 2))) tap_diag(const char *fmt, ...)
{
	va_list ap;

	fputs("# ", stdout);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	fputc('\n', stdout);
	fflush(stdout);
}

/* Records one test result; returns pass (so callers can add diagnostics). */
static inline int __attribute__((format(printf, 4, 5)))
tap_ok_at(int pass, const char *file, int line, const char *fmt, ...)
{
	va_list ap;

	tap_state_.run++;
	if (!pass)
		tap_state_.failed++;
	printf("%sok %d - ", pass ? "" : "not ", tap_state_.run);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	fputc('\n', stdout);
	if (!pass)
		printf("#   failed at %s:%d\n", file, line);
	fflush(stdout);
	return pass;
}

#define ok(cond, ...) tap_ok_at(!!(cond), __FILE__, __LINE__, __VA_ARGS__)

/* Integer equality with got/expected diagnostics. */
#define is_int(got, expected, ...) do { \
	long long tap_g_ = (long long)(got), tap_e_ = (long long)(expected); \
	if (!tap_ok_at(tap_g_ == tap_e_, __FILE__, __LINE__, __VA_ARGS__)) \
		tap_diag("  got %lld, expected %lld", tap_g_, tap_e_); \
} while (0)

/* Unsigned 64-bit equality. */
#define is_u64(got, expected, ...) do { \
	uint64_t tap_g_ = (uint64_t)(got), tap_e_ = (uint64_t)(expected); \
	if (!tap_ok_at(tap_g_ == tap_e_, __FILE__, __LINE__, __VA_ARGS__)) \
		tap_diag("  got %" PRIu64 ", expected %" PRIu64, tap_g_, tap_e_); \
} while (0)

/* String equality (NULL-safe). */
#define is_str(got, expected, ...) do { \
	const char *tap_g_ = (got), *tap_e_ = (expected); \
	int tap_p_ = (tap_g_ && tap_e_) ? strcmp(tap_g_, tap_e_) == 0 : tap_g_ == tap_e_; \
	if (!tap_ok_at(tap_p_, __FILE__, __LINE__, __VA_ARGS__)) \
		tap_diag("  got \"%s\", expected \"%s\"", tap_g_ ? tap_g_ : "(null)", \
			 tap_e_ ? tap_e_ : "(null)"); \
} while (0)

/* Value within [lo, hi]. */
#define in_range(got, lo, hi, ...) do { \
	double tap_g_ = (double)(got), tap_l_ = (double)(lo), tap_h_ = (double)(hi); \
	if (!tap_ok_at(tap_g_ >= tap_l_ && tap_g_ <= tap_h_, __FILE__, __LINE__, __VA_ARGS__)) \
		tap_diag("  got %g, expected within [%g, %g]", tap_g_, tap_l_, tap_h_); \
} while (0)

/* Skips n tests with a reason ("ok N # SKIP reason"). */
static inline void tap_skip(int n, const char *reason)
{
	for (int i = 0; i < n; i++)
		printf("ok %d # SKIP %s\n", ++tap_state_.run, reason);
	fflush(stdout);
}

/* Skips the whole program ("1..0 # SKIP reason"); returns the exit status. */
static inline int tap_skip_all(const char *reason)
{
	printf("1..0 # SKIP %s\n", reason);
	fflush(stdout);
	return 0;
}

/* Stops the run at once ("Bail out!"). */
static inline void __attribute__((noreturn)) tap_bail_out(const char *reason)
{
	printf("Bail out! %s\n", reason);
	fflush(stdout);
	exit(255);
}

/* Ends the run: prints a plan if none was given; returns the exit status. */
static inline int tap_done(void)
{
	if (tap_state_.planned < 0)
		printf("1..%d\n", tap_state_.run);
	else if (tap_state_.planned != tap_state_.run)
		tap_diag("planned %d tests but ran %d", tap_state_.planned, tap_state_.run);
	fflush(stdout);
	if (tap_state_.failed)
		tap_diag("failed %d of %d tests", tap_state_.failed, tap_state_.run);
	return (tap_state_.failed || (tap_state_.planned >= 0 && tap_state_.planned != tap_state_.run)) ? 1 : 0;
}

#endif /* EV3LX_TAP_H */
