/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_string.c - the string helpers of rtapi_string.h that neither the kernel nor libc
 * offer under one name; plain C, compiled unchanged for both flavors. */
#include "rtapi.h"
#include "rtapi_string.h"

size_t rtapi_strlcpy(char *dst, const char *src, size_t size)
{
	size_t len = 0;

	while (src[len])
		len++;
	if (size) {
		size_t n = len < size - 1 ? len : size - 1;
		size_t i;

		for (i = 0; i < n; i++)
			dst[i] = src[i];
		dst[n] = '\0';
	}
	return len;
}

static int digit_value(char c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	if (c >= 'a' && c <= 'z')
		return c - 'a' + 10;
	if (c >= 'A' && c <= 'Z')
		return c - 'A' + 10;
	return 99;
}

/* Magnitude of the number at s; *neg gets the sign, *ovf whether it overflowed. */
static unsigned long parse_magnitude(const char *s, char **end, int base, int *neg, int *ovf)
{
	const char *p = s, *digits;
	unsigned long v = 0, limit;
	int d;

	*neg = 0;
	*ovf = 0;
	while (*p == ' ' || *p == '\t' || *p == '\n')
		p++;
	if (*p == '-' || *p == '+')
		*neg = *p++ == '-';
	if ((base == 0 || base == 16) && p[0] == '0' && (p[1] == 'x' || p[1] == 'X') &&
	    digit_value(p[2]) < 16) {
		p += 2;
		base = 16;
	} else if (base == 0) {
		base = p[0] == '0' ? 8 : 10;
	}
	if (base < 2 || base > 36) {
		if (end)
			*end = (char *)s;
		return 0;
	}
	digits = p;
	limit = ~0UL / (unsigned long)base;
	for (; (d = digit_value(*p)) < base; p++) {
		if (v > limit || v * base > ~0UL - d)
			*ovf = 1;
		v = v * base + d;
	}
	if (end)
		*end = (char *)(p == digits ? s : p);
	return v;
}

unsigned long rtapi_strtoul(const char *s, char **end, int base)
{
	int neg, ovf;
	unsigned long v = parse_magnitude(s, end, base, &neg, &ovf);

	if (ovf)
		return ~0UL;
	return neg ? -v : v;
}

long rtapi_strtol(const char *s, char **end, int base)
{
	int neg, ovf;
	unsigned long v = parse_magnitude(s, end, base, &neg, &ovf);
	unsigned long max = ~0UL >> 1;

	if (neg)
		return (ovf || v > max + 1) ? -(long)max - 1 : (long)(0 - v);
	return (ovf || v > max) ? (long)max : (long)v;
}
