/*
 * legacy_long_regs.h — what the build found of the users' modules that a
 * 64-bit host cannot run (mk/legacy.mk, mk/legacy_long_regs.sh): register
 * pointers to volatile (unsigned) long, whose elements are 8 bytes apart on
 * an LP64 host.  Empty in the ILP32 configurations (host32, arm926-test).
 */
#ifndef LEGACY_LONG_REGS_H
#define LEGACY_LONG_REGS_H

#include <string.h>

/* "MODULE: NAME is a pointer to volatile unsigned long, ...", NULL-terminated (generated). */
extern const char *const legacy_long_regs[];

/* The build's finding for module (its first one), or NULL if it has none. */
static inline const char *legacy_long_regs_of(const char *module)
{
	size_t n = strlen(module);

	for (const char *const *f = legacy_long_regs; *f != NULL; f++)
		if (strncmp(*f, module, n) == 0 && (*f)[n] == ':')
			return *f;
	return NULL;
}

#endif
