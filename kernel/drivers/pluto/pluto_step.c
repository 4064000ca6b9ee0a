/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_step.c - the Pluto-P parallel-port FPGA board with its step/direction design,
 * pluto_step(9); register map and protocol: pluto.md. loadrt pluto_step
 * [ioaddr=0x378] [ioaddr_hi=0|-1|ADDR] [epp_wide=1] [watchdog=1] [speedrange=0..3].
 * Every load uploads the FPGA image pluto/pluto_step.rbf from the firmware search path
 * (rtapi_firmware.h; not shipped with HAL) over the port in SPP mode, then talks EPP.
 * Functions pluto-step.read and pluto-step.write (FP, pluto_step_fp.c). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "pluto_step_fp.h"
#include "pluto_common.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Pluto-P board, step/direction firmware");

static int ioaddr = 0x378;
RTAPI_MP_INT(ioaddr, "address of the parallel port");
static int ioaddr_hi;
RTAPI_MP_INT(ioaddr_hi, "ECP registers' address (0: ioaddr + 0x400, -1: none)");
static int epp_wide = 1;
RTAPI_MP_INT(epp_wide, "16- and 32-bit EPP transfers (0: bytes only)");
static int watchdog = 1;
RTAPI_MP_INT(watchdog, "tristate the outputs ~6.5 ms after the last write (0: off)");
static int speedrange;
RTAPI_MP_INT(speedrange, "0..3: top speed 312.5 kHz / 2^speedrange");

/* float defaults as bit patterns: init code runs outside FPU sections */
#define FLOAT_ONE_BITS  0x3ff0000000000000ULL	/* 1.0 */
#define FLOAT_HALF_BITS 0x3fe0000000000000ULL	/* 0.5 */
#define FLOAT_TWO_BITS  0x4000000000000000ULL	/* 2.0 */

static int comp_id;
static struct pluto_step *step;

static int export_stepgen(struct pluto_stepgen *g, int m)
{
	int err = hal_pin_float_newf(HAL_IN, &g->position_cmd, comp_id,
				     "pluto-step.stepgen.%d.position-cmd", m);

	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &g->velocity_fb, comp_id,
					 "pluto-step.stepgen.%d.velocity-fb", m);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &g->position_fb, comp_id,
					 "pluto-step.stepgen.%d.position-fb", m);
	if (!err)
		err = hal_pin_s32_newf(HAL_OUT, &g->counts, comp_id, "pluto-step.stepgen.%d.counts", m);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &g->enable, comp_id, "pluto-step.stepgen.%d.enable", m);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &g->reset, comp_id, "pluto-step.stepgen.%d.reset", m);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &g->scale, comp_id, "pluto-step.stepgen.%d.scale", m);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &g->maxvel, comp_id, "pluto-step.stepgen.%d.maxvel", m);
	*(volatile rtapi_u64 *)&g->scale = FLOAT_ONE_BITS;
	return err;
}

static int export_all(struct pluto_step *s)
{
	int i, err = 0;

	for (i = 0; !err && i < 4; i++)
		err = export_stepgen(&s->sg[i], i);
	if (!err)
		err = hal_param_bit_newf(HAL_RW, &s->step_polarity, comp_id,
					 "pluto-step.stepgen.step-polarity");
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &s->steplen, comp_id, "pluto-step.stepgen.steplen");
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &s->stepspace, comp_id, "pluto-step.stepgen.stepspace");
	if (!err)
		err = hal_param_u32_newf(HAL_RW, &s->dirtime, comp_id, "pluto-step.stepgen.dirtime");
	if (!err)
		err = pluto_export_io(&s->io, comp_id, "pluto-step", 14, 16);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &s->debug_2, comp_id, "pluto-step.debug-2");
	if (!err)
		err = hal_param_float_newf(HAL_RW, &s->debug_3, comp_id, "pluto-step.debug-3");
	*(volatile rtapi_u64 *)&s->debug_2 = FLOAT_HALF_BITS;
	*(volatile rtapi_u64 *)&s->debug_3 = FLOAT_TWO_BITS;
	if (!err)
		err = hal_export_funct("pluto-step.read", pluto_step_read, s, 1, 0, comp_id);
	if (!err)
		err = hal_export_funct("pluto-step.write", pluto_step_write, s, 1, 0, comp_id);
	return err;
}

int rtapi_app_main(void)
{
	int err = pluto_check_params("pluto_step", ioaddr, ioaddr_hi, epp_wide, watchdog);

	if (!err && (speedrange < 0 || speedrange > 3)) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pluto_step: speedrange=%d: must be 0, 1, 2 or 3\n",
				speedrange);
		err = -EINVAL;
	}
	if (err)
		return err;
	err = pluto_open("pluto_step", "pluto/pluto_step.rbf", sizeof(*step),
			 offsetof(struct pluto_step, port), ioaddr, ioaddr_hi, &comp_id,
			 (void **)&step);
	if (err)
		return err;
	step->epp_wide = epp_wide;
	step->speedrange = speedrange;
	step->watchdog_bit = watchdog ? 0x4000 : 0;
	err = export_all(step);
	if (err) {
		pluto_close(&step->port, comp_id);
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	pluto_close(&step->port, comp_id);
}
