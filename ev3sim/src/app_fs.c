/*
 * app_fs.c — an EV3RT app's C library file calls on the simulated SD card.
 *
 * On the brick an app's fopen("/ev3rt/log.txt", "w") is newlib's, over
 * FatFs on the SD card: "/" is the card's root, and FatFs (built without
 * relative paths, FF_FS_RPATH 0) takes a relative path from the root too.
 * The app build (mk/ev3rt_app.mk) renames the app's references to these
 * calls (mk/ev3rt_app_fs.syms) to the ev3rt_fs_* functions below, which map
 * the path into the card's host directory (ev3sim run --sd, brick_io.h) and
 * make the host's call there: the app writes its card, never the host's
 * current directory or root.  Without a card every path fails with ENODEV;
 * a ".." above the card's root or a symbolic link leading out of it fails
 * with EACCES.  Host only.
 */
#define _GNU_SOURCE     /* the *64 calls and O_TMPFILE of the large-file interface */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>
#include "ev3sim/brick_io.h"
#include "driver_interface_filesys.h"

/* The app's functions under their renamed names (nothing but the renamed app calls them). */
FILE *ev3rt_fs_fopen(const char *path, const char *mode);
FILE *ev3rt_fs_fopen64(const char *path, const char *mode);
FILE *ev3rt_fs_freopen(const char *path, const char *mode, FILE *stream);
FILE *ev3rt_fs_freopen64(const char *path, const char *mode, FILE *stream);
int ev3rt_fs_open(const char *path, int flags, ...);
int ev3rt_fs_open64(const char *path, int flags, ...);
int ev3rt_fs_open_2(const char *path, int flags);
int ev3rt_fs_open64_2(const char *path, int flags);
int ev3rt_fs_creat(const char *path, mode_t mode);
int ev3rt_fs_creat64(const char *path, mode_t mode);
int ev3rt_fs_remove(const char *path);
int ev3rt_fs_unlink(const char *path);
int ev3rt_fs_rmdir(const char *path);
int ev3rt_fs_mkdir(const char *path, mode_t mode);
int ev3rt_fs_rename(const char *from, const char *to);
int ev3rt_fs_stat(const char *path, struct stat *st);
int ev3rt_fs_stat64(const char *path, struct stat64 *st);
int ev3rt_fs_lstat(const char *path, struct stat *st);
int ev3rt_fs_lstat64(const char *path, struct stat64 *st);
int ev3rt_fs_access(const char *path, int how);
DIR *ev3rt_fs_opendir(const char *path);
struct dirent *ev3rt_fs_readdir(DIR *dir);

/* The host path of path for use (malloc'd), or NULL with errno set as FatFs's errors map to it. */
static char *host_path(const char *path, enum brick_io_card_use use)
{
	char *host = NULL;

	switch (brick_io_card_path(path, use, &host)) {
	case E_OK:
		return host;
	case E_OBJ:
		errno = ENODEV;         /* no card in the slot */
		break;
	case E_NOEXS:
		errno = ENOENT;
		break;
	case E_NOMEM:
		errno = ENOMEM;
		break;
	default:
		errno = path == NULL ? EFAULT : path[0] == '\0' ? ENOENT : EACCES;
		break;
	}
	return NULL;
}

/* Frees host keeping errno (the host call's). */
static void done(char *host)
{
	int err = errno;

	free(host);
	errno = err;
}

/* A mode that may create or truncate: "w", "a" and their "+" forms. */
static enum brick_io_card_use fopen_use(const char *mode)
{
	return mode && (mode[0] == 'w' || mode[0] == 'a') ? BRICK_IO_CARD_CREATE : BRICK_IO_CARD_EXISTING;
}

FILE *ev3rt_fs_fopen(const char *path, const char *mode)
{
	char *host = host_path(path, fopen_use(mode));
	FILE *f = host ? fopen(host, mode) : NULL;

	done(host);
	return f;
}

FILE *ev3rt_fs_fopen64(const char *path, const char *mode)
{
	char *host = host_path(path, fopen_use(mode));
	FILE *f = host ? fopen64(host, mode) : NULL;

	done(host);
	return f;
}

FILE *ev3rt_fs_freopen(const char *path, const char *mode, FILE *stream)
{
	char *host;
	FILE *f;

	if (path == NULL)           /* a new mode for the same file: no path to map */
		return freopen(NULL, mode, stream);
	host = host_path(path, fopen_use(mode));
	f = host ? freopen(host, mode, stream) : NULL;
	done(host);
	return f;
}

FILE *ev3rt_fs_freopen64(const char *path, const char *mode, FILE *stream)
{
	char *host;
	FILE *f;

	if (path == NULL)
		return freopen64(NULL, mode, stream);
	host = host_path(path, fopen_use(mode));
	f = host ? freopen64(host, mode, stream) : NULL;
	done(host);
	return f;
}

/* The mode argument of open(), there only with O_CREAT or O_TMPFILE. */
#define OPEN_MODE(flags, mode)                                          \
	do {                                                            \
		va_list ap;                                             \
									\
		va_start(ap, flags);                                    \
		mode = ((flags) & (O_CREAT | O_TMPFILE)) ? (mode_t)va_arg(ap, unsigned) : 0; \
		va_end(ap);                                             \
	} while (0)

/* A file's descriptor moved above EV3RT's serial file numbers
 * (driver_interface_filesys.h), which the app's fdopen takes for the serial
 * ports: the card's files never get them, as on the brick. */
static int above_serial_filenos(int fd, int flags)
{
	int moved;

	if (fd < 0 || fd > SIO_USB_CDC_FILENO)
		return fd;
	moved = fcntl(fd, (flags & O_CLOEXEC) ? F_DUPFD_CLOEXEC : F_DUPFD, SIO_USB_CDC_FILENO + 1);
	close(fd);
	return moved;
}

int ev3rt_fs_open(const char *path, int flags, ...)
{
	char *host;
	mode_t mode;
	int fd;

	OPEN_MODE(flags, mode);
	host = host_path(path, (flags & O_CREAT) ? BRICK_IO_CARD_CREATE : BRICK_IO_CARD_EXISTING);
	fd = host ? open(host, flags, mode) : -1;
	done(host);
	return above_serial_filenos(fd, flags);
}

int ev3rt_fs_open64(const char *path, int flags, ...)
{
	char *host;
	mode_t mode;
	int fd;

	OPEN_MODE(flags, mode);
	host = host_path(path, (flags & O_CREAT) ? BRICK_IO_CARD_CREATE : BRICK_IO_CARD_EXISTING);
	fd = host ? open64(host, flags, mode) : -1;
	done(host);
	return above_serial_filenos(fd, flags);
}

/* _FORTIFY_SOURCE's open() without O_CREAT */
int ev3rt_fs_open_2(const char *path, int flags)
{
	return ev3rt_fs_open(path, flags);
}

int ev3rt_fs_open64_2(const char *path, int flags)
{
	return ev3rt_fs_open64(path, flags);
}

int ev3rt_fs_creat(const char *path, mode_t mode)
{
	return ev3rt_fs_open(path, O_WRONLY | O_CREAT | O_TRUNC, mode);
}

int ev3rt_fs_creat64(const char *path, mode_t mode)
{
	return ev3rt_fs_open64(path, O_WRONLY | O_CREAT | O_TRUNC, mode);
}

int ev3rt_fs_remove(const char *path)
{
	char *host = host_path(path, BRICK_IO_CARD_ENTRY);
	int r = host ? remove(host) : -1;

	done(host);
	return r;
}

int ev3rt_fs_unlink(const char *path)
{
	char *host = host_path(path, BRICK_IO_CARD_ENTRY);
	int r = host ? unlink(host) : -1;

	done(host);
	return r;
}

int ev3rt_fs_rmdir(const char *path)
{
	char *host = host_path(path, BRICK_IO_CARD_ENTRY);
	int r = host ? rmdir(host) : -1;

	done(host);
	return r;
}

int ev3rt_fs_mkdir(const char *path, mode_t mode)
{
	char *host = host_path(path, BRICK_IO_CARD_ENTRY);
	int r = host ? mkdir(host, mode) : -1;

	done(host);
	return r;
}

int ev3rt_fs_rename(const char *from, const char *to)
{
	char *host_from = host_path(from, BRICK_IO_CARD_ENTRY);
	char *host_to = host_from ? host_path(to, BRICK_IO_CARD_ENTRY) : NULL;
	int r = host_to ? rename(host_from, host_to) : -1;

	done(host_to);
	done(host_from);
	return r;
}

int ev3rt_fs_stat(const char *path, struct stat *st)
{
	char *host = host_path(path, BRICK_IO_CARD_EXISTING);
	int r = host ? stat(host, st) : -1;

	done(host);
	return r;
}

int ev3rt_fs_stat64(const char *path, struct stat64 *st)
{
	char *host = host_path(path, BRICK_IO_CARD_EXISTING);
	int r = host ? stat64(host, st) : -1;

	done(host);
	return r;
}

/* The card has no symbolic links of its own; one in its host directory is shown as such. */
int ev3rt_fs_lstat(const char *path, struct stat *st)
{
	char *host = host_path(path, BRICK_IO_CARD_ENTRY);
	int r = host ? lstat(host, st) : -1;

	done(host);
	return r;
}

int ev3rt_fs_lstat64(const char *path, struct stat64 *st)
{
	char *host = host_path(path, BRICK_IO_CARD_ENTRY);
	int r = host ? lstat64(host, st) : -1;

	done(host);
	return r;
}

int ev3rt_fs_access(const char *path, int how)
{
	char *host = host_path(path, BRICK_IO_CARD_EXISTING);
	int r = host ? access(host, how) : -1;

	done(host);
	return r;
}

DIR *ev3rt_fs_opendir(const char *path)
{
	char *host = host_path(path, BRICK_IO_CARD_EXISTING);
	DIR *d = host ? opendir(host) : NULL;

	done(host);
	return d;
}

/*
 * readdir for an app built without 64-bit file offsets (a 32-bit host: the
 * ARMv5 tests under qemu-arm): the host's directories give 64-bit entry
 * offsets, which the C library's 32-bit readdir refuses with EOVERFLOW.  The
 * entry is read with readdir64 and handed over in a struct dirent of the
 * app's size; like readdir's, it is valid until the next call.
 */
struct dirent *ev3rt_fs_readdir(DIR *dir)
{
	static struct dirent entry;
	struct dirent64 *e;

	/* cppcheck-suppress readdirCalled ; one simulation thread, and readdir64_r is deprecated in glibc */
	if ((e = readdir64(dir)) == NULL)
		return NULL;
	entry.d_ino = (ino_t)e->d_ino;
	entry.d_off = (off_t)e->d_off;
	entry.d_reclen = (unsigned short)sizeof(entry);
	entry.d_type = e->d_type;
	snprintf(entry.d_name, sizeof(entry.d_name), "%s", e->d_name);
	return &entry;
}
