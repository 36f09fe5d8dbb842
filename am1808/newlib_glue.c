/*
 * newlib_glue.c — what newlib's C library asks of the platform in this image.
 *
 * linux_compat formats with vsnprintf into fixed buffers, which never grow,
 * but newlib's string printf is linked with its buffer-growing path and so
 * refers to the heap.  ev3lx allocates only from linux_compat's kmalloc pool:
 * the C heap is empty, and a request for it fails cleanly.
 *
 * The image has no file descriptors either: the only stdio streams are the
 * API's serial streams (fopencookie, which call their own functions), but
 * newlib's stdio refers to the descriptor calls for every other stream, so
 * each is here and fails with EBADF.
 */
#include <errno.h>
#include <stddef.h>
#include <sys/stat.h>
#include <sys/types.h>

void *_sbrk(ptrdiff_t increment);

/* No C heap: every request fails with ENOMEM. */
void *_sbrk(ptrdiff_t increment)
{
	(void)increment;
	errno = ENOMEM;
	return (void *)-1;
}

int _write(int fd, const void *buf, size_t len);
int _read(int fd, void *buf, size_t len);
int _close(int fd);
int _fstat(int fd, struct stat *st);
int _isatty(int fd);
off_t _lseek(int fd, off_t offset, int whence);

/* No descriptor exists: every descriptor call fails with EBADF. */
static int no_descriptor(int fd)
{
	(void)fd;
	errno = EBADF;
	return -1;
}

int _write(int fd, const void *buf, size_t len)
{
	(void)buf; (void)len;
	return no_descriptor(fd);
}

int _read(int fd, void *buf, size_t len)
{
	(void)buf; (void)len;
	return no_descriptor(fd);
}

int _close(int fd)
{
	return no_descriptor(fd);
}

int _fstat(int fd, struct stat *st)
{
	(void)st;
	return no_descriptor(fd);
}

/* Not a terminal (0, errno EBADF), as newlib's own stub answers. */
int _isatty(int fd)
{
	(void)no_descriptor(fd);
	return 0;
}

off_t _lseek(int fd, off_t offset, int whence)
{
	(void)offset; (void)whence;
	return no_descriptor(fd);
}

int _getpid(void);
int _kill(int pid, int sig);
void _exit(int status);

/* One program, no processes: newlib's abort asks for its own process ID and signals it. */
int _getpid(void)
{
	return 1;
}

/* No signal can be delivered: abort then ends in _exit. */
int _kill(int pid, int sig)
{
	(void)pid; (void)sig;
	errno = EINVAL;
	return -1;
}

/* The program cannot end: the caller stops here, where a debugger finds it. */
void _exit(int status)
{
	(void)status;
	for (;;)
		;
}
