/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sampler.c - sample HAL pins into a shared-memory FIFO in real time, sampler(9):
 * loadrt sampler depth=depth1[,depth2...] cfg=string1[,string2...].
 * Per FIFO N: input pins sampler.N.pin.M (typed by cfg), sampler.N.enable (bit in,
 * default TRUE), sampler.N.curr-depth (s32 out), sampler.N.full (bit out);
 * params sampler.N.overruns and sampler.N.sample-num (s32 rw); function sampler.N.
 * halsampler(1) reads the FIFO (layout in streamer_fifo.h). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "streamer_fifo.h"
#include "fifo_module.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("sample HAL data in real time into a FIFO for halsampler");

static char *cfg[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_STRING(cfg, HAL_FIFO_MAX_FIFOS, "pin types of each FIFO: f, b, s, u per pin");
static int depth[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_INT(depth, HAL_FIFO_MAX_FIFOS, "samples each FIFO holds");

struct sampler {		/* in hal_malloc() memory, one per FIFO */
	struct hal_fifo_hdr *hdr;	/* shared memory: sample() is the producer */
	struct hal_fifo_rt fifo;	/* sample()'s own geometry and 'in': never from hdr */
	union hal_fifo_value *data;
	hal_bit_t *enable;		/* read by sample() */
	hal_s32_t *curr_depth;		/* written by sample() */
	hal_bit_t *full;		/* written by sample() */
	hal_s32_t overruns;		/* param: sample() counts up, setp resets */
	hal_s32_t sample_num;		/* param: sample() counts up, setp resets */
	bool gap;			/* private to sample(): a sample was dropped */
	int num_pins;
	char type[HAL_FIFO_MAX_PINS];	/* enum hal_fifo_type per pin */
	union fifo_pin_ptr pins[HAL_FIFO_MAX_PINS];
};

static struct fifo_module mod = { .name = "sampler" };	/* init/exit only */

static rtapi_s32 next_s32(rtapi_s32 v)
{
	return (rtapi_s32)((rtapi_u32)v + 1u);	/* wraps without signed overflow */
}

/* One sample per call: drop it (counting an overrun) when the FIFO is full, and
 * flag the next stored sample so halsampler can print "overrun" at the gap. */
static void sample(void *arg, long period_ns)
{
	struct sampler *s = arg;
	union hal_fifo_value *rec;
	rtapi_u32 used;
	int m;

	if (*s->enable) {
		rec = hal_fifo_rt_write_slot(s->hdr, &s->fifo, s->data);
		if (!rec) {
			s->overruns = next_s32(s->overruns);
			s->gap = true;
		} else {
			rec[HAL_FIFO_REC_SAMPLE].s = s->sample_num;
			rec[HAL_FIFO_REC_FLAGS].u = s->gap ? HAL_FIFO_GAP : 0;
			rec += HAL_FIFO_REC_HDR_WORDS;
			for (m = 0; m < s->num_pins; m++) {
				switch (s->type[m]) {
				case HAL_FIFO_FLOAT:
					rec[m].f = *s->pins[m].f;
					break;
				case HAL_FIFO_BIT:
					rec[m].u = *s->pins[m].b ? 1 : 0;
					break;
				case HAL_FIFO_S32:
					rec[m].s = *s->pins[m].s;
					break;
				default:
					rec[m].u = *s->pins[m].u;
					break;
				}
			}
			hal_fifo_rt_write_done(s->hdr, &s->fifo);
			s->gap = false;
		}
		s->sample_num = next_s32(s->sample_num);
	}
	used = hal_fifo_rt_used(s->hdr, &s->fifo, 1);
	*s->curr_depth = (hal_s32_t)used;
	*s->full = used >= s->fifo.slots - 1;
}

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
		err = hal_param_s32_newf(HAL_RW, &s->overruns, fm->comp_id, "sampler.%d.overruns", n);
	if (!err)
		err = hal_param_s32_newf(HAL_RW, &s->sample_num, fm->comp_id, "sampler.%d.sample-num", n);
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
