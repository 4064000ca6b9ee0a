/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_parport.c - a simulated PC parallel port (small-boards.md §3.1) behind the port
 * ranges io..io+7 and io+0x400..+2 (rtapi_iosim.h), so that hal_parport and the
 * parallel-port boards run without hardware: loadrt sim_parport io=0x1000[,...].
 * Per port N (HAL TRUE = electrically high, as hal_parport's pins):
 *   sim-parport.N.pin-NN-out (bit OUT) the level of output pins 1-9, 14, 16, 17;
 *   sim-parport.N.pin-NN-in (bit IN) what the outside drives on 2-9 (read when the
 *     data port is an input) and on the status pins 10-13, 15;
 *   sim-parport.N.pin-NN-pulldown (bit IN) pulls the open-collector pins 1, 14, 16,
 *     17 low;
 *   u32 OUT pins counting register traffic (data-writes, control-writes, data-reads,
 *     status-reads, control-reads, epp-cycles) and showing the last data, control
 *     and ecr values written.
 * EPP cycles reach a 256-byte register file: an address cycle sets the pointer, each
 * data cycle reads or writes the register there and advances it. With board=B for
 * the port they reach a device on the cable instead: B = pluto_servo or pluto_step,
 * a Pluto-P board (sim_pluto.c) configured through the port and answering that
 * design's register map; B = 7i43 (400K FPGA) or 7i43_200 (200K), a Mesa 7i43
 * (sim_7i43.c: its CPLD, and HostMot2 once configured); B = none, nothing connected. A cycle nobody answers sets
 * the EPP timeout flag, status bit 0, until a status write with bit 0 set clears it. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_iosim.h"
#include "rtapi_string.h"
#include "hal.h"
#include "sim_pluto.h"
#include "sim_7i43.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("simulated PC parallel port");

#define SIM_MAX 4
static int io[SIM_MAX];
RTAPI_MP_ARRAY_INT(io, SIM_MAX, "base addresses of the simulated ports");
static char *board[SIM_MAX];
RTAPI_MP_ARRAY_STRING(board, SIM_MAX, "device on each port's cable: none, pluto_servo, "
		      "pluto_step, 7i43, 7i43_200 (default: an EPP register file)");

enum cable { CABLE_REGFILE, CABLE_NONE, CABLE_PLUTO, CABLE_7I43 };

static const int status_pin[5] = { 15, 13, 12, 10, 11 };	/* status bits 3..7 */
static const int control_pin[4] = { 1, 14, 16, 17 };		/* control bits 0..3 */

struct sim_pp {			/* HAL memory; touched only by port accesses */
	hal_bit_t *data_level[8], *data_ext[8];
	hal_bit_t *status_ext[5];
	hal_bit_t *control_level[4], *control_pulldown[4];
	hal_u32_t *data_writes, *control_writes, *data_reads, *status_reads, *control_reads;
	hal_u32_t *epp_cycles, *data, *control, *ecr;
	unsigned char data_reg, control_reg, ecr_reg, epp_addr;
	unsigned char epp_mem[256];
	enum cable cable;
	struct sim_pluto *pluto;	/* CABLE_PLUTO */
	struct sim_7i43 *mesa;		/* CABLE_7I43 */
	int epp_timeout;		/* status bit 0 */
	int handle_lo, handle_hi;
	char name[24];
};

static int comp_id;
static struct sim_pp *sims;
static int num_sims;

static void update_levels(struct sim_pp *s)
{
	int i, input = s->control_reg & 0x20;

	for (i = 0; i < 8; i++)
		*s->data_level[i] = input ? *s->data_ext[i] : (s->data_reg >> i) & 1;
	for (i = 0; i < 4; i++)	/* bits 0, 1, 3 are inverted by the port */
		*s->control_level[i] = (((s->control_reg ^ 0x0b) >> i) & 1) &&
				       !*s->control_pulldown[i];
}

static unsigned char status_byte(struct sim_pp *s)
{
	unsigned char b = 0;
	int i;

	for (i = 0; i < 5; i++)
		b |= (unsigned char)(*s->status_ext[i] & 1) << (i + 3);
	return (b ^ 0x80) | (s->epp_timeout ? 0x01 : 0);	/* Busy is inverted */
}

static unsigned char lo_inb(void *dev, unsigned int off)
{
	struct sim_pp *s = dev;
	unsigned char b = 0;
	int i;

	update_levels(s);
	switch (off) {
	case 0:
		++*s->data_reads;
		for (i = 0; i < 8; i++)
			b |= (unsigned char)(*s->data_level[i] & 1) << i;
		return b;
	case 1:
		++*s->status_reads;
		return status_byte(s);
	case 2:
		++*s->control_reads;
		for (i = 0; i < 4; i++)
			b |= (unsigned char)(*s->control_level[i] & 1) << i;
		return (s->control_reg & 0xf0) | (b ^ 0x0b);
	case 3:
		++*s->epp_cycles;
		if (s->cable == CABLE_7I43) {
			if (sim_7i43_epp_addr_read(s->mesa, &b) < 0) {
				s->epp_timeout = 1;
				return 0xff;
			}
			return b;
		}
		if (s->cable != CABLE_REGFILE) {	/* address reads: unused by the Pluto */
			s->epp_timeout = 1;
			return 0xff;
		}
		return s->epp_addr;
	default:
		++*s->epp_cycles;
		if (s->cable == CABLE_REGFILE)
			return s->epp_mem[s->epp_addr++];
		if (s->cable == CABLE_NONE ||
		    (s->cable == CABLE_PLUTO ? sim_pluto_epp_read(s->pluto, &b) :
		     sim_7i43_epp_read(s->mesa, &b)) < 0) {
			s->epp_timeout = 1;
			return 0xff;
		}
		return b;
	}
}

/* An EPP write cycle to a device on the cable. */
static void cable_write(struct sim_pp *s, int addr_cycle, unsigned char b)
{
	int rc = -1;

	if (s->cable == CABLE_PLUTO)
		rc = addr_cycle ? sim_pluto_epp_addr(s->pluto, b) : sim_pluto_epp_write(s->pluto, b);
	else if (s->cable == CABLE_7I43)
		rc = addr_cycle ? sim_7i43_epp_addr(s->mesa, b) : sim_7i43_epp_write(s->mesa, b);
	if (rc < 0)
		s->epp_timeout = 1;
}

static void lo_outb(void *dev, unsigned int off, unsigned char b)
{
	struct sim_pp *s = dev;

	switch (off) {
	case 0:
		++*s->data_writes;
		s->data_reg = b;
		*s->data = b;
		break;
	case 1:			/* status is read-only but for the timeout flag */
		if (b & 0x01)
			s->epp_timeout = 0;
		break;
	case 2:
		++*s->control_writes;
		s->control_reg = b;
		*s->control = b;
		break;
	case 3:
		++*s->epp_cycles;
		if (s->cable == CABLE_REGFILE)
			s->epp_addr = b;
		else
			cable_write(s, 1, b);
		break;
	default:
		++*s->epp_cycles;
		if (s->cable == CABLE_REGFILE)
			s->epp_mem[s->epp_addr++] = b;
		else
			cable_write(s, 0, b);
		break;
	}
	update_levels(s);
	if (s->cable == CABLE_PLUTO && off <= 2)
		sim_pluto_spp(s->pluto, s->data_reg, s->control_reg);
	if (s->cable == CABLE_7I43 && off == 2)
		sim_7i43_spp(s->mesa, s->control_reg);
}

static unsigned char hi_inb(void *dev, unsigned int off)
{
	struct sim_pp *s = dev;

	return off == 2 ? s->ecr_reg : 0;
}

static void hi_outb(void *dev, unsigned int off, unsigned char b)
{
	struct sim_pp *s = dev;

	if (off == 2) {
		s->ecr_reg = b;
		*s->ecr = b;
	}
}

static const struct rtapi_iosim_ops lo_ops = { lo_inb, lo_outb };
static const struct rtapi_iosim_ops hi_ops = { hi_inb, hi_outb };

static int export_u32(hal_u32_t **p, int n, const char *what)
{
	return hal_pin_u32_newf(HAL_OUT, p, comp_id, "sim-parport.%d.%s", n, what);
}

static int export_sim(struct sim_pp *s, int n)
{
	int i, err = 0;

	for (i = 0; !err && i < 8; i++) {
		err = hal_pin_bit_newf(HAL_OUT, &s->data_level[i], comp_id,
				       "sim-parport.%d.pin-%02d-out", n, i + 2);
		if (!err)
			err = hal_pin_bit_newf(HAL_IN, &s->data_ext[i], comp_id,
					       "sim-parport.%d.pin-%02d-in", n, i + 2);
	}
	for (i = 0; !err && i < 5; i++)
		err = hal_pin_bit_newf(HAL_IN, &s->status_ext[i], comp_id,
				       "sim-parport.%d.pin-%02d-in", n, status_pin[i]);
	for (i = 0; !err && i < 4; i++) {
		err = hal_pin_bit_newf(HAL_OUT, &s->control_level[i], comp_id,
				       "sim-parport.%d.pin-%02d-out", n, control_pin[i]);
		if (!err)
			err = hal_pin_bit_newf(HAL_IN, &s->control_pulldown[i], comp_id,
					       "sim-parport.%d.pin-%02d-pulldown", n, control_pin[i]);
	}
	if (!err) err = export_u32(&s->data_writes, n, "data-writes");
	if (!err) err = export_u32(&s->control_writes, n, "control-writes");
	if (!err) err = export_u32(&s->data_reads, n, "data-reads");
	if (!err) err = export_u32(&s->status_reads, n, "status-reads");
	if (!err) err = export_u32(&s->control_reads, n, "control-reads");
	if (!err) err = export_u32(&s->epp_cycles, n, "epp-cycles");
	if (!err) err = export_u32(&s->data, n, "data");
	if (!err) err = export_u32(&s->control, n, "control");
	if (!err) err = export_u32(&s->ecr, n, "ecr");
	if (!err && s->cable == CABLE_PLUTO) {
		s->pluto = sim_pluto_new(comp_id, n, !strcmp(board[n], "pluto_step") ?
					 SIM_PLUTO_STEP : SIM_PLUTO_SERVO);
		err = s->pluto ? 0 : -ENOMEM;
	}
	if (!err && s->cable == CABLE_7I43) {
		s->mesa = sim_7i43_new(comp_id, n, !strcmp(board[n], "7i43_200") ? 200 : 400);
		err = s->mesa ? 0 : -ENOMEM;
	}
	if (err)
		return err;
	s->control_reg = 0x0c;	/* after power-up: nInit high, nSelectIn low */
	*s->control = s->control_reg;
	update_levels(s);
	return 0;
}

static void unregister_all(void)
{
	int n;

	for (n = 0; n < num_sims; n++) {
		if (sims[n].handle_hi >= 0)
			rtapi_iosim_unregister(sims[n].handle_hi);
		if (sims[n].handle_lo >= 0)
			rtapi_iosim_unregister(sims[n].handle_lo);
	}
}

int rtapi_app_main(void)
{
	int n, num, err = 0;

	for (num = 0; num < SIM_MAX && io[num] > 0; num++)
		if (io[num] < 16 || io[num] > 0xffff - 0x403) {
			rtapi_print_msg(RTAPI_MSG_ERR, "sim_parport: io=0x%x: must be 0x10..0x%x\n",
					io[num], 0xffff - 0x403);
			return -EINVAL;
		}
	if (num == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_parport: give the ports' addresses: io=0x...\n");
		return -EINVAL;
	}
	for (n = 0; n < SIM_MAX; n++) {
		if (!board[n] || !*board[n])
			continue;
		if (n >= num || (strcmp(board[n], "none") &&
				 strcmp(board[n], "pluto_servo") &&
				 strcmp(board[n], "pluto_step") && strcmp(board[n], "7i43") &&
				 strcmp(board[n], "7i43_200"))) {
			rtapi_print_msg(RTAPI_MSG_ERR, "sim_parport: board=%s (entry %d): must be "
					"none, pluto_servo, pluto_step, 7i43 or 7i43_200, for a port "
					"given in io=\n",
					board[n], n + 1);
			return -EINVAL;
		}
	}
	comp_id = hal_init("sim_parport");
	if (comp_id < 0)
		return comp_id;
	sims = hal_malloc(num * (long)sizeof(*sims));
	if (!sims) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_parport: out of HAL memory\n");
		hal_exit(comp_id);
		return -ENOMEM;
	}
	for (n = 0; n < num; n++)
		sims[n].handle_lo = sims[n].handle_hi = -1;
	num_sims = num;
	for (n = 0; !err && n < num; n++) {
		struct sim_pp *s = &sims[n];

		rtapi_snprintf(s->name, sizeof(s->name), "sim-parport.%d", n);
		s->cable = !board[n] || !*board[n] ? CABLE_REGFILE :
			   !strcmp(board[n], "none") ? CABLE_NONE :
			   !strncmp(board[n], "7i43", 4) ? CABLE_7I43 : CABLE_PLUTO;
		s->pluto = 0;
		s->mesa = 0;
		s->epp_timeout = 0;
		err = export_sim(s, n);
		if (!err) {
			s->handle_lo = rtapi_iosim_register(io[n], 8, &lo_ops, s, s->name);
			err = s->handle_lo < 0 ? s->handle_lo : 0;
		}
		if (!err) {
			s->handle_hi = rtapi_iosim_register(io[n] + 0x400, 3, &hi_ops, s, s->name);
			err = s->handle_hi < 0 ? s->handle_hi : 0;
		}
	}
	if (err) {
		unregister_all();
		hal_exit(comp_id);
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	unregister_all();
	hal_exit(comp_id);
}
