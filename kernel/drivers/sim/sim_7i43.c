/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_7i43.c - the 7i43 on a simulated parallel port's cable (sim_7i43.h). HAL pins,
 * per port N: sim-parport.N.7i43.io.NNN.in (bit IN, what the outside drives onto IO
 * pin NNN, 0-47: P4 then P3) and .io.NNN.out (bit OUT, the connector level);
 * .unplugged (bit IN: no EPP cycle is answered, as with the cable pulled);
 * .done (bit OUT: the FPGA is configured); .config-bytes (u32 OUT: bytes clocked
 * into the configuration port since PROG_B was last released). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "hal.h"
#include "sim_7i43.h"
#include "../hostmot2/sim/hm2_sim_model.h"
#include "../hostmot2/sim/hm2_sim_fpgacfg.h"

#define RECONFIG_ADDR	0x7F7F
#define RECONFIG_BYTE	0x5A
#define AUTOINC		0x8000
#define IDROM_PTR	0x10C	/* where the IDROM offset is (hostmot2.md section 1) */
#define IDROM_FPGA_SIZE	0x14	/* the IDROM's FPGA size word */

struct sim_7i43 {
	hal_bit_t *io_in[SIM_MAX_PINS], *io_out[SIM_MAX_PINS];
	hal_bit_t *unplugged, *done;
	hal_u32_t *config_bytes;
	int fpga_k;
	/* CPLD */
	int prog_b;			/* the latch: 1 = released */
	int select_control;		/* last address cycle's bit 0 */
	struct hm2_sim_fpgacfg cfg;
	/* the configured FPGA: HostMot2's EPP front end and the register model */
	rtapi_u16 addr;
	int addr_high_next;		/* the next address write sets the high byte */
	rtapi_u32 wlatch, rlatch;
	struct hm2_sim_model model;
};

static int pin_bit(hal_pin_dir_t dir, hal_bit_t **p, int comp_id, int n, const char *what)
{
	return hal_pin_bit_newf(dir, p, comp_id, "sim-parport.%d.7i43.%s", n, what);
}

struct sim_7i43 *sim_7i43_new(int comp_id, int n, int fpga_k)
{
	const struct sim_layout *l = hm2_sim_layout_find("7i43");
	struct sim_7i43 *b = hal_malloc(sizeof(*b));
	int i, err = 0;

	if (!b || !l) {
		rtapi_print_msg(RTAPI_MSG_ERR, "sim_parport: %s\n", b ? "no 7i43 layout" :
				"out of HAL memory");
		return 0;
	}
	memset(b, 0, sizeof(*b));
	b->fpga_k = fpga_k;
	b->model.layout = l;
	b->model.num_pins = l->ports * l->port_width;
	for (i = 0; !err && i < b->model.num_pins; i++) {
		err = hal_pin_bit_newf(HAL_IN, &b->io_in[i], comp_id, "sim-parport.%d.7i43.io.%03d.in",
				       n, i);
		if (!err)
			err = hal_pin_bit_newf(HAL_OUT, &b->io_out[i], comp_id,
					       "sim-parport.%d.7i43.io.%03d.out", n, i);
	}
	if (!err) err = pin_bit(HAL_IN, &b->unplugged, comp_id, n, "unplugged");
	if (!err) err = pin_bit(HAL_OUT, &b->done, comp_id, n, "done");
	if (!err) err = hal_pin_u32_newf(HAL_OUT, &b->config_bytes, comp_id,
					 "sim-parport.%d.7i43.config-bytes", n);
	return err ? 0 : b;
}

/* PROG_B low: the FPGA forgets its configuration; the CPLD answers EPP again. */
static void unconfigure(struct sim_7i43 *b)
{
	hm2_sim_fpgacfg_clear(&b->cfg);
	*b->done = 0;
}

/* DONE rose: the firmware starts, with the IDROM of a board of this size. */
static void configured(struct sim_7i43 *b)
{
	struct hm2_sim_model *m = &b->model;

	hm2_sim_model_init(m, m->layout, SIM_FAULT_NONE, rtapi_get_time());
	m->mem[(hm2_sim_model_read(m, IDROM_PTR) + IDROM_FPGA_SIZE) / 4] = b->fpga_k;
	b->addr = 0;
	b->addr_high_next = 0;
	*b->done = 1;
}

void sim_7i43_spp(struct sim_7i43 *b, unsigned char control)
{
	if (!(control & 0x04))		/* /INIT low */
		unconfigure(b);
}

/* Before a HostMot2 transfer (it starts with an address cycle): the outside levels
 * in, the model's time forward. After a register write: the levels out. */
static void sync_in(struct sim_7i43 *b)
{
	struct hm2_sim_model *m = &b->model;
	int i;

	for (i = 0; i < m->num_pins; i++)
		m->ext_in[i] = *b->io_in[i];
	hm2_sim_model_advance(m, rtapi_get_time());
	m->transactions++;
}

static void sync_out(struct sim_7i43 *b)
{
	int i;

	for (i = 0; i < b->model.num_pins; i++)
		*b->io_out[i] = b->model.level[i];
}

static void next_data_cycle(struct sim_7i43 *b)
{
	if (b->addr & AUTOINC)
		b->addr = AUTOINC | ((b->addr + 1) & 0x7FFF);
	b->addr_high_next = 0;
}

int sim_7i43_epp_addr(struct sim_7i43 *b, unsigned char byte)
{
	if (*b->unplugged)
		return -1;
	if (!b->cfg.done) {
		b->select_control = byte & 1;
		return 0;
	}
	if (b->addr_high_next)
		b->addr = (rtapi_u16)((b->addr & 0x00FF) | byte << 8);
	else {
		b->addr = (rtapi_u16)((b->addr & 0xFF00) | byte);
		sync_in(b);
	}
	b->addr_high_next = !b->addr_high_next;
	return 0;
}

int sim_7i43_epp_addr_read(struct sim_7i43 *b, unsigned char *byte)
{
	if (*b->unplugged)
		return -1;
	if (!b->cfg.done)
		*byte = (unsigned char)b->select_control;
	else {
		*byte = (unsigned char)(b->addr_high_next ? b->addr >> 8 : b->addr);
		b->addr_high_next = !b->addr_high_next;
	}
	return 0;
}

int sim_7i43_epp_read(struct sim_7i43 *b, unsigned char *byte)
{
	rtapi_u32 a = b->addr & 0x7FFF;

	if (*b->unplugged)
		return -1;
	if (!b->cfg.done) {	/* CPLD: DONE, or the size bit (1 = 400K) */
		*byte = b->select_control ? 0 : b->fpga_k == 400;
		return 0;
	}
	if ((a & 3) == 0)	/* lane 0 fetches the word, lanes 1-3 come from the latch */
		b->rlatch = hm2_sim_model_read(&b->model, a);
	*byte = (unsigned char)(b->rlatch >> 8 * (a & 3));
	next_data_cycle(b);
	return 0;
}

int sim_7i43_epp_write(struct sim_7i43 *b, unsigned char byte)
{
	rtapi_u32 a = b->addr & 0x7FFF;

	if (*b->unplugged)
		return -1;
	if (!b->cfg.done) {
		if (b->select_control) {
			b->prog_b = byte & 1;
			if (!b->prog_b)
				unconfigure(b);
			*b->config_bytes = 0;
		} else if (b->prog_b) {
			hm2_sim_fpgacfg_byte(&b->cfg, byte);
			*b->config_bytes = b->cfg.bytes;
			if (b->cfg.done)
				configured(b);
		}
		return 0;
	}
	if (b->addr == RECONFIG_ADDR && byte == RECONFIG_BYTE) {
		/* the firmware's RECONFIG output: the CPLD pulses PROG_B */
		unconfigure(b);
		b->prog_b = 1;
		b->select_control = 1;
		return 0;
	}
	b->wlatch = (b->wlatch & ~(0xFFu << 8 * (a & 3))) | (rtapi_u32)byte << 8 * (a & 3);
	if ((a & 3) == 3) {	/* lane 3 commits the 32-bit write */
		hm2_sim_model_write(&b->model, a & ~3u, b->wlatch);
		sync_out(b);
	}
	next_data_cycle(b);
	return 0;
}
