/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_string.h - string functions for realtime code (intro(3rtapi), "rtapi_string.h").
 * Use it instead of <string.h>: strlen, strcmp, strncmp, strcpy, strncpy, strcat,
 * memcpy, memmove, memset, memcmp, strchr, strrchr, strstr come from <linux/string.h> in
 * the kernel flavor and from the C library in userspace. The rtapi_ functions below
 * exist in both flavors (rtapi_string.c, no libc). */
#ifndef RTAPI_STRING_H
#define RTAPI_STRING_H

#if defined(__KERNEL__)
#include <linux/string.h>
#else
#include <string.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Copy at most size-1 characters and always terminate (when size > 0), like BSD
 * strlcpy; returns strlen(src), so a result >= size means it was cut. */
size_t rtapi_strlcpy(char *dst, const char *src, size_t size);

/* Parse an integer like the kernel's simple_strtol: leading blanks, an optional sign,
 * base 0 detects 0x (hex) and 0 (octal); base 16 accepts a 0x prefix. *end (if end is
 * not NULL) points after the last digit used, or at s when there was none. Values
 * beyond the type's range saturate. */
long rtapi_strtol(const char *s, char **end, int base);
unsigned long rtapi_strtoul(const char *s, char **end, int base);

#ifdef __cplusplus
}
#endif
#endif /* RTAPI_STRING_H */
