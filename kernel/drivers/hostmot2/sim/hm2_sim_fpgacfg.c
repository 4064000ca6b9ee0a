/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_fpgacfg.c - the FPGA configuration-port model (hm2_sim_fpgacfg.h). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_sim_fpgacfg.h"
#include "../hm2_bitfile.h"

void hm2_sim_fpgacfg_clear(struct hm2_sim_fpgacfg *c)
{
	memset(c, 0, sizeof(*c));
}

void hm2_sim_fpgacfg_byte(struct hm2_sim_fpgacfg *c, rtapi_u8 port)
{
	rtapi_u8 b = hm2_bitfile_reverse(port);	/* the card's wiring, undone */

	c->bytes++;
	if (c->done)
		return;		/* extra clocks after DONE are ignored, as the FPGA does */
	c->shift = c->shift << 8 | b;
	if (!c->synced) {
		if (c->shift == FPGACFG_SYNC) {
			c->synced = 1;
			c->word_bytes = 0;
			c->prev_word = 0;
		}
		return;
	}
	if (++c->word_bytes < 4)
		return;
	c->word_bytes = 0;
	if (c->prev_word == FPGACFG_CMD_HDR && c->shift == FPGACFG_DESYNC)
		c->done = 1;
	c->prev_word = c->shift;
}
