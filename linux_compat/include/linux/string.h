/*
 * linux/string.h — the string functions, declared here as Linux declares
 * them (its lib/string.c role is played by the C library's implementations,
 * which the compiler may also expand inline), plus the kernel's own.
 */
#ifndef _LINUX_STRING_H
#define _LINUX_STRING_H

#include <linux/types.h>
#include <linux/compiler.h>

void *memcpy(void *dest, const void *src, size_t count);
void *memmove(void *dest, const void *src, size_t count);
void *memset(void *s, int c, size_t count);
int memcmp(const void *cs, const void *ct, size_t count);
void *memchr(const void *s, int c, size_t n);
size_t strlen(const char *s);
size_t strnlen(const char *s, size_t count);
char *strcpy(char *dest, const char *src);
char *strncpy(char *dest, const char *src, size_t count);
char *strcat(char *dest, const char *src);
char *strncat(char *dest, const char *src, size_t count);
int strcmp(const char *cs, const char *ct);
int strncmp(const char *cs, const char *ct, size_t count);
int strcasecmp(const char *s1, const char *s2);
int strncasecmp(const char *s1, const char *s2, size_t len);
char *strchr(const char *s, int c);
char *strrchr(const char *s, int c);
char *strstr(const char *s1, const char *s2);
char *strpbrk(const char *cs, const char *ct);
char *strsep(char **s, const char *ct);
size_t strspn(const char *s, const char *accept);
size_t strcspn(const char *s, const char *reject);

/* Copies src into dest (size bytes, NUL-terminated); returns the length
 * copied, or -E2BIG if src was truncated (size 0: -E2BIG). */
ssize_t strscpy(char *dest, const char *src, size_t count);
/* Like memset, but the compiler may not drop it (for secrets). */
void memzero_explicit(void *s, size_t count);
/* Pointer to the first byte in [start, start+bytes) that is not c, or NULL. */
void *memchr_inv(const void *start, int c, size_t bytes);
/* s with leading whitespace skipped. */
char *skip_spaces(const char *str);
/* s with leading and trailing whitespace removed (trailing in place). */
char *strim(char *s);
/* Length of prefix if str starts with it, else 0. */
static inline size_t str_has_prefix(const char *str, const char *prefix)
{
	size_t len = strlen(prefix);

	return strncmp(str, prefix, len) == 0 ? len : 0;
}
/* Index of string in the array of n strings (n < 0: NULL-terminated), or -EINVAL. */
int match_string(const char * const *array, size_t n, const char *string);
/* true if a equals b, ignoring one trailing newline in a (for sysfs-style input). */
bool sysfs_streq(const char *a, const char *b);

#endif /* _LINUX_STRING_H */
