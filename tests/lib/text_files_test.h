/*
 * text_files_test.h — small text files and scratch directories for tests
 * that hand files to the program under test (an SD card directory, a serial
 * port file) and read what it wrote.  The including test defines
 * _XOPEN_SOURCE 700 before its first include (nftw).
 */
#ifndef EV3LX_TESTS_TEXT_FILES_TEST_H
#define EV3LX_TESTS_TEXT_FILES_TEST_H

#include <ftw.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "tap.h"

/* Makes a fresh directory from template (ending in XXXXXX, replaced in
 * place): every test that writes files gets its own, so that the same test
 * in several configurations can run at once.  Bails out if it cannot. */
static inline void tf_make_scratch_dir(char *template)
{
	if (mkdtemp(template) == NULL)
		tap_bail_out("mkdtemp");
}

/* Writes text to path (created or truncated); false on any error. */
static inline bool tf_write_text(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	return f != NULL && fputs(text, f) >= 0 && fclose(f) == 0;
}

/* Writes len bytes to dir/rel (created or truncated); bails out on any error. */
static inline void tf_put_file(const char *dir, const char *rel, const void *bytes, size_t len)
{
	char path[512];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, rel);
	f = fopen(path, "wb");
	if (f == NULL || fwrite(bytes, 1, len, f) != len || fclose(f) != 0)
		tap_bail_out(path);
}

/* Reads path into buf (NUL-terminated, at most len - 1 bytes); the bytes read, 0 if none. */
static inline size_t tf_read_text(const char *path, char *buf, size_t len)
{
	FILE *f = fopen(path, "r");
	size_t n = 0;

	if (f != NULL) {
		n = fread(buf, 1, len - 1, f);
		fclose(f);
	}
	buf[n] = '\0';
	return n;
}

static inline int tf_remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
	(void)st; (void)flag; (void)ftw;
	return remove(path);
}

/* Removes dir and everything below it (symbolic links themselves, not what they point to). */
static inline void tf_remove_tree(const char *dir)
{
	nftw(dir, tf_remove_entry, 8, FTW_DEPTH | FTW_PHYS);
}

#endif /* EV3LX_TESTS_TEXT_FILES_TEST_H */
