/* SPDX-License-Identifier: GPL-2.0-or-later */
/* siggen.c - signal generator, siggen(9) and the SigGen section of the realtime
 * components chapter: loadrt siggen [num_chan=num|names=name1[,name2...]].
 * Per generator: float inputs frequency (default 1 Hz), amplitude (default 1),
 * offset; six outputs sine, cosine, triangle, sawtooth, square (float) and clock
 * (bit); function PREFIX.update (uses FP). The waveforms are in siggen_core.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "comp_setup.h"
#include "instance_names.h"
#include "siggen_core.h"
#include "siggen_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("signal generator");

static int num_chan = -1;	/* -1: not given (one channel, unless names= is) */
RTAPI_MP_INT(num_chan, "number of signal generators, 1..16");
static char *names[SIGGEN_MAX];
RTAPI_MP_ARRAY_STRING(names, SIGGEN_MAX, "names of the signal generators (instead of num_chan)");

static int comp_id;

/* Init code runs outside kernel_fpu_begin/end in the kernel flavor, so the
 * defaults are stored as IEEE-754 bit patterns, without touching FP registers. */

static void set_float_bits(hal_float_t *p, rtapi_u64 bits)
{
	*(volatile rtapi_u64 *)p = bits;
}

static int float_pin(hal_pin_dir_t dir, hal_float_t **p, const char *prefix, const char *pin)
{
	return hal_pin_float_newf(dir, p, comp_id, "%s.%s", prefix, pin);
}

static int siggen_export(struct siggen *g, const char *prefix)
{
	char fn[HAL_NAME_LEN + 1];
	int err;

	err = float_pin(HAL_IN, &g->frequency, prefix, "frequency");
	if (!err)
		err = float_pin(HAL_IN, &g->amplitude, prefix, "amplitude");
	if (!err)
		err = float_pin(HAL_IN, &g->offset, prefix, "offset");
	if (!err)
		err = float_pin(HAL_OUT, &g->sine, prefix, "sine");
	if (!err)
		err = float_pin(HAL_OUT, &g->cosine, prefix, "cosine");
	if (!err)
		err = float_pin(HAL_OUT, &g->triangle, prefix, "triangle");
	if (!err)
		err = float_pin(HAL_OUT, &g->sawtooth, prefix, "sawtooth");
	if (!err)
		err = float_pin(HAL_OUT, &g->square, prefix, "square");
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &g->clock, comp_id, "%s.clock", prefix);
	if (err)
		return err;
	set_float_bits(g->frequency, FLOAT_ONE_BITS);
	set_float_bits(g->amplitude, FLOAT_ONE_BITS);
	set_float_bits(g->offset, 0);
	rtapi_snprintf(fn, sizeof(fn), "%s.update", prefix);
	return hal_export_funct(fn, siggen_update, g, 1, 0, comp_id);
}

int rtapi_app_main(void)
{
	char prefix[HAL_NAME_LEN + 1];
	struct siggen *all;
	int n, i, err;

	n = instance_count("siggen", "num_chan", num_chan, names, SIGGEN_MAX, SIGGEN_MAX);
	if (n < 0)
		return n;
	all = comp_setup("siggen", n * (long)sizeof(*all), &comp_id, &err);
	if (!all)
		return err;
	for (i = 0; !err && i < n; i++) {
		instance_prefix(prefix, sizeof(prefix), "siggen", names, i);
		err = siggen_export(&all[i], prefix);
	}
	return comp_finish(comp_id, err);
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
