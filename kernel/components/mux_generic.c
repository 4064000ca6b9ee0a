/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux_generic.c - choose one from several input values, mux_generic(9):
 * loadrt mux_generic config="bb8,fu12". Each entry is a mux: input type, output type
 * (b, f, s, u) and the number of inputs (1..1024). Per mux mux-gen.NN:
 *   pins suppress-no-input (bit in), debounce-us (u32 in), sel-int (u32 in),
 *   sel-bit-MM (bit in, log2(size) of them when size is a power of two),
 *   in-TYPE-MM (in), out-TYPE (out); params elapsed (float ro), selected (s32 ro);
 *   function mux-gen.NN, floating-point when the input or output is a float.
 * The selection is sel-int plus the binary value of the sel-bits; one past the last
 * input leaves the output as it is. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "mux_generic_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("multiplexer of any size and pin types");

#define MUX_GEN_MAX_MUXES 64

static char *config[MUX_GEN_MAX_MUXES];
RTAPI_MP_ARRAY_STRING(config, MUX_GEN_MAX_MUXES,
		      "muxes: input type, output type (b f s u), number of inputs, e.g. bb8,fu12");

static int comp_id;

static const char *const type_name[] = { "bit", "float", "s32", "u32" };

/* Integer-only conversions, for muxes with neither a float input nor output. */
static void mux_gen_update(void *arg, long period_ns)
{
	struct mux_gen *m = arg;
	rtapi_s64 v;
	int i;

	if (!mux_gen_select(&m->st, mux_gen_sel_value(m), *m->suppress, *m->debounce_us,
			    period_ns, m->cfg.size)) {
		m->selected = (hal_s32_t)m->st.selected;
		return;
	}
	m->selected = (hal_s32_t)m->st.selected;
	i = (int)m->st.selected;
	switch (m->cfg.in_type) {
	case MUX_GEN_BIT: v = *m->in[i].b ? 1 : 0; break;
	case MUX_GEN_S32: v = *m->in[i].s; break;
	default: v = *m->in[i].u; break;
	}
	switch (m->cfg.out_type) {
	case MUX_GEN_BIT: *m->out.b = v != 0; break;
	case MUX_GEN_S32: *m->out.s = (hal_s32_t)(rtapi_u32)v; break;	/* wraps, as C does */
	default: *m->out.u = (rtapi_u32)v; break;
	}
}

static int pin_new(enum mux_gen_type t, hal_pin_dir_t dir, union mux_gen_pin *p, const char *name)
{
	switch (t) {
	case MUX_GEN_BIT: return hal_pin_bit_new(name, dir, &p->b, comp_id);
	case MUX_GEN_FLOAT: return hal_pin_float_new(name, dir, &p->f, comp_id);
	case MUX_GEN_S32: return hal_pin_s32_new(name, dir, &p->s, comp_id);
	default: return hal_pin_u32_new(name, dir, &p->u, comp_id);
	}
}

static int mux_gen_export(const struct mux_gen_cfg *c, int n)
{
	char name[HAL_NAME_LEN + 1];
	struct mux_gen *m;
	bool fp = c->in_type == MUX_GEN_FLOAT || c->out_type == MUX_GEN_FLOAT;
	int i, err;

	m = hal_malloc((long)sizeof(*m) + c->size * (long)sizeof(m->in[0]));
	if (!m) {
		rtapi_print_msg(RTAPI_MSG_ERR, "mux_generic: out of HAL memory for mux %d (%d inputs)\n",
				n, c->size);
		return -ENOMEM;
	}
	m->cfg = *c;
	m->num_bits = mux_gen_sel_bits(c->size);
	err = hal_pin_bit_newf(HAL_IN, &m->suppress, comp_id, "mux-gen.%02d.suppress-no-input", n);
	if (!err)
		err = hal_pin_u32_newf(HAL_IN, &m->debounce_us, comp_id, "mux-gen.%02d.debounce-us", n);
	if (!err)
		err = hal_pin_u32_newf(HAL_IN, &m->sel_int, comp_id, "mux-gen.%02d.sel-int", n);
	for (i = 0; !err && i < m->num_bits; i++)
		err = hal_pin_bit_newf(HAL_IN, &m->sel_bit[i], comp_id, "mux-gen.%02d.sel-bit-%02d", n, i);
	for (i = 0; !err && i < c->size; i++) {
		rtapi_snprintf(name, sizeof(name), "mux-gen.%02d.in-%s-%02d", n, type_name[c->in_type], i);
		err = pin_new(c->in_type, HAL_IN, &m->in[i], name);
	}
	if (!err) {
		rtapi_snprintf(name, sizeof(name), "mux-gen.%02d.out-%s", n, type_name[c->out_type]);
		err = pin_new(c->out_type, HAL_OUT, &m->out, name);
	}
	if (!err)
		err = hal_param_float_newf(HAL_RO, &m->elapsed, comp_id, "mux-gen.%02d.elapsed", n);
	if (!err)
		err = hal_param_s32_newf(HAL_RO, &m->selected, comp_id, "mux-gen.%02d.selected", n);
	if (err)
		return err;
	rtapi_snprintf(name, sizeof(name), "mux-gen.%02d", n);
	return hal_export_funct(name, fp ? mux_gen_update_fp : mux_gen_update, m, fp, 0, comp_id);
}

int rtapi_app_main(void)
{
	struct mux_gen_cfg cfg[MUX_GEN_MAX_MUXES];
	int n, num, err = 0;

	for (num = 0; num < MUX_GEN_MAX_MUXES && config[num] && config[num][0]; num++) {
		int bad = mux_gen_parse(config[num], &cfg[num]);

		if (bad == -1) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"mux_generic: config entry %d '%s': the first two letters are the input and output type, each one of b, f, s, u\n",
					num + 1, config[num]);
			return -EINVAL;
		}
		if (bad) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"mux_generic: config entry %d '%s': the number of inputs after the type letters must be 1..%d\n",
					num + 1, config[num], MUX_GEN_MAX_SIZE);
			return -EINVAL;
		}
	}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR,
				"mux_generic: config= is required, e.g. loadrt mux_generic config=\"bb8,fu12\"\n");
		return -EINVAL;
	}
	comp_id = hal_init("mux_generic");
	if (comp_id < 0)
		return comp_id;
	for (n = 0; !err && n < num; n++)
		err = mux_gen_export(&cfg[n], n);
	if (err) {
		hal_exit(comp_id);	/* removes every pin, parameter and function made so far */
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
