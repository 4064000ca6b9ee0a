/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pluto_servo.c - the Pluto-P parallel-port FPGA board with its servo design,
 * pluto_servo(9); register map and protocol: pluto.md. loadrt pluto_servo
 * [ioaddr=0x378] [ioaddr_hi=0|-1|ADDR] [epp_wide=1] [watchdog=1] [test_encoder=0].
 * Every load uploads the FPGA image pluto/pluto_servo.rbf from the firmware search
 * path (rtapi_firmware.h; not shipped with HAL) over the port in SPP mode, then talks
 * EPP. Functions pluto-servo.read and pluto-servo.write (FP, pluto_servo_fp.c). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "pluto_servo_fp.h"
#include "pluto_common.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Pluto-P board, servo firmware");

static int ioaddr = 0x378;
RTAPI_MP_INT(ioaddr, "address of the parallel port");
static int ioaddr_hi;
RTAPI_MP_INT(ioaddr_hi, "ECP registers' address (0: ioaddr + 0x400, -1: none)");
static int epp_wide = 1;
RTAPI_MP_INT(epp_wide, "16- and 32-bit EPP transfers (0: bytes only)");
static int watchdog = 1;
RTAPI_MP_INT(watchdog, "tristate the outputs ~6.5 ms after the last write (0: off)");
static int test_encoder;
RTAPI_MP_INT(test_encoder, "count dout.00..02 as encoder 0's A, B, Z (test mode)");

#define FLOAT_ONE_BITS 0x3ff0000000000000ULL	/* 1.0, set outside FPU sections */

static int comp_id;
static struct pluto_servo *servo;

static int export_encoder(struct pluto_encoder *e, int m)
{
	int err = hal_pin_s32_newf(HAL_OUT, &e->count, comp_id, "pluto-servo.encoder.%d.count", m);

	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &e->position, comp_id,
					 "pluto-servo.encoder.%d.position", m);
	if (!err)
		err = hal_pin_float_newf(HAL_OUT, &e->velocity, comp_id,
					 "pluto-servo.encoder.%d.velocity", m);
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &e->reset, comp_id, "pluto-servo.encoder.%d.reset", m);
	if (!err)
		err = hal_pin_bit_newf(HAL_IO, &e->index_enable, comp_id,
				       "pluto-servo.encoder.%d.index-enable", m);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &e->scale, comp_id, "pluto-servo.encoder.%d.scale", m);
	*(volatile rtapi_u64 *)&e->scale = FLOAT_ONE_BITS;
	e->count64 = e->index64 = e->zero = 0;
	return err;
}

static int export_pwm(struct pluto_pwm *p, int m)
{
	int err = hal_pin_float_newf(HAL_IN, &p->value, comp_id, "pluto-servo.pwm.%d.value", m);

	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &p->enable, comp_id, "pluto-servo.pwm.%d.enable", m);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &p->offset, comp_id, "pluto-servo.pwm.%d.offset", m);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &p->scale, comp_id, "pluto-servo.pwm.%d.scale", m);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &p->max_dc, comp_id, "pluto-servo.pwm.%d.max-dc", m);
	if (!err)
		err = hal_param_float_newf(HAL_RW, &p->min_dc, comp_id, "pluto-servo.pwm.%d.min-dc", m);
	if (!err)
		err = hal_param_bit_newf(HAL_RW, &p->pwmdir, comp_id, "pluto-servo.pwm.%d.pwmdir", m);
	*(volatile rtapi_u64 *)&p->scale = FLOAT_ONE_BITS;
	*(volatile rtapi_u64 *)&p->max_dc = FLOAT_ONE_BITS;
	return err;
}

static int export_all(struct pluto_servo *s)
{
	int i, err = 0;

	for (i = 0; !err && i < 4; i++)
		err = export_encoder(&s->enc[i], i);
	if (!err)
		err = hal_param_bit_newf(HAL_RW, &s->z_polarity, comp_id, "pluto-servo.encoder.z-polarity");
	for (i = 0; !err && i < 4; i++)
		err = export_pwm(&s->pwm[i], i);
	if (!err)
		err = hal_param_bit_newf(HAL_RW, &s->is_pdm, comp_id, "pluto-servo.pwm.is-pdm");
	if (!err)
		err = pluto_export_io(&s->io, comp_id, "pluto-servo", 20, 20);
	if (!err)
		err = hal_export_funct("pluto-servo.read", pluto_servo_read, s, 1, 0, comp_id);
	if (!err)
		err = hal_export_funct("pluto-servo.write", pluto_servo_write, s, 1, 0, comp_id);
	return err;
}

int rtapi_app_main(void)
{
	int err = pluto_check_params("pluto_servo", ioaddr, ioaddr_hi, epp_wide, watchdog);

	if (!err && test_encoder != 0 && test_encoder != 1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "pluto_servo: test_encoder=%d: must be 0 or 1\n",
				test_encoder);
		err = -EINVAL;
	}
	if (err)
		return err;
	err = pluto_open("pluto_servo", "pluto/pluto_servo.rbf", sizeof(*servo),
			 offsetof(struct pluto_servo, port), ioaddr, ioaddr_hi, &comp_id,
			 (void **)&servo);
	if (err)
		return err;
	servo->epp_wide = epp_wide;
	servo->control_bits = (watchdog ? 0x4000 : 0) | (test_encoder ? 0x2000 : 0);
	err = export_all(servo);
	if (err) {
		pluto_close(&servo->port, comp_id);
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	pluto_close(&servo->port, comp_id);
}
