/*
 * linux/kstrtox.h — strict string-to-integer conversion.
 * Each returns 0 and stores the value, -EINVAL for malformed input (one
 * trailing newline is accepted, as in Linux) or -ERANGE on overflow.
 * base 0 means auto-detect (0x hex, 0 octal, else decimal).
 */
#ifndef _LINUX_KSTRTOX_H
#define _LINUX_KSTRTOX_H

#include <linux/types.h>
#include <linux/compiler.h>

int __must_check kstrtoull(const char *s, unsigned int base, unsigned long long *res);
int __must_check kstrtoll(const char *s, unsigned int base, long long *res);
int __must_check kstrtoul(const char *s, unsigned int base, unsigned long *res);
int __must_check kstrtol(const char *s, unsigned int base, long *res);
int __must_check kstrtouint(const char *s, unsigned int base, unsigned int *res);
int __must_check kstrtoint(const char *s, unsigned int base, int *res);
int __must_check kstrtou16(const char *s, unsigned int base, u16 *res);
int __must_check kstrtos16(const char *s, unsigned int base, s16 *res);
int __must_check kstrtou8(const char *s, unsigned int base, u8 *res);
int __must_check kstrtos8(const char *s, unsigned int base, s8 *res);
/* "y/Y/1/on" -> true, "n/N/0/off" -> false (Linux's kstrtobool). */
int __must_check kstrtobool(const char *s, bool *res);

#define kstrtou64(s, base, res)	kstrtoull((s), (base), (unsigned long long *)(res))
#define kstrtos64(s, base, res)	kstrtoll((s), (base), (long long *)(res))
#define kstrtou32(s, base, res)	kstrtouint((s), (base), (unsigned int *)(res))
#define kstrtos32(s, base, res)	kstrtoint((s), (base), (int *)(res))

/* Legacy lenient parsers: convert the leading digits, store the end in *endp. */
unsigned long simple_strtoul(const char *cp, char **endp, unsigned int base);
long simple_strtol(const char *cp, char **endp, unsigned int base);
unsigned long long simple_strtoull(const char *cp, char **endp, unsigned int base);
long long simple_strtoll(const char *cp, char **endp, unsigned int base);

#endif /* _LINUX_KSTRTOX_H */
