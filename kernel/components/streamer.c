/* SPDX-License-Identifier: GPL-2.0-or-later */
/* streamer.c - write data from a shared-memory FIFO to HAL pins in real time,
 * streamer(9): loadrt streamer depth=depth1[,depth2...] cfg=string1[,string2...].
 * Per FIFO N: output pins streamer.N.pin.M (typed by cfg), streamer.N.curr-depth
 * (s32 out), streamer.N.empty (bit out), streamer.N.enable (bit in, default TRUE),
 * streamer.N.underruns (s32 read/write pin, listed under PINS on the page),
 * streamer.N.clock (bit in) and streamer.N.clock-mode (s32 in: 0 every period, the
 * default; 1 falling edges of clock, 2 rising, 3 both; other values as 0);
 * function streamer.N. halstreamer(1) fills the FIFO (layout in streamer_fifo.h). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "streamer_fifo.h"
#include "fifo_module.h"
#include "streamer_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("stream data from halstreamer into HAL in real time");

static char *cfg[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_STRING(cfg, HAL_FIFO_MAX_FIFOS, "pin types of each FIFO: f, b, s, u per pin");
static int depth[HAL_FIFO_MAX_FIFOS];
RTAPI_MP_ARRAY_INT(depth, HAL_FIFO_MAX_FIFOS, "samples each FIFO holds");

static struct fifo_module mod = { .name = "streamer" };	/* init/exit only */

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
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &s->clock, fm->comp_id, "streamer.%d.clock", n);
	if (!err)
		err = hal_pin_s32_newf(HAL_IN, &s->clock_mode, fm->comp_id, "streamer.%d.clock-mode", n);
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
