/*
 * fuzz_replay.h — a fuzz harness as a TAP test: feeds every file of the
 * harness's committed corpus (tests/fuzz/corpus/NAME/, in name order) to
 * LLVMFuzzerTestOneInput, as `make fuzz` found and minimised them.  A crash,
 * a sanitizer report or a bug report of the stack fails the test; the
 * ASan+UBSan configuration is where this matters most.  Tests run in
 * build/<config>/, so the corpus is two directories up (or, run from the
 * repository's root, right there).
 *
 * Include it last in a harness, after defining FUZZ_NAME and, if the harness
 * keeps a brick, FUZZ_FINISH (called once after the corpus); the harness
 * * defines _POSIX_C_SOURCE 200809L (opendir, strdup) and _FILE_OFFSET_BITS 64
 * (readdir under qemu-arm of an ext4 directory) before its first include.
 */
#ifndef EV3LX_TESTS_FUZZ_REPLAY_H
#define EV3LX_TESTS_FUZZ_REPLAY_H

#ifndef EV3LX_LIBFUZZER
#include <dirent.h>
#include <string.h>
#include "tap.h"

#define FZ_MAX_INPUT  (64 * 1024)
#define FZ_MAX_FILES  4096

static int fz_name_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

int main(void)
{
	static const char *const roots[] = { "../../tests/fuzz/corpus/", "tests/fuzz/corpus/" };
	static uint8_t buf[FZ_MAX_INPUT];
	static char *names[FZ_MAX_FILES];
	char dir[512], path[1024];
	unsigned n = 0, ran = 0;
	struct dirent *e;
	DIR *d = NULL;

	tap_plan(2);
	for (unsigned i = 0; i < sizeof(roots) / sizeof(roots[0]) && d == NULL; i++) {
		snprintf(dir, sizeof(dir), "%s%s", roots[i], FUZZ_NAME);
		d = opendir(dir);
	}
	if (d == NULL) {
		tap_diag("no corpus directory for %s", FUZZ_NAME);
		ok(false, "corpus of %s found", FUZZ_NAME);
		return tap_done();
	}
	/* cppcheck-suppress readdirCalled ; one thread reads one directory stream: readdir is safe */
	while ((e = readdir(d)) != NULL && n < FZ_MAX_FILES)
		if (e->d_name[0] != '.')
			names[n++] = strdup(e->d_name);
	closedir(d);
	qsort(names, n, sizeof(names[0]), fz_name_cmp);
	ok(n > 0, "corpus of %s: %u inputs", FUZZ_NAME, n);
	for (unsigned i = 0; i < n; i++) {
		FILE *f;
		size_t size;

		snprintf(path, sizeof(path), "%s/%s", dir, names[i]);
		f = fopen(path, "rb");
		if (f == NULL)
			continue;
		size = fread(buf, 1, sizeof(buf), f);
		fclose(f);
		LLVMFuzzerTestOneInput(buf, size);
		ran++;
		free(names[i]);
	}
#ifdef FUZZ_FINISH
	FUZZ_FINISH();
#endif
	is_int(ran, n, "every input replayed without a crash or a bug report");
	return tap_done();
}
#endif /* EV3LX_LIBFUZZER */

#endif /* EV3LX_TESTS_FUZZ_REPLAY_H */
