/*
 * app.c — misbehave: the main task does what EV3LX_MISBEHAVE names, each a
 * mistake an app can make on the brick:
 *   stall       loops without a service call in code the app's CPU time
 *               does not count (as a library's loop: time stands still)
 *   busy        loops without a service call in its own code (its CPU
 *               time lets virtual time pass: no stall)
 *   null        stores through a NULL pointer
 *   divide      divides by zero (under the sanitizers UBSan reports it first)
 *   abort       calls abort() (as a failed assert does)
 *   recurse     recurses without end
 *   big-locals  keeps 64 KiB of locals in a task whose stack is 4 KiB
 * Anything else (or nothing): logs a line and ends.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "ev3api.h"
#include "app.h"

#define BIG_LOCALS (64 * 1024)

static volatile unsigned long spins;
/* NULL; under the sanitizers a field 16 bytes into a NULL structure, since UBSan
 * stops a store through NULL itself before it faults */
#if defined(__SANITIZE_ADDRESS__)
static volatile uintptr_t nowhere_address = 16;
#define NOWHERE ((int *)nowhere_address)
#else
static int *volatile nowhere;
#define NOWHERE nowhere
#endif
static volatile int zero;
static volatile int never = -1;   /* a depth recursion never reaches (the compiler cannot know) */

/* Calls itself with a frame of its own each time; the addition after the
 * call keeps it from becoming a loop. */
static __attribute__((noinline)) int recurse(int depth)
{
	volatile char frame[256];

	if (depth == never)
		return 0;
	frame[depth & 255] = (char)depth;
	return recurse(depth + 1) + frame[depth & 255];
}

/* Fills 64 KiB of locals and sleeps with them in use. */
static __attribute__((noinline)) void big_locals(void)
{
	volatile char buf[BIG_LOCALS];

	for (size_t i = 0; i < sizeof(buf); i += 512)
		buf[i] = (char)i;
	tslp_tsk(10);
	syslog(LOG_NOTICE, "misbehave: big locals %d", buf[512]);
}

/* Spins for ever in code no basic-block count reaches (as a loop inside a
 * library the app calls): nothing charges CPU time, so time stands still. */
static __attribute__((noinline, no_sanitize_coverage)) void spin_unseen(void)
{
	for (;;)
		spins++;
}

void main_task(intptr_t exinf)
{
	const char *what = getenv("EV3LX_MISBEHAVE");

	(void)exinf;
	tslp_tsk(100);
	if (what == NULL)
		what = "";
	if (strcmp(what, "stall") == 0) {
		spin_unseen();
	} else if (strcmp(what, "busy") == 0) {
		for (;;)
			spins++;
	} else if (strcmp(what, "null") == 0) {
		*NOWHERE = 1;
	} else if (strcmp(what, "divide") == 0) {
		syslog(LOG_NOTICE, "misbehave: %d", 100 / zero);
	} else if (strcmp(what, "abort") == 0) {
		abort();
	} else if (strcmp(what, "recurse") == 0) {
		syslog(LOG_NOTICE, "misbehave: %d", recurse(0));
	} else if (strcmp(what, "big-locals") == 0) {
		big_locals();
	}
	syslog(LOG_NOTICE, "misbehave: done");
}
