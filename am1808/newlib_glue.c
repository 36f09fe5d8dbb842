/*
 * newlib_glue.c — what newlib's C library asks of the platform in this image.
 *
 * linux_compat formats with vsnprintf into fixed buffers, which never grow,
 * but newlib's string printf is linked with its buffer-growing path and so
 * refers to the heap.  ev3lx allocates only from linux_compat's kmalloc pool:
 * the C heap is empty, and a request for it fails cleanly.
 */
#include <errno.h>
#include <stddef.h>

void *_sbrk(ptrdiff_t increment);

/* No C heap: every request fails with ENOMEM. */
void *_sbrk(ptrdiff_t increment)
{
	(void)increment;
	errno = ENOMEM;
	return (void *)-1;
}
