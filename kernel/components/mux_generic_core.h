/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux_generic_core.h - the integer parts of mux_generic(9), HAL-free so unit tests
 * can call them: reading one config= entry ("bb8", "fu12") and choosing the selected
 * input with debounce. Used by mux_generic.c and mux_generic_fp.c. */
#ifndef MUX_GENERIC_CORE_H
#define MUX_GENERIC_CORE_H

#include "rtapi.h"

#define MUX_GEN_MAX_SIZE 1024	/* inputs of one mux, as mux_generic(9) says */

enum mux_gen_type { MUX_GEN_BIT, MUX_GEN_FLOAT, MUX_GEN_S32, MUX_GEN_U32, MUX_GEN_BAD };

static inline enum mux_gen_type mux_gen_type_of(char c)
{
	switch (c) {
	case 'b': case 'B': return MUX_GEN_BIT;
	case 'f': case 'F': return MUX_GEN_FLOAT;
	case 's': case 'S': return MUX_GEN_S32;
	case 'u': case 'U': return MUX_GEN_U32;
	default: return MUX_GEN_BAD;
	}
}

struct mux_gen_cfg {
	enum mux_gen_type in_type, out_type;
	int size;		/* number of inputs, 1..MUX_GEN_MAX_SIZE */
};

/* Parse one entry: input type letter, output type letter, decimal size. 0, or -1
 * when the letters are not b/f/s/u, -2 when the size is missing, not a number or
 * out of 1..MUX_GEN_MAX_SIZE. */
static inline int mux_gen_parse(const char *s, struct mux_gen_cfg *c)
{
	int i, size = 0;

	if (!s[0] || !s[1])
		return -1;
	c->in_type = mux_gen_type_of(s[0]);
	c->out_type = mux_gen_type_of(s[1]);
	if (c->in_type == MUX_GEN_BAD || c->out_type == MUX_GEN_BAD)
		return -1;
	for (i = 2; s[i]; i++) {
		if (s[i] < '0' || s[i] > '9' || i > 6)
			return -2;
		size = size * 10 + (s[i] - '0');
	}
	if (i == 2 || size < 1 || size > MUX_GEN_MAX_SIZE)
		return -2;
	c->size = size;
	return 0;
}

/* Number of sel-bit pins: log2(size) when size is a power of two, else none. */
static inline int mux_gen_sel_bits(int size)
{
	int bits = 0;

	if (size & (size - 1))
		return 0;
	while ((1 << bits) < size)
		bits++;
	return bits;
}

struct mux_gen_sel_state {	/* private to the mux's function */
	rtapi_s64 selected;	/* input whose value is on the output; starts at 0 */
	rtapi_s64 pending;	/* selection waiting out the debounce time */
	rtapi_u64 elapsed_ns;	/* how long 'pending' has been stable */
};

/* One period: 'sel' is sel-int plus the weighted sel-bits. Returns true when the
 * output is to be written from input s->selected, false when it keeps its value
 * (suppress-no-input with nothing selected, or a selection past the last input).
 * A new selection takes over once it was stable for debounce_us; 0 = at once. */
static inline bool mux_gen_select(struct mux_gen_sel_state *s, rtapi_s64 sel, bool suppress,
				  rtapi_u32 debounce_us, long period_ns, int size)
{
	if (suppress && sel == 0)
		return false;
	if (sel != s->selected) {
		if (sel != s->pending) {
			s->pending = sel;
			s->elapsed_ns = 0;
		} else {
			s->elapsed_ns += (rtapi_u64)period_ns;
		}
		if (s->elapsed_ns >= (rtapi_u64)debounce_us * 1000u) {
			s->selected = sel;
			s->elapsed_ns = 0;
		}
	} else {
		s->pending = sel;
		s->elapsed_ns = 0;
	}
	return s->selected >= 0 && s->selected < size;
}

#endif /* MUX_GENERIC_CORE_H */
