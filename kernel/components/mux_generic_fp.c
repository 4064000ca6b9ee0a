/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux_generic_fp.c - the realtime function of a mux_generic(9) mux whose input or output
 * is a float, alone in this file: the kernel flavor compiles only *_fp.c files with SSE,
 * and this runs only on a thread that opened an FPU section (uses_fp = 1). */
#include "mux_generic_fp.h"

/* The selected input as a double. */
static double read_in(const struct mux_gen *m, int i)
{
	switch (m->cfg.in_type) {
	case MUX_GEN_BIT: return *m->in[i].b ? 1.0 : 0.0;
	case MUX_GEN_FLOAT: return *m->in[i].f;
	case MUX_GEN_S32: return *m->in[i].s;
	default: return *m->in[i].u;
	}
}

/* Out-of-range conversions give what x86-64 C code gives: s32 0x80000000, and u32
 * the low 32 bits of the 64-bit conversion (0 beyond its range, and for NaN). */
static void write_out(struct mux_gen *m, double v)
{
	switch (m->cfg.out_type) {
	case MUX_GEN_BIT:
		*m->out.b = v != 0.0;
		break;
	case MUX_GEN_FLOAT:
		*m->out.f = v;
		break;
	case MUX_GEN_S32:
		*m->out.s = v >= -2147483648.0 && v < 2147483648.0 ? (hal_s32_t)v : (hal_s32_t)(-2147483647 - 1);
		break;
	default:
		*m->out.u = v > -9.2e18 && v < 9.2e18 ? (rtapi_u32)(rtapi_s64)v : 0u;
		break;
	}
}

COMP_FP_LOCAL void mux_gen_update_fp(void *arg, long period_ns)
{
	struct mux_gen *m = arg;
	bool take = mux_gen_select(&m->st, mux_gen_sel_value(m), *m->suppress, *m->debounce_us,
				   period_ns, m->cfg.size);

	m->selected = (hal_s32_t)m->st.selected;
	m->elapsed = (double)m->st.elapsed_ns * 1e-9;
	if (take)
		write_out(m, read_in(m, (int)m->st.selected));
}
