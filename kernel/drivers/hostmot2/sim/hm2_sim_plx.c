/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_plx.c - the PLX bridge model (hm2_sim_plx.h). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hm2_sim_plx.h"
#include "../hm2_plx.h"

static unsigned long ctrl_offset(const struct hm2_sim_plx *p)
{
	return p->type == SIM_PLX_9030 ? PLX9030_CTRL : PLX9054_CNTRL;
}

/* /PROGRAM as the FPGA sees it: the 9054's USERO drives it only when an output */
static int program_high(const struct hm2_sim_plx *p)
{
	rtapi_u32 c = p->reg[ctrl_offset(p) / 4];

	if (p->type == SIM_PLX_9030)
		return !!(c & PLX9030_PROGRAM);
	return !(c & PLX9054_USERO_OUT) || (c & PLX9054_PROGRAM);
}

static int done(const struct hm2_sim_plx *p)
{
	if (p->fault == SIM_PLX_DONE_STUCK)
		return 1;
	return p->fault != SIM_PLX_NO_DONE && p->fpga->done;
}

void hm2_sim_plx_init(struct hm2_sim_plx *p, enum sim_plx_type type, enum sim_plx_fault fault,
		      struct hm2_sim_fpgacfg *fpga)
{
	int i;

	memset(p, 0, sizeof(*p));
	p->type = type;
	p->fault = fault;
	p->fpga = fpga;
	p->init_wait = -1;
	if (type == SIM_PLX_9030) {
		for (i = 0; i < 4; i++)		/* 32-bit bus, wait states; READY# off */
			p->reg[PLX9030_LAS0BRD / 4 + i] = 0x00400020;
		p->reg[PLX9030_CTRL / 4] = PLX9030_PROGRAM | PLX9030_WRITE | PLX9030_LED;
	} else {
		p->reg[PLX9054_CNTRL / 4] = PLX9054_PROGRAM;
	}
}

rtapi_u32 hm2_sim_plx_read(struct hm2_sim_plx *p, unsigned long offset)
{
	rtapi_u32 v = p->reg[(offset / 4) % SIM_PLX_REGS];

	if (offset != ctrl_offset(p))
		return v;
	if (p->init_wait > 0 && --p->init_wait == 0)
		p->init_wait = -1;
	if (p->type == SIM_PLX_9030) {
		v &= ~(PLX9030_DONE | PLX9030_INIT);
		if (done(p))
			v |= PLX9030_DONE;
		if (p->init_wait < 0 && p->fault != SIM_PLX_INIT_STUCK)
			v |= PLX9030_INIT;
	} else {
		v &= ~PLX9054_DONE;
		if ((v & PLX9054_USERI_IN) && done(p))
			v |= PLX9054_DONE;
	}
	return v;
}

void hm2_sim_plx_write(struct hm2_sim_plx *p, unsigned long offset, rtapi_u32 value)
{
	int was_high = program_high(p);

	p->reg[(offset / 4) % SIM_PLX_REGS] = value;
	if (offset != ctrl_offset(p))
		return;
	if (!program_high(p)) {		/* PROG_B low: configuration cleared, /INIT low */
		hm2_sim_fpgacfg_clear(p->fpga);
		p->init_wait = 0;
	} else if (!was_high) {
		p->init_wait = SIM_PLX_INIT_READS;
	}
}

int hm2_sim_plx_data(struct hm2_sim_plx *p, rtapi_u8 value)
{
	rtapi_u32 c = p->reg[ctrl_offset(p) / 4];
	int was_done = p->fpga->done;

	if (!program_high(p) || (p->type == SIM_PLX_9030 &&
				 ((c & PLX9030_WRITE) || p->init_wait >= 0))) {
		p->ignored++;
		return 0;
	}
	hm2_sim_fpgacfg_byte(p->fpga, value);
	return !was_done && p->fpga->done;
}

int hm2_sim_plx_window_ok(const struct hm2_sim_plx *p)
{
	int i;

	if (p->type != SIM_PLX_9030)
		return 1;
	for (i = 0; i < 4; i++)
		if (!(p->reg[PLX9030_LAS0BRD / 4 + i] & PLX9030_LASBRD_READY))
			return 0;
	return 1;
}
