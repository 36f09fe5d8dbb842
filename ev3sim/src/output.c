/*
 * output.c — ev3sim's output files and standard output (output.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "ev3sim/cli.h"
#include "ev3sim/output.h"

const char *ev3sim_output_error(int err)
{
	/* O_NONBLOCK's answer for a FIFO without a reader (POSIX open()) */
	return err == ENXIO ? "a FIFO no process is reading" : strerror(err);
}

/* Opens path for writing without blocking: the descriptor, or -1 with errno set. */
static int open_nonblocking(const char *path)
{
	int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_NONBLOCK | O_CLOEXEC, 0666);
	int flags;

	if (fd < 0)
		return -1;
	/* the writes themselves wait for a slow reader as any file's do */
	flags = fcntl(fd, F_GETFL);
	if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0) {
		int err = errno;

		close(fd);
		errno = err;
		return -1;
	}
	return fd;
}

FILE *ev3sim_fopen_output(const char *path)
{
	int fd, err;
	FILE *f;

	if (path == NULL || *path == '\0') {
		errno = ENOENT;
		return NULL;
	}
	if ((fd = open_nonblocking(path)) < 0)
		return NULL;
	if ((f = fdopen(fd, "w")) == NULL) {
		err = errno;
		close(fd);
		errno = err;
	}
	return f;
}

FILE *ev3sim_open_output(const char *cmd, const char *path)
{
	FILE *f = ev3sim_fopen_output(path);

	if (f == NULL)
		fprintf(stderr, "ev3sim %s: cannot write %s: %s\n", cmd, path ? path : "(null)",
			path && *path ? ev3sim_output_error(errno) : "empty path");
	return f;
}

bool ev3sim_close_output(const char *cmd, FILE *f, const char *path)
{
	bool ok = !ferror(f);       /* a write that failed before this flush */
	int err = 0;

	if (fflush(f) != 0) {
		ok = false;
		err = errno;
	}
	if (fclose(f) != 0) {
		ok = false;
		if (err == 0)
			err = errno;
	}
	if (!ok)
		fprintf(stderr, "ev3sim %s: cannot write %s completely%s%s\n", cmd, path,
			err ? ": " : "", err ? strerror(err) : "");
	return ok;
}

bool ev3sim_can_create(const char *cmd, const char *path)
{
	struct stat st;
	int fd;

	if (path == NULL || *path == '\0') {
		fprintf(stderr, "ev3sim %s: cannot write %s: empty path\n", cmd, path ? path : "(null)");
		return false;
	}
	if (stat(path, &st) == 0 && S_ISFIFO(st.st_mode)) {
		fprintf(stderr, "ev3sim %s: cannot write %s: a FIFO (this output is written to a "
			"regular file by name; only the outputs written as the run goes stream)\n", cmd, path);
		return false;
	}
	fd = open_nonblocking(path);
	if (fd < 0 || close(fd) != 0) {
		fprintf(stderr, "ev3sim %s: cannot write %s: %s\n", cmd, path, ev3sim_output_error(errno));
		return false;
	}
	return true;
}

int ev3sim_finish_stdout(const char *cmd, int status)
{
	bool lost = ferror(stdout) != 0;
	int err = 0;

	if (fflush(stdout) != 0) {
		lost = true;
		err = errno;
	}
	if (!lost)
		return status;
	clearerr(stdout);   /* reported once, by whoever looks first */
	fprintf(stderr, "ev3sim%s%s: cannot write the standard output%s%s\n", cmd ? " " : "", cmd ? cmd : "",
		err ? ": " : "", err ? strerror(err) : "");
	return EV3SIM_EXIT_FAIL;
}
