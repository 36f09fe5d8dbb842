/*
 * uaccess_fault.h — fault-safe user-memory access, one implementation per
 * target (src/host/uaccess_fault.c, src/am1808/uaccess_fault.c).
 *
 * prb_mem answers "may this task touch the range" from the protection
 * domains; for a kernel-domain task (and under KERNEL_DS) it checks nothing,
 * so a wild pointer would fault inside the copy.  Linux recovers from such a
 * fault through the exception table and copy_*_user return the bytes not
 * copied; these functions are that recovery.
 */
#ifndef LINUX_COMPAT_UACCESS_FAULT_H
#define LINUX_COMPAT_UACCESS_FAULT_H

#include <stdbool.h>
#include <stddef.h>

/* True if the calling context's prb_mem accepts ranges without checking them (a kernel-domain task). */
bool lx_uaccess_unverified(void);

/* Copies n bytes; a fault ends the copy.  Returns the bytes copied (exact to the byte). */
size_t lx_uaccess_copy(void *dst, const void *src, size_t n);

/* Zeroes n bytes; a fault ends it.  Returns the bytes zeroed. */
size_t lx_uaccess_clear(void *dst, size_t n);

/* Length of the string at s, at most n; *faulted set if a fault ended the scan first. */
size_t lx_uaccess_strnlen(const char *s, size_t n, bool *faulted);

#endif /* LINUX_COMPAT_UACCESS_FAULT_H */
