/*
 * app_build.h — how `ev3sim run APP_DIR` builds an app directory: a build
 * directory of its own keyed by the directory's real path, the app reached
 * through a link in it (so that make never sees the path's characters), a
 * lock so that concurrent runs of one app build it once, and make.
 */
#ifndef EV3SIM_APP_BUILD_H
#define EV3SIM_APP_BUILD_H

#include <stdbool.h>
#include <stddef.h>

/* The app's name (the summary's app=, make's): the real path's last
 * component with every byte outside [A-Za-z0-9_.-] made '_', at most 64
 * bytes; "app" for an empty one. */
void ev3sim_app_name(const char *app_realpath, char *name, size_t len);

/* The app's build directory name under build/CONFIG/ev3rt/:
 * run_NAME-HHHHHHHHHHHHHHHH, the hash (64-bit FNV-1a) of the whole real path,
 * so that two directories of one name never share a build. */
void ev3sim_app_key(const char *app_realpath, char *key, size_t len);

/* Builds the app whose real path is app in the ev3lx tree at root for the
 * configuration config (host or host32: whose library it links), with the
 * EV3RT SDK libraries of lib_dir (a real path, or NULL), for the kernel
 * profile kernel ("hrp2", "hrp3", or NULL / "auto": told by app.cfg), with
 * debug at -O0 (for gdb: `ev3sim run --debug`, under KEY-debug, so that no
 * -O2 object is reused, nor the other way round): creates
 * ROOT/build/CONFIG/ev3rt/KEY/, locks KEY/.lock (flock, waiting for a
 * concurrent build of the same app), links KEY/app to the app directory and
 * KEY/libdir to lib_dir, and runs make with those links.  On success returns a read-only descriptor of the built runner
 * (opened before the lock is released, so a later rebuild cannot change what
 * runs) and its path in runner; -1 with the reason in err otherwise. */
int ev3sim_app_build(const char *root, const char *config, const char *app, const char *lib_dir, const char *kernel,
		     bool debug, char *runner, size_t runner_len, char *err, size_t err_len);

#endif /* EV3SIM_APP_BUILD_H */
