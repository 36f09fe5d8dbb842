/*
 * api_internal.h — helpers shared by the API's source files (not for applications).
 */
#ifndef EV3API_INTERNAL_H
#define EV3API_INTERNAL_H

#include <stdbool.h>
#include "kernel.h"

/* Whether the caller may write size bytes at p: not NULL and, from a task,
 * inside its protection domain (prb_mem).  Handlers run in the kernel domain. */
static inline bool api_can_write(const void *p, SIZE size)
{
	if (p == NULL)
		return false;
	return sns_ctx() || prb_mem(p, size, TSK_SELF, TPM_WRITE) == E_OK;
}

#endif /* EV3API_INTERNAL_H */
