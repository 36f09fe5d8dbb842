/*
 * stderr_capture.h — what a negative test's call writes to stderr, kept off
 * the terminal and checked: the error message is part of the contract (it
 * must name what is wrong and where), and a suite run should show only
 * messages nobody expected.
 *
 *   struct stderr_capture cap;
 *   stderr_capture_begin(&cap);
 *   is_int(run_main(argc, argv), 2, "a bad option: status 2");
 *   ok(strstr(stderr_capture_end(&cap), "--robot") != NULL, "the message names it");
 *
 * File descriptor 2 goes to a temporary file between begin and end (so
 * writes by the C library and by write(2) alike are caught); end restores it
 * and returns the text, at most STDERR_CAPTURE_MAX - 1 bytes.  The including
 * test defines _POSIX_C_SOURCE 200809L before its first include (dup, fileno).
 */
#ifndef EV3LX_TESTS_STDERR_CAPTURE_H
#define EV3LX_TESTS_STDERR_CAPTURE_H

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#define STDERR_CAPTURE_MAX 4096

struct stderr_capture {
	int saved_fd;             /* the real stderr, -1 if the capture could not start */
	FILE *file;               /* where fd 2 writes meanwhile */
	char text[STDERR_CAPTURE_MAX];
};

/* Sends fd 2 to a temporary file until stderr_capture_end; exits the test on failure. */
static inline void stderr_capture_begin(struct stderr_capture *cap)
{
	fflush(stderr);
	cap->text[0] = '\0';
	cap->file = tmpfile();
	cap->saved_fd = dup(2);
	if (cap->file == NULL || cap->saved_fd < 0 || dup2(fileno(cap->file), 2) < 0) {
		perror("stderr_capture_begin");
		exit(1);
	}
}

/* Restores fd 2; returns what was written to it since stderr_capture_begin. */
static inline const char *stderr_capture_end(struct stderr_capture *cap)
{
	size_t n;

	fflush(stderr);
	if (dup2(cap->saved_fd, 2) < 0) {
		perror("stderr_capture_end");
		exit(1);
	}
	close(cap->saved_fd);
	rewind(cap->file);
	n = fread(cap->text, 1, sizeof(cap->text) - 1, cap->file);
	cap->text[n] = '\0';
	fclose(cap->file);
	return cap->text;
}

#endif /* EV3LX_TESTS_STDERR_CAPTURE_H */
