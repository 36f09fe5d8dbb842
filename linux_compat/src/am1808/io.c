/*
 * io.c (AM1808) — the MMU maps the peripheral space flat, so the window of a
 * register range is its physical address.
 */
#include <linux_compat/platform.h>

/* The physical address itself. */
void *lx_platform_io_window(uintptr_t phys, size_t size)
{
	(void)size;
	return (void *)phys;
}
