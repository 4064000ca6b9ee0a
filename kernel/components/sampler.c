/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sampler.c - sample HAL pins into a shared-memory FIFO in real time, sampler(9):
 * loadrt sampler depth=depth1[,depth2...] cfg=string1[,string2...].
 * Per FIFO N: input pins sampler.N.pin.M (typed by cfg), sampler.N.enable (bit in,
 * default TRUE), sampler.N.curr-depth (s32 out), sampler.N.full (bit out),
 * sampler.N.overruns and sampler.N.sample-num (s32 I/O pins, as in LinuxCNC 2.9 and
 * later: the sampler counts them up, setp resets them); function sampler.N.
 * halsampler(1) reads the FIFO (layout in streamer_fifo.h). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "streamer_fifo.h"
#include "fifo_module.h"
#include "sampler_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("sample HAL data in real time into a FIFO for halsampler");

static char *cfg[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_STRING(cfg, HAL_FIFO_MAX_FIFOS, "pin types of each FIFO: f, b, s, u per pin");
static int depth[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_INT(depth, HAL_FIFO_MAX_FIFOS, "samples each FIFO holds");

static struct fifo_module mod = { .name = "sampler" };	/* init/exit only */

static int sampler_export(struct fifo_module *fm, void *mem, int n)
{
	struct sampler *s = mem;
	char fn[HAL_NAME_LEN + 1];
	int m, err;

	err = fifo_shm_create(&fm->shm[n], "sampler", fm->module_id, SAMPLER_SHMEM_KEY, n, cfg[n], depth[n]);
	if (err)
		return err;
	s->hdr = fm->shm[n].hdr;
	s->data = fm->shm[n].data;
	s->num_pins = hal_fifo_cfg_pins(cfg[n]);
	hal_fifo_rt_init(&s->fifo, (rtapi_u32)depth[n], (rtapi_u32)s->num_pins);
	for (m = 0; m < s->num_pins; m++)
		s->type[m] = hal_fifo_type_of(cfg[n][m]);
	err = fifo_pins_export(s->pins, fm->comp_id, "sampler", n, cfg[n], HAL_IN);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &s->enable, fm->comp_id, "sampler.%d.enable", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &s->curr_depth, fm->comp_id, "sampler.%d.curr-depth", n);
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &s->full, fm->comp_id, "sampler.%d.full", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_IO, &s->overruns, fm->comp_id, "sampler.%d.overruns", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_IO, &s->sample_num, fm->comp_id, "sampler.%d.sample-num", n);
	if (err)
		return err;
	*s->enable = true;
	rtapi_snprintf(fn, sizeof(fn), "sampler.%d", n);
	return hal_export_funct(fn, sample, s, 1, 0, fm->comp_id);
}

int rtapi_app_main(void)
{
	return fifo_module_load(&mod, cfg, depth, sizeof(struct sampler), sampler_export);
}

void rtapi_app_exit(void)
{
	fifo_module_remove(&mod);
}
