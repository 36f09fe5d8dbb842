/*
 * ev3sim_test.h — running ev3sim's command line in a child process, as a
 * user would run build/host/ev3sim, but in the test's own configuration
 * (host, host-san, arm926 under qemu): each run boots the stack once in a
 * fresh process, so runs cannot share state.  Output goes through temporary
 * files and comes back as strings.
 */
#ifndef EV3LX_TESTS_EV3SIM_TEST_H
#define EV3LX_TESTS_EV3SIM_TEST_H

#define _POSIX_C_SOURCE 200809L
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/wait.h>
#include "tap.h"
#include "ev3sim/cli.h"

#define ET_OUT_MAX 65536

struct et_run {
	int status;                 /* exit status, or -1 if the child did not exit normally */
	char out[ET_OUT_MAX];       /* stdout */
	char err[8192];             /* stderr */
};

/* Reads what a temporary file holds (truncated to len - 1). */
static inline void et_slurp(FILE *f, char *buf, size_t len)
{
	size_t n;

	rewind(f);
	n = fread(buf, 1, len - 1, f);
	buf[n] = '\0';
}

/* A hung child is killed after this long (the test then fails instead of hanging). */
#define ET_HANG_S 300

/* Runs main_fn(argc, argv) with args (NULL-terminated, without the program
 * name) in a child process, its stdout to stdout_path (NULL: captured in
 * r->out); false if the child could not be run. */
static inline bool et_run_main(struct et_run *r, const char *const *args, int (*main_fn)(int, char **),
			       const char *stdout_path)
{
	char *argv[64];
	int argc = 0, wstatus = 0;
	FILE *out = tmpfile(), *err = tmpfile();
	pid_t pid;

	memset(r, 0, sizeof(*r));
	r->status = -1;
	if (out == NULL || err == NULL)
		return false;
	argv[argc++] = (char *)"ev3sim";
	while (*args && argc < 63)
		argv[argc++] = (char *)*args++;
	argv[argc] = NULL;
	fflush(NULL);
	pid = fork();
	if (pid < 0)
		return false;
	if (pid == 0) {
		FILE *to = stdout_path ? fopen(stdout_path, "w") : out;
		int status;

		if (to == NULL)
			_exit(126);
		alarm(ET_HANG_S);
		dup2(fileno(to), STDOUT_FILENO);
		dup2(fileno(err), STDERR_FILENO);
		status = main_fn(argc, argv);
		fflush(NULL);
		_exit(status);
	}
	if (waitpid(pid, &wstatus, 0) != pid)
		return false;
	if (WIFEXITED(wstatus))
		r->status = WEXITSTATUS(wstatus);
	et_slurp(out, r->out, sizeof(r->out));
	et_slurp(err, r->err, sizeof(r->err));
	fclose(out);
	fclose(err);
	return true;
}

/* Runs `ev3sim argv...` (argv NULL-terminated, without the program name) in
 * a child process; false if the child could not be run. */
static inline bool et_run(struct et_run *r, const char *const *args)
{
	return et_run_main(r, args, ev3sim_main, NULL);
}

/* Opens FIFO path for reading without blocking, so that a writer's open
 * finds a reader; -1 if it cannot.  The FIFO then holds what is written
 * (up to the pipe's 64 KiB) until et_fifo_drain reads it. */
static inline int et_fifo_reader(const char *path)
{
	return open(path, O_RDONLY | O_NONBLOCK);
}

/* Reads what the FIFO's writer left (it has closed it) into buf, at most
 * len bytes; the number read.  Never blocks. */
static inline size_t et_fifo_drain(int fd, char *buf, size_t len)
{
	size_t n = 0;
	ssize_t got;

	while (n < len && (got = read(fd, buf + n, len - n)) > 0)
		n += (size_t)got;
	return n;
}

/* The last line of the output (the summary), without its newline. */
static inline const char *et_last_line(const struct et_run *r, char *buf, size_t len)
{
	const char *end = r->out + strlen(r->out), *start;

	while (end > r->out && end[-1] == '\n')
		end--;
	start = end;
	while (start > r->out && start[-1] != '\n')
		start--;
	snprintf(buf, len, "%.*s", (int)(end - start), start);
	return buf;
}

/* The value of key=value in a summary line, or "" if absent. */
static inline const char *et_value(const char *line, const char *key, char *buf, size_t len)
{
	size_t klen = strlen(key);
	const char *p = line;

	buf[0] = '\0';
	while ((p = strstr(p, key)) != NULL) {
		if ((p == line || p[-1] == ' ') && p[klen] == '=') {
			size_t n = strcspn(p + klen + 1, " \n");

			snprintf(buf, len, "%.*s", (int)n, p + klen + 1);
			break;
		}
		p += klen;
	}
	return buf;
}

/* A numeric summary value (NaN-free: -1e300 if absent). */
static inline double et_number(const char *line, const char *key)
{
	char buf[64];

	et_value(line, key, buf, sizeof(buf));
	return buf[0] ? strtod(buf, NULL) : -1e300;
}

/* Virtual seconds to run: the full length natively, shorter where every
 * access is checked (sanitizers, ~4x slower) and shorter still where every
 * instruction is emulated (qemu-arm, ~50x slower). */
static inline const char *et_seconds(const char *host, const char *san, const char *arm)
{
#if defined(__arm__)
	(void)host; (void)san;
	return arm;
#elif defined(__SANITIZE_ADDRESS__)
	(void)host; (void)arm;
	return san;
#else
	(void)san; (void)arm;
	return host;
#endif
}

#endif /* EV3LX_TESTS_EV3SIM_TEST_H */
