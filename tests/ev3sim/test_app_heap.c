/*
 * test_app_heap.c — an app's malloc is the app heap in its domain, as on
 * EV3RT (1 MiB, the heap EV3RT gives TDOM_APP): tests/ev3sim/apps/heap reads
 * sensors into malloc'd memory (E_MACV when malloc was the host's), grows
 * with realloc, frees what the C library allocated, and finds the heap full
 * at the same size twice (nothing leaks, freed blocks merge).
 */
#include "ev3sim_test.h"
#include "ev3sim/run.h"

extern const struct rtos_cfg ev3rt_app_cfg;

static struct et_run run;

static int heap_main(int argc, char **argv)
{
	return ev3sim_run_main(argc, argv, "heap", &ev3rt_app_cfg);
}

int main(void)
{
	static const char *const args[] = { "--seconds", "3", "--in1", "color", NULL };
	unsigned r = 0, g = 0, b = 0, first = 0, second = 0;
	const char *line;
	bool ran = et_run_main(&run, args, heap_main, NULL);

	ok(ran && run.status == 0, "the heap app runs (status %d)", run.status);
	if (run.status != 0)
		tap_diag("stderr:\n%s", run.err);
	ok(strstr(run.out, "heap: calloc'd counts 0 0") != NULL, "calloc zeroes");
	line = strstr(run.out, "heap: rgb into malloc'd memory ");
	if (line == NULL || sscanf(line, "heap: rgb into malloc'd memory %u %u %u", &r, &g, &b) != 3)
		r = g = b = 0;
	ok(r + g + b > 0, "a colour read into malloc'd memory delivers (%u %u %u)", r, g, b);
	ok(strstr(run.out, "heap: lcd from malloc'd text 0") != NULL, "the LCD draws malloc'd text (E_OK)");
	ok(strstr(run.out, "heap: realloc kept \"heap\" and grew to 3999") != NULL, "realloc keeps the contents");
	ok(strstr(run.out, "heap: strdup a copy the C library made") != NULL, "the C library's memory is freed by free");
	ok(strstr(run.out, "heap: posix_memalign 16 0, 64 1") != NULL,
	   "posix_memalign serves the heap's 16-byte alignment and refuses 64 (ENOMEM)");
	line = strstr(run.out, "heap: full after ");
	ok(line != NULL && sscanf(line, "heap: full after %u KiB, again after %u KiB", &first, &second) == 2,
	   "it filled the heap twice");
	in_range((long)first, 896, 1024, "the heap holds almost 1 MiB in 64 KiB pieces (%u KiB)", first);
	is_int(second, first, "and as much again after freeing it all");
	ok(strstr(run.out, "heap: done") != NULL, "the app ran to its end");
	ok(strstr(run.out, "E_MACV") == NULL, "no call was refused for the app's own memory");
	return tap_done();
}
