/*
 * io.c (host) — a physical register range is reachable only through the
 * window the installed MMIO handler (host_sim) returns for it, so that every
 * access has declared semantics; an unmodelled range maps to NULL.
 */
#include <linux_compat/platform.h>
#include <rtos_host.h>

/* The register model's window for [phys, phys + size), or NULL. */
void *lx_platform_io_window(uintptr_t phys, size_t size)
{
	return rtos_host_map_io(phys, (SIZE)size);
}
