/*
 * string.c — the kernel's string helpers that the C library lacks.
 */
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux/errno.h>

/* Copies at most count-1 characters and a NUL; the length, or -E2BIG if truncated. */
ssize_t strscpy(char *dest, const char *src, size_t count)
{
	size_t i;

	if (count == 0)
		return -E2BIG;
	for (i = 0; i < count; i++) {
		dest[i] = src[i];
		if (src[i] == '\0')
			return (ssize_t)i;
	}
	dest[count - 1] = '\0';
	return -E2BIG;
}

/* memset the compiler cannot elide. */
void memzero_explicit(void *s, size_t count)
{
	memset(s, 0, count);
	barrier_data(s);
}

/* First byte of [start, start+bytes) that differs from c, or NULL. */
void *memchr_inv(const void *start, int c, size_t bytes)
{
	const unsigned char *p = start;
	size_t i;

	for (i = 0; i < bytes; i++)
		if (p[i] != (unsigned char)c)
			return (void *)(p + i);
	return NULL;
}

/* True for the characters Linux's isspace accepts. */
static bool is_space(char c)
{
	return c == ' ' || (c >= '\t' && c <= '\r');
}

/* str past its leading whitespace. */
char *skip_spaces(const char *str)
{
	while (is_space(*str))
		str++;
	return (char *)str;
}

/* Cuts trailing whitespace in place; returns s past its leading whitespace. */
char *strim(char *s)
{
	size_t len = strlen(s);

	while (len > 0 && is_space(s[len - 1]))
		s[--len] = '\0';
	return skip_spaces(s);
}

/* True if a equals b, except that a may carry one trailing newline more. */
bool sysfs_streq(const char *a, const char *b)
{
	while (*a && *a == *b) {
		a++;
		b++;
	}
	if (*a == *b)
		return true;
	if (*a == '\n' && a[1] == '\0' && *b == '\0')
		return true;
	if (*b == '\n' && b[1] == '\0' && *a == '\0')
		return true;
	return false;
}

/* Index of string in array (n entries; stops at a NULL entry), or -EINVAL. */
int match_string(const char * const *array, size_t n, const char *string)
{
	size_t i;

	for (i = 0; i < n; i++) {
		if (array[i] == NULL)
			break;
		if (strcmp(array[i], string) == 0)
			return (int)i;
	}
	return -EINVAL;
}
