/* SPDX-License-Identifier: GPL-2.0-or-later */
/* streamer.c - write data from a shared-memory FIFO to HAL pins in real time,
 * streamer(9): loadrt streamer depth=depth1[,depth2...] cfg=string1[,string2...].
 * Per FIFO N: output pins streamer.N.pin.M (typed by cfg), streamer.N.curr-depth
 * (s32 out), streamer.N.empty (bit out), streamer.N.enable (bit in, default TRUE),
 * streamer.N.underruns (s32 read/write pin, listed under PINS on the page);
 * function streamer.N. halstreamer(1) fills the FIFO (layout in streamer_fifo.h). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "streamer_fifo.h"
#include "fifo_module.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("stream data from halstreamer into HAL in real time");

static char *cfg[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_STRING(cfg, HAL_FIFO_MAX_FIFOS, "pin types of each FIFO: f, b, s, u per pin");
static int depth[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_INT(depth, HAL_FIFO_MAX_FIFOS, "samples each FIFO holds");

struct streamer {		/* in hal_malloc() memory, one per FIFO */
	struct hal_fifo_hdr *hdr;	/* shared memory: update() is the consumer */
	struct hal_fifo_rt fifo;	/* update()'s own geometry and 'out': never from hdr */
	union hal_fifo_value *data;
	hal_s32_t *curr_depth;		/* written by update() */
	hal_bit_t *empty;		/* written by update() */
	hal_bit_t *enable;		/* read by update() */
	hal_s32_t *underruns;		/* I/O pin: update() counts up, setp resets */
	int num_pins;
	char type[HAL_FIFO_MAX_PINS];	/* enum hal_fifo_type per pin */
	union fifo_pin_ptr pins[HAL_FIFO_MAX_PINS];
};

static struct fifo_module mod = { .name = "streamer" };	/* init/exit only */

/* One record per call; with none available the pins keep their values and an
 * underrun is counted. */
static void update(void *arg, long period_ns)
{
	struct streamer *s = arg;
	const union hal_fifo_value *rec;
	rtapi_u32 used;
	int m;

	if (*s->enable) {
		rec = hal_fifo_rt_read_slot(s->hdr, &s->fifo, s->data);
		if (!rec) {
			*s->underruns = (hal_s32_t)((rtapi_u32)*s->underruns + 1u);
		} else {
			rec += HAL_FIFO_REC_HDR_WORDS;
			for (m = 0; m < s->num_pins; m++) {
				switch (s->type[m]) {
				case HAL_FIFO_FLOAT:
					*s->pins[m].f = rec[m].f;
					break;
				case HAL_FIFO_BIT:
					*s->pins[m].b = rec[m].u != 0;
					break;
				case HAL_FIFO_S32:
					*s->pins[m].s = (hal_s32_t)rec[m].s;
					break;
				default:
					*s->pins[m].u = (rtapi_u32)rec[m].u;
					break;
				}
			}
			hal_fifo_rt_read_done(s->hdr, &s->fifo);
		}
	}
	used = hal_fifo_rt_used(s->hdr, &s->fifo, 0);
	*s->curr_depth = (hal_s32_t)used;
	*s->empty = used == 0;
}

static int streamer_export(struct fifo_module *fm, void *mem, int n)
{
	struct streamer *s = mem;
	char fn[HAL_NAME_LEN + 1];
	int m, err;

	err = fifo_shm_create(&fm->shm[n], "streamer", fm->module_id, STREAMER_SHMEM_KEY, n, cfg[n], depth[n]);
	if (err)
		return err;
	s->hdr = fm->shm[n].hdr;
	s->data = fm->shm[n].data;
	s->num_pins = hal_fifo_cfg_pins(cfg[n]);
	hal_fifo_rt_init(&s->fifo, (rtapi_u32)depth[n], (rtapi_u32)s->num_pins);
	for (m = 0; m < s->num_pins; m++)
		s->type[m] = hal_fifo_type_of(cfg[n][m]);
	err = fifo_pins_export(s->pins, fm->comp_id, "streamer", n, cfg[n], HAL_OUT);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &s->curr_depth, fm->comp_id, "streamer.%d.curr-depth", n);
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &s->empty, fm->comp_id, "streamer.%d.empty", n);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &s->enable, fm->comp_id, "streamer.%d.enable", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_IO, &s->underruns, fm->comp_id, "streamer.%d.underruns", n);
	if (err)
		return err;
	*s->enable = true;
	*s->empty = true;
	rtapi_snprintf(fn, sizeof(fn), "streamer.%d", n);
	return hal_export_funct(fn, update, s, 1, 0, fm->comp_id);
}

int rtapi_app_main(void)
{
	return fifo_module_load(&mod, cfg, depth, sizeof(struct streamer), streamer_export);
}

void rtapi_app_exit(void)
{
	fifo_module_remove(&mod);
}
