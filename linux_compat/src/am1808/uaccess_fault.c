/*
 * uaccess_fault.c (AM1808) — on the brick a kernel-domain access to an
 * unmapped address is a data abort, which HRP2 hands to the CPU exception
 * handler (DEF_EXC) of the firmware, not back to the copy: there is no
 * exception-table fix-up, so the kernel domain's copies are plain ones and
 * a wild pointer stays the firmware's fault (docs/linux-api.md).
 */
#include <linux/string.h>
#include <linux_compat/uaccess_fault.h>

/* prb_mem of HRP2 checks a kernel-domain task against nothing either, but no copy can recover. */
bool lx_uaccess_unverified(void)
{
	return false;
}

/* A plain copy: the whole range. */
size_t lx_uaccess_copy(void *dst, const void *src, size_t n)
{
	memcpy(dst, src, n);
	return n;
}

/* A plain memset: the whole range. */
size_t lx_uaccess_clear(void *dst, size_t n)
{
	memset(dst, 0, n);
	return n;
}

/* A plain strnlen; never faulted. */
size_t lx_uaccess_strnlen(const char *s, size_t n, bool *faulted)
{
	*faulted = false;
	return strnlen(s, n);
}
