/*
 * app_build.c — building an app directory for `ev3sim run` (app_build.h).
 *
 * make expands '$' in any variable's value and splits words at spaces, so
 * the app directory's own path never reaches it: make is given the link
 * ROOT/build/CONFIG/ev3rt/KEY/app, whose characters are all safe (and
 * KEY/libdir for --lib-dir), and the app's sanitised name.  KEY hashes the real path: two directories called
 * "robot" build apart.  The lock serialises builds of one app only.
 */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE          /* flock */
#include "ev3sim/app_build.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define APP_NAME_MAX 64

static bool is_safe_name_byte(char c)
{
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
	       c == '.' || c == '-';
}

void ev3sim_app_name(const char *app_realpath, char *name, size_t len)
{
	const char *slash = strrchr(app_realpath, '/');
	const char *base = slash != NULL ? slash + 1 : app_realpath;
	size_t n = 0;

	if (len == 0)
		return;
	for (; n < APP_NAME_MAX && n + 1 < len && base[n] != '\0'; n++)
		name[n] = is_safe_name_byte(base[n]) ? base[n] : '_';
	name[n] = '\0';
	if (n == 0)
		snprintf(name, len, "app");
}

void ev3sim_app_key(const char *app_realpath, char *key, size_t len)
{
	uint64_t hash = 0xcbf29ce484222325ULL;    /* FNV-1a, 64 bits */
	char name[APP_NAME_MAX + 1];

	for (const char *c = app_realpath; *c != '\0'; c++)
		hash = (hash ^ (unsigned char)*c) * 0x100000001b3ULL;
	ev3sim_app_name(app_realpath, name, sizeof(name));
	snprintf(key, len, "run_%s-%016llx", name, (unsigned long long)hash);
}

/* mkdir -p of path (absolute); 0 or -1 with errno. */
static int make_dirs(const char *path)
{
	char buf[PATH_MAX];
	size_t n = strlen(path);

	if (n >= sizeof(buf)) {
		errno = ENAMETOOLONG;
		return -1;
	}
	memcpy(buf, path, n + 1);
	for (char *p = buf + 1;; p++) {
		if (*p == '/' || *p == '\0') {
			char c = *p;

			*p = '\0';
			if (mkdir(buf, 0777) != 0 && errno != EEXIST)
				return -1;
			*p = c;
			if (c == '\0')
				return 0;
		}
	}
}

/* dir/name: a link to target (made, or checked: a hash collision or a stale
 * link is replaced); 0 or -1 with errno. */
static int link_dir(const char *dir, const char *name, const char *target_dir)
{
	char link[PATH_MAX], target[PATH_MAX], tmp[PATH_MAX];
	ssize_t n;

	if (snprintf(link, sizeof(link), "%s/%s", dir, name) >= (int)sizeof(link) ||
	    snprintf(tmp, sizeof(tmp), "%s/%s.%ld", dir, name, (long)getpid()) >= (int)sizeof(tmp)) {
		errno = ENAMETOOLONG;
		return -1;
	}
	n = readlink(link, target, sizeof(target) - 1);
	if (n >= 0) {
		target[n] = '\0';
		if (strcmp(target, target_dir) == 0)
			return 0;
	}
	/* a new link takes the old one's place in one step */
	(void)unlink(tmp);
	if (symlink(target_dir, tmp) != 0)
		return -1;
	if (rename(tmp, link) != 0) {
		int e = errno;

		(void)unlink(tmp);
		errno = e;
		return -1;
	}
	return 0;
}

/* Runs argv (argv[0] found along PATH) to its end: its exit status, or -1
 * with the reason in err if it could not be run or did not exit. */
static int run_program(char *const argv[], char *err, size_t err_len)
{
	int wstatus, pipefd[2], child_errno = 0;
	pid_t pid;

	/* the child reports a failed exec through a close-on-exec pipe */
	if (pipe(pipefd) != 0 || fcntl(pipefd[0], F_SETFD, FD_CLOEXEC) != 0 ||
	    fcntl(pipefd[1], F_SETFD, FD_CLOEXEC) != 0) {
		snprintf(err, err_len, "cannot run %s: %s", argv[0], strerror(errno));
		return -1;
	}
	pid = fork();
	if (pid < 0) {
		snprintf(err, err_len, "cannot run %s: %s", argv[0], strerror(errno));
		close(pipefd[0]);
		close(pipefd[1]);
		return -1;
	}
	if (pid == 0) {
		int e;

		close(pipefd[0]);
		execvp(argv[0], argv);
		e = errno;
		(void)!write(pipefd[1], &e, sizeof(e));
		_exit(127);
	}
	close(pipefd[1]);
	if (read(pipefd[0], &child_errno, sizeof(child_errno)) != (ssize_t)sizeof(child_errno))
		child_errno = 0;
	close(pipefd[0]);
	if (waitpid(pid, &wstatus, 0) < 0) {
		snprintf(err, err_len, "waiting for %s: %s", argv[0], strerror(errno));
		return -1;
	}
	if (child_errno != 0) {
		snprintf(err, err_len, "cannot execute %s: %s", argv[0], strerror(child_errno));
		return -1;
	}
	if (!WIFEXITED(wstatus)) {
		snprintf(err, err_len, "%s was killed by signal %d", argv[0], WTERMSIG(wstatus));
		return -1;
	}
	return WEXITSTATUS(wstatus);
}

int ev3sim_app_build(const char *root, const char *config, const char *app, const char *lib_dir, const char *kernel,
		     bool debug, char *runner, size_t runner_len, char *err, size_t err_len)
{
	char key[APP_NAME_MAX + 32], name[APP_NAME_MAX + 1], dir[PATH_MAX], lock[PATH_MAX + 8];
	char app_arg[PATH_MAX + 8], lib_arg[PATH_MAX + 24] = "EV3RT_LIB_DIR=";
	char name_arg[APP_NAME_MAX + 32], key_arg[APP_NAME_MAX + 48], config_arg[APP_NAME_MAX + 32];
	char kernel_arg[32];
	size_t key_len;
	int lock_fd, fd = -1, status;

	ev3sim_app_name(app, name, sizeof(name));
	ev3sim_app_key(app, key, sizeof(key));
	key_len = strlen(key);
	if (debug)
		snprintf(key + key_len, sizeof(key) - key_len, "-debug");
	if (snprintf(config_arg, sizeof(config_arg), "EV3RT_RUN_CONFIG=%s", config) >= (int)sizeof(config_arg) ||
	    snprintf(dir, sizeof(dir), "%s/build/%s/ev3rt/%s", root, config, key) >= (int)sizeof(dir) ||
	    snprintf(runner, runner_len, "%s/%s", dir, key) >= (int)runner_len) {
		snprintf(err, err_len, "the path of %s's build directory is too long", app);
		return -1;
	}
	snprintf(lock, sizeof(lock), "%s/.lock", dir);
	snprintf(app_arg, sizeof(app_arg), "APP=%s/app", dir);
	if (lib_dir != NULL)
		snprintf(lib_arg, sizeof(lib_arg), "EV3RT_LIB_DIR=%s/libdir", dir);
	snprintf(name_arg, sizeof(name_arg), "EV3RT_APP_NAME=%s", name);
	snprintf(key_arg, sizeof(key_arg), "EV3RT_RUN_KEY=%s", key);
	snprintf(kernel_arg, sizeof(kernel_arg), "EV3RT_KERNEL=%s", kernel != NULL ? kernel : "auto");
	if (make_dirs(dir) != 0) {
		snprintf(err, err_len, "cannot create %s: %s", dir, strerror(errno));
		return -1;
	}
	if ((lock_fd = open(lock, O_RDWR | O_CREAT | O_CLOEXEC, 0666)) < 0) {
		snprintf(err, err_len, "cannot open %s: %s", lock, strerror(errno));
		return -1;
	}
	while ((status = flock(lock_fd, LOCK_EX)) != 0 && errno == EINTR)
		;
	if (status != 0) {
		snprintf(err, err_len, "cannot lock %s: %s", lock, strerror(errno));
		close(lock_fd);
		return -1;
	}
	if (link_dir(dir, "app", app) != 0) {
		snprintf(err, err_len, "cannot link %s/app to %s: %s", dir, app, strerror(errno));
	} else if (lib_dir != NULL && link_dir(dir, "libdir", lib_dir) != 0) {
		snprintf(err, err_len, "cannot link %s/libdir to %s: %s", dir, lib_dir, strerror(errno));
	} else {
		char *make_argv[] = { "make", "-s", "--no-print-directory", "-C", (char *)root, app_arg, lib_arg,
				      name_arg, key_arg, config_arg, kernel_arg,
				      debug ? "EV3RT_DEBUG=1" : "EV3RT_DEBUG=0", "ev3rt-app", NULL };
		char why[PATH_MAX + 64] = "";

		status = run_program(make_argv, why, sizeof(why));
		if (status < 0)
			snprintf(err, err_len, "building %s failed: %s", app, why);
		else if (status != 0)
			snprintf(err, err_len, "building %s failed (make exited %d)", app, status);
		else if ((fd = open(runner, O_RDONLY | O_CLOEXEC)) < 0)
			snprintf(err, err_len, "cannot open the runner %s: %s", runner, strerror(errno));
	}
	close(lock_fd);	/* releases the lock */
	return fd;
}
