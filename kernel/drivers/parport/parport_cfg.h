/* SPDX-License-Identifier: GPL-2.0-or-later */
/* parport_cfg.h - the hal_parport cfg= string (small-boards.md §3.3), HAL-free so the
 * unit tests call it directly: up to 8 entries "addr [type]", tokens separated by
 * whitespace or '_'; addr is hex with an optional 0x (< 16: a Linux parport number);
 * type is a word whose first letter decides: in, out (the default), epp, x. */
#ifndef PARPORT_CFG_H
#define PARPORT_CFG_H

#include "rtapi.h"

#define PARPORT_MAX_PORTS 8

enum parport_type { PARPORT_OUT = 0, PARPORT_IN, PARPORT_EPP, PARPORT_X };

struct parport_cfg_entry {
	unsigned int addr;
	enum parport_type type;
};

static inline int parport_cfg_sep(char c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '_';
}

static inline int parport_cfg_hex(char c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	if (c >= 'a' && c <= 'f')
		return c - 'a' + 10;
	if (c >= 'A' && c <= 'F')
		return c - 'A' + 10;
	return -1;
}

/* 1 when c starts a type word (setting *t), else 0. */
static inline int parport_cfg_type(char c, enum parport_type *t)
{
	switch (c) {
	case 'i': case 'I': *t = PARPORT_IN; return 1;
	case 'o': case 'O': *t = PARPORT_OUT; return 1;
	case 'e': case 'E': *t = PARPORT_EPP; return 1;
	case 'x': case 'X': *t = PARPORT_X; return 1;
	}
	return 0;
}

/* Fills e[0..n-1] and returns n (1..8), or -EINVAL with 'why' (at least 80 bytes)
 * saying what is wrong where. */
static inline int parport_cfg_parse(const char *s, struct parport_cfg_entry *e, char *why,
				    unsigned long why_len)
{
	int n = 0;

	for (;;) {
		unsigned long v = 0;
		int digits = 0;
		const char *tok;

		while (parport_cfg_sep(*s))
			s++;
		if (!*s)
			break;
		if (n == PARPORT_MAX_PORTS) {
			rtapi_snprintf(why, why_len, "more than %d ports at '%s'",
				       PARPORT_MAX_PORTS, s);
			return -EINVAL;
		}
		tok = s;
		if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X'))
			s += 2;
		for (; *s && !parport_cfg_sep(*s); s++, digits++) {
			int d = parport_cfg_hex(*s);

			if (d < 0 || v > 0xfff) {
				rtapi_snprintf(why, why_len, "'%.20s' is not a port address "
					       "(hex, at most 0xffff) or parport number", tok);
				return -EINVAL;
			}
			v = v * 16 + d;
		}
		if (!digits) {
			rtapi_snprintf(why, why_len, "'%.20s' is not a port address", tok);
			return -EINVAL;
		}
		e[n].addr = v;
		e[n].type = PARPORT_OUT;
		while (parport_cfg_sep(*s))
			s++;
		if (parport_cfg_type(*s, &e[n].type))	/* else the next token is an address */
			while (*s && !parport_cfg_sep(*s))
				s++;
		n++;
	}
	if (n == 0) {
		rtapi_snprintf(why, why_len, "no port given");
		return -EINVAL;
	}
	return n;
}

#endif /* PARPORT_CFG_H */
