/*
 * kstrtox.c — Linux's strict (kstrto*) and lenient (simple_strto*) integer parsers.
 */
#include <linux/kernel.h>
#include <linux/kstrtox.h>
#include <linux/errno.h>

/* Value of digit c in base (or base if c is not a digit of it). */
static unsigned int digit_value(char c, unsigned int base)
{
	unsigned int v;

	if (c >= '0' && c <= '9')
		v = (unsigned int)(c - '0');
	else if (c >= 'a' && c <= 'z')
		v = (unsigned int)(c - 'a') + 10U;
	else if (c >= 'A' && c <= 'Z')
		v = (unsigned int)(c - 'A') + 10U;
	else
		return base;
	return v < base ? v : base;
}

/* Skips a base prefix ("0x", "0") and resolves base 0; returns the digits' start. */
static const char *parse_base(const char *s, unsigned int *base)
{
	if (*base == 0) {
		if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X') && digit_value(s[2], 16) < 16) {
			*base = 16;
			return s + 2;
		}
		*base = s[0] == '0' ? 8 : 10;
		return s;
	}
	if (*base == 16 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X') && digit_value(s[2], 16) < 16)
		return s + 2;
	return s;
}

/*
 * Parses digits at s into *res; returns the number of digits consumed, or -ERANGE
 * on overflow.  *end receives the first unparsed character.
 */
static int parse_digits(const char *s, unsigned int base, unsigned long long *res, const char **end)
{
	unsigned long long value = 0;
	int count = 0;
	bool overflow = false;
	unsigned int d;

	while ((d = digit_value(*s, base)) < base) {
		if (value > (~0ULL - d) / base)
			overflow = true;
		value = value * base + d;
		s++;
		count++;
	}
	*end = s;
	*res = value;
	return overflow ? -ERANGE : count;
}

/* Strictly parses an unsigned long long: digits, then at most one newline. */
int kstrtoull(const char *s, unsigned int base, unsigned long long *res)
{
	unsigned long long value;
	const char *end;
	int n;

	if (s == NULL || res == NULL || base == 1 || base > 36)
		return -EINVAL;
	if (s[0] == '+')
		s++;
	s = parse_base(s, &base);
	n = parse_digits(s, base, &value, &end);
	if (n < 0)
		return n;
	if (n == 0)
		return -EINVAL;
	if (*end == '\n')
		end++;
	if (*end != '\0')
		return -EINVAL;
	*res = value;
	return 0;
}

/* Strictly parses a long long (optional leading '-'). */
int kstrtoll(const char *s, unsigned int base, long long *res)
{
	unsigned long long value;
	int ret;

	if (s == NULL || res == NULL)
		return -EINVAL;
	if (s[0] == '-') {
		ret = kstrtoull(s + 1, base, &value);
		if (ret)
			return ret;
		if (value > (unsigned long long)LLONG_MAX + 1ULL)
			return -ERANGE;
		*res = value == (unsigned long long)LLONG_MAX + 1ULL ? LLONG_MIN : -(long long)value;
		return 0;
	}
	ret = kstrtoull(s, base, &value);
	if (ret)
		return ret;
	if (value > (unsigned long long)LLONG_MAX)
		return -ERANGE;
	*res = (long long)value;
	return 0;
}

/* Parses an unsigned value no greater than max into *res. */
static int parse_unsigned_max(const char *s, unsigned int base, unsigned long long max,
			      unsigned long long *res)
{
	int ret = kstrtoull(s, base, res);

	if (ret)
		return ret;
	return *res > max ? -ERANGE : 0;
}

/* Parses a signed value within [min, max] into *res. */
static int parse_signed_range(const char *s, unsigned int base, long long min, long long max,
			      long long *res)
{
	int ret = kstrtoll(s, base, res);

	if (ret)
		return ret;
	return (*res < min || *res > max) ? -ERANGE : 0;
}

/* Strictly parses an unsigned long. */
int kstrtoul(const char *s, unsigned int base, unsigned long *res)
{
	unsigned long long v;
	int ret = parse_unsigned_max(s, base, ULONG_MAX, &v);

	if (ret == 0)
		*res = (unsigned long)v;
	return ret;
}

/* Strictly parses a long. */
int kstrtol(const char *s, unsigned int base, long *res)
{
	long long v;
	int ret = parse_signed_range(s, base, LONG_MIN, LONG_MAX, &v);

	if (ret == 0)
		*res = (long)v;
	return ret;
}

/* Strictly parses an unsigned int. */
int kstrtouint(const char *s, unsigned int base, unsigned int *res)
{
	unsigned long long v;
	int ret = parse_unsigned_max(s, base, UINT_MAX, &v);

	if (ret == 0)
		*res = (unsigned int)v;
	return ret;
}

/* Strictly parses an int. */
int kstrtoint(const char *s, unsigned int base, int *res)
{
	long long v;
	int ret = parse_signed_range(s, base, INT_MIN, INT_MAX, &v);

	if (ret == 0)
		*res = (int)v;
	return ret;
}

/* Strictly parses a u16. */
int kstrtou16(const char *s, unsigned int base, u16 *res)
{
	unsigned long long v;
	int ret = parse_unsigned_max(s, base, 0xffffU, &v);

	if (ret == 0)
		*res = (u16)v;
	return ret;
}

/* Strictly parses an s16. */
int kstrtos16(const char *s, unsigned int base, s16 *res)
{
	long long v;
	int ret = parse_signed_range(s, base, -32768, 32767, &v);

	if (ret == 0)
		*res = (s16)v;
	return ret;
}

/* Strictly parses a u8. */
int kstrtou8(const char *s, unsigned int base, u8 *res)
{
	unsigned long long v;
	int ret = parse_unsigned_max(s, base, 0xffU, &v);

	if (ret == 0)
		*res = (u8)v;
	return ret;
}

/* Strictly parses an s8. */
int kstrtos8(const char *s, unsigned int base, s8 *res)
{
	long long v;
	int ret = parse_signed_range(s, base, -128, 127, &v);

	if (ret == 0)
		*res = (s8)v;
	return ret;
}

/* Parses y/Y/1/on/true as true and n/N/0/off/false as false; -EINVAL otherwise. */
int kstrtobool(const char *s, bool *res)
{
	if (s == NULL || res == NULL)
		return -EINVAL;
	switch (s[0]) {
	case 'y': case 'Y': case '1': case 't': case 'T':
		*res = true;
		return 0;
	case 'n': case 'N': case '0': case 'f': case 'F':
		*res = false;
		return 0;
	case 'o': case 'O':
		if (s[1] == 'n' || s[1] == 'N') {
			*res = true;
			return 0;
		}
		if (s[1] == 'f' || s[1] == 'F') {
			*res = false;
			return 0;
		}
		return -EINVAL;
	default:
		return -EINVAL;
	}
}

/* Leniently parses leading digits (no sign); *endp gets the first unparsed char. */
unsigned long long simple_strtoull(const char *cp, char **endp, unsigned int base)
{
	unsigned long long value = 0;
	const char *end = cp;

	if (cp != NULL) {
		cp = parse_base(cp, &base);
		(void)parse_digits(cp, base, &value, &end);
	}
	if (endp != NULL)
		*endp = (char *)end;
	return value;
}

/* Leniently parses an unsigned long. */
unsigned long simple_strtoul(const char *cp, char **endp, unsigned int base)
{
	return (unsigned long)simple_strtoull(cp, endp, base);
}

/* Leniently parses a long long with optional '-'. */
long long simple_strtoll(const char *cp, char **endp, unsigned int base)
{
	if (cp != NULL && cp[0] == '-')
		return -(long long)simple_strtoull(cp + 1, endp, base);
	return (long long)simple_strtoull(cp, endp, base);
}

/* Leniently parses a long with optional '-'. */
long simple_strtol(const char *cp, char **endp, unsigned int base)
{
	return (long)simple_strtoll(cp, endp, base);
}
