/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim.c - a board driver for a simulated HostMot2 card. Each board is a register
 * model (hm2_sim_model.c) with a real IDROM, registered with hostmot2 exactly like a
 * PCI or Ethernet card, so a configuration written for hm2_5i25.0 runs unchanged
 * on the real card:
 *   loadrt hostmot2
 *   loadrt hm2_sim board=5i25 config="num_encoders=1 num_stepgens=3"
 * board= and config= are comma-separated arrays, one entry per board (up to 4);
 * fault= puts one IDROM defect into a board (tests of the driver's refusals).
 * The world outside the card: pins hm2_sim.K.io.NNN.in (what outside devices drive
 * onto IO pin NNN; encoders count from these) and hm2_sim.K.io.NNN.out (the level on
 * the connector), K = board index in this module. Boards with muxed encoders have
 * hm2_sim.K.mux.NN.a/.b/.index (what encoder NN behind the outside multiplexer
 * drives); a board with a 7i65 on its BSPI has hm2_sim.K.7i65.dac-M (the DAC code,
 * +-32767 = +-10 V), .enable-M, .watchdog-bitten (outputs) and .digital-in-M. Reads are batched (queued and
 * sent as one request per cycle); hm2_sim.K.bus-words counts the 32-bit
 * words moved; hm2_sim.K.bus-error TRUE makes every transfer fail (hostmot2's
 * io_error recovery). Boards whose real card is programmed by the driver (5i20)
 * take firmware=: the bitstream goes, bit-reversed as on the card, into a model of
 * the FPGA's configuration port (hm2_sim_fpgacfg.c) that raises DONE only for a
 * Xilinx bitstream in the right bit order; until then the registers read 0.
 * bus=pci shows the boards as simulated Mesa PCI cards instead (hm2_sim_pci.c: the
 * card's IDs and BARs, a PLX bridge model on the 5i20, 4i65, 5i23, 4i68, 4i69) for
 * hm2_pci to find and register: loadrt hm2_sim bus=pci board=5i20; loadrt hm2_pci. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_string.h"
#include "hal.h"
#include "../hm2_llio.h"
#include "hm2_sim_board.h"
#include "../hm2_bitfile.h"
#include "../hm2_boards.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Simulated Mesa HostMot2 board for hostmot2");

#define MAX_BOARDS 4
#define MAX_QUEUE HM2_SIM_MAX_QUEUE
#define MAX_QUEUED_WRITE_WORDS HM2_SIM_MAX_QUEUED_WRITE_WORDS

static char *board[MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(board, MAX_BOARDS, "simulated boards: 5i25 (7i76 step/dir), 5i20 (SVST8_4), 5i23 (7i65, muxed encoders, 3pwmgen, UART), 5i22, 5i21, 3x20, 7i43 (SVST4_4); bus=pci: also 6i25, 4i65, 4i68, 4i69, 5i24");
static char *config[MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(config, MAX_BOARDS, "hostmot2 config string of each board");
static char *fault[MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(fault, MAX_BOARDS, "IDROM defect to present (driver tests); bus=pci: or a PLX fault (no-done, done-stuck, init-stuck)");
static char *bus = "";
RTAPI_MP_STRING(bus, "pci: show the boards as simulated PCI cards for hm2_pci instead of registering them");

static int comp_id;
static struct sim_board *boards;
static int num_boards;

/* Before a transaction: the outside world's levels in, the model's time forward. */
void hm2_sim_sync_in(struct sim_board *b)
{
	struct hm2_sim_model *m = &b->model;
	int i;

	for (i = 0; i < m->num_pins; i++)
		m->ext_in[i] = *b->io_in[i];
	for (i = 0; i < m->qc[1].num && i < SIM_MAX_INST; i++) {
		m->mux_in[i][0] = *b->mux_in[i][0];
		m->mux_in[i][1] = *b->mux_in[i][1];
		m->mux_in[i][2] = *b->mux_in[i][2];
	}
	if (m->layout->bspi_7i65)
		for (i = 0; i < SIM_7I65_INPUTS; i++)
			m->card.din[i] = *b->din[i];
	hm2_sim_model_advance(m, rtapi_get_time());
	m->transactions++;
}

/* After it: the connector levels (writes may have changed them) and the counter. */
void hm2_sim_sync_out(struct sim_board *b)
{
	struct hm2_sim_model *m = &b->model;
	int i;

	for (i = 0; i < m->num_pins; i++)
		*b->io_out[i] = m->level[i];
	*b->bus_words = m->words_read + m->words_written;
	if (!m->layout->bspi_7i65)
		return;
	for (i = 0; i < SIM_7I65_CHANNELS; i++) {
		*b->dac[i] = m->card.dac[i];
		*b->enable[i] = (m->card.enables >> i) & 1;
	}
	*b->card_bitten = m->card.bitten;
}

static int check(rtapi_u32 addr, int size)
{
	return (size <= 0 || (size & 3) || (addr & 3) || addr + size > 0x10000) ? -EINVAL : 0;
}

/* the board's bus-error pin: a transport failure, as a pulled cable gives */
static int bus_down(struct sim_board *b)
{
	return b->bus_error && *b->bus_error;
}

static int sim_read(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size)
{
	struct sim_board *b = llio->priv;
	rtapi_u32 *w = buf;
	int i;

	if (check(addr, size))
		return -EINVAL;
	if (bus_down(b))
		return -EIO;
	hm2_sim_sync_in(b);
	for (i = 0; i < size / 4; i++)
		w[i] = b->fpga.done ? hm2_sim_model_read(&b->model, addr + 4 * i) : 0;
	hm2_sim_sync_out(b);
	return 0;
}

static int sim_write(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size)
{
	struct sim_board *b = llio->priv;
	const rtapi_u32 *w = buf;
	int i;

	if (check(addr, size))
		return -EINVAL;
	if (bus_down(b))
		return -EIO;
	hm2_sim_sync_in(b);
	for (i = 0; i < size / 4 && b->fpga.done; i++)
		hm2_sim_model_write(&b->model, addr + 4 * i, w[i]);
	hm2_sim_sync_out(b);
	return 0;
}

static int sim_queue_read(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size)
{
	struct sim_board *b = llio->priv;

	if (check(addr, size) || b->num_rq >= MAX_QUEUE)
		return -EINVAL;
	b->rq[b->num_rq].addr = addr;
	b->rq[b->num_rq].buf = buf;
	b->rq[b->num_rq].size = size;
	b->num_rq++;
	return 0;
}

/* one request: every queued read sees the board at the same instant */
static int sim_send_queued_reads(struct hm2_llio *llio)
{
	struct sim_board *b = llio->priv;
	int i, j;

	if (bus_down(b)) {
		b->num_rq = 0;
		return -EIO;
	}
	hm2_sim_sync_in(b);
	for (i = 0; i < b->num_rq; i++) {
		rtapi_u32 *w = b->rq[i].buf;

		for (j = 0; j < b->rq[i].size / 4; j++)
			w[j] = b->fpga.done ? hm2_sim_model_read(&b->model, b->rq[i].addr + 4 * j) : 0;
	}
	b->num_rq = 0;
	hm2_sim_sync_out(b);
	return 0;
}

static int sim_receive_queued_reads(struct hm2_llio *llio)
{
	return 0;	/* the data arrived with the request */
}

static int sim_send_queued_writes(struct hm2_llio *llio)
{
	struct sim_board *b = llio->priv;
	int i;

	if (!b->num_wq)
		return 0;
	if (bus_down(b)) {
		b->num_wq = 0;
		return -EIO;
	}
	hm2_sim_sync_in(b);
	for (i = 0; i < b->num_wq && b->fpga.done; i++)
		hm2_sim_model_write(&b->model, b->wq_addr[i], b->wq_val[i]);
	b->num_wq = 0;
	hm2_sim_sync_out(b);
	return 0;
}

static int sim_queue_write(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size)
{
	struct sim_board *b = llio->priv;
	const rtapi_u32 *w = buf;
	int i;

	if (check(addr, size))
		return -EINVAL;
	if (b->num_wq + size / 4 > MAX_QUEUED_WRITE_WORDS)
		sim_send_queued_writes(llio);	/* a full packet goes out early */
	for (i = 0; i < size / 4; i++) {
		b->wq_addr[b->num_wq] = addr + 4 * i;
		b->wq_val[b->num_wq] = w[i];
		b->num_wq++;
	}
	return 0;
}

/* PROG_B: the FPGA forgets its configuration, and the model its register state */
static int sim_reset(struct hm2_llio *llio)
{
	struct sim_board *b = llio->priv;

	hm2_sim_fpgacfg_clear(&b->fpga);
	return 0;
}

static int sim_program_fpga(struct hm2_llio *llio, const void *bitstream, rtapi_u32 size)
{
	struct sim_board *b = llio->priv;
	const rtapi_u8 *p = bitstream;
	rtapi_u32 i;

	for (i = 0; i < size; i++)
		hm2_sim_fpgacfg_byte(&b->fpga, hm2_bitfile_reverse(p[i]));
	if (!b->fpga.done) {
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: the FPGA did not assert DONE after %u bytes (%s)\n",
				llio->name, size, b->fpga.synced ? "no DESYNC command at the end" :
				"no Xilinx sync word in the expected bit order");
		return -EIO;
	}
	hm2_sim_model_init(&b->model, b->model.layout, b->fault, rtapi_get_time());
	return 0;
}

static int export_board(struct sim_board *b, int k)
{
	int n = b->model.num_pins, i, rc;

	b->io_in = hal_malloc(n * sizeof(*b->io_in));
	b->io_out = hal_malloc(n * sizeof(*b->io_out));
	if (!b->io_in || !b->io_out)
		return -ENOMEM;
	rc = hal_pin_u32_newf(HAL_OUT, &b->bus_words, comp_id, "hm2_sim.%d.bus-words", k);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_IN, &b->bus_error, comp_id, "hm2_sim.%d.bus-error", k);
	for (i = 0; i < n && !rc; i++) {
		rc = hal_pin_bit_newf(HAL_IN, &b->io_in[i], comp_id, "hm2_sim.%d.io.%03d.in", k, i);
		if (!rc)
			rc = hal_pin_bit_newf(HAL_OUT, &b->io_out[i], comp_id, "hm2_sim.%d.io.%03d.out", k, i);
	}
	for (i = 0; i < b->model.qc[1].num && i < SIM_MAX_INST && !rc; i++) {
		rc = hal_pin_bit_newf(HAL_IN, &b->mux_in[i][0], comp_id, "hm2_sim.%d.mux.%02d.a", k, i);
		if (!rc)
			rc = hal_pin_bit_newf(HAL_IN, &b->mux_in[i][1], comp_id, "hm2_sim.%d.mux.%02d.b", k, i);
		if (!rc)
			rc = hal_pin_bit_newf(HAL_IN, &b->mux_in[i][2], comp_id, "hm2_sim.%d.mux.%02d.index",
					      k, i);
	}
	if (!b->model.layout->bspi_7i65)
		return rc;
	for (i = 0; i < SIM_7I65_CHANNELS && !rc; i++) {
		rc = hal_pin_s32_newf(HAL_OUT, &b->dac[i], comp_id, "hm2_sim.%d.7i65.dac-%d", k, i);
		if (!rc)
			rc = hal_pin_bit_newf(HAL_OUT, &b->enable[i], comp_id, "hm2_sim.%d.7i65.enable-%d", k, i);
	}
	for (i = 0; i < SIM_7I65_INPUTS && !rc; i++)
		rc = hal_pin_bit_newf(HAL_IN, &b->din[i], comp_id, "hm2_sim.%d.7i65.digital-in-%d", k, i);
	if (!rc)
		rc = hal_pin_bit_newf(HAL_OUT, &b->card_bitten, comp_id, "hm2_sim.%d.7i65.watchdog-bitten", k);
	return rc;
}

/* bus=pci: the board becomes a simulated PCI card with the card's IDs and BARs;
 * hm2_pci finds it and registers it. A card without a layout of its own gets the
 * first layout of its shape (6i25: the 5i25's; 4i65, 4i68, 4i69, 5i24: the 5i20's). */
static int setup_pci_board(int k, const char *name, const char *cfg, const char *fault_name)
{
	const struct hm2_board_info *info = hm2_board_find(name);
	const struct sim_layout *l = hm2_sim_layout_find(name);
	struct sim_board *b = &boards[k];
	int f = SIM_FAULT_NONE, pf = SIM_PLX_OK, rc;

	if (!l && info)
		l = hm2_sim_layout_shaped(info->connectors, info->pins_per_connector);
	if (!l || !info) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: board=%s: no simulated PCI card of that name; "
				"known: 5i25, 6i25, 5i20, 4i65, 5i23, 4i68, 4i69, 5i24, 5i22, 5i21, 3x20\n", name);
		return -EINVAL;
	}
	if (cfg && *cfg) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: config= with bus=pci: give it to hm2_pci\n");
		return -EINVAL;
	}
	if (fault_name && *fault_name) {
		pf = hm2_sim_plx_fault_find(fault_name);
		f = pf < 0 ? hm2_sim_fault_find(fault_name) : SIM_FAULT_NONE;
		if (f < 0) {
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: fault=%s: unknown fault; known: %s, "
					"no-done, done-stuck, init-stuck\n", fault_name,
					hm2_sim_fault_names());
			return -EINVAL;
		}
		if (pf < 0)
			pf = SIM_PLX_OK;
	}
	hm2_sim_model_init(&b->model, l, f, rtapi_get_time());
	b->fault = f;
	b->fpga.done = 1;	/* configured by an earlier load, until firmware= resets it */
	rc = export_board(b, k);
	if (!rc)
		rc = hm2_sim_pci_attach(b, k, name, pf);
	if (!rc)
		rtapi_print_msg(RTAPI_MSG_INFO, "hm2_sim: board %d is a simulated PCI %s running %s\n",
				k, name, l->firmware);
	return rc;
}

static int setup_board(int k, const char *name, const char *cfg, const char *fault_name)
{
	const struct sim_layout *l = hm2_sim_layout_find(name);
	struct sim_board *b = &boards[k];
	const struct hm2_board_info *info;
	int f = SIM_FAULT_NONE, same = 0, i, rc;

	if (!l) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: board=%s: unknown board; known: %s\n", name,
				hm2_sim_layout_names());
		return -EINVAL;
	}
	if (fault_name && *fault_name) {
		f = hm2_sim_fault_find(fault_name);
		if (f < 0) {
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: fault=%s: unknown fault; known: %s\n",
					fault_name, hm2_sim_fault_names());
			return -EINVAL;
		}
	}
	for (i = 0; i < k; i++)
		if (strcmp(boards[i].model.layout->board, l->board) == 0)
			same++;
	hm2_sim_model_init(&b->model, l, f, rtapi_get_time());
	b->fault = f;
	rtapi_snprintf(b->llio.name, sizeof(b->llio.name), "hm2_%s.%d", l->board, same);
	b->llio.comp_id = comp_id;
	b->llio.num_ioport_connectors = l->ports;
	b->llio.pins_per_connector = l->port_width;
	for (i = 0; i < l->ports && i < HM2_LLIO_MAX_CONNECTORS; i++)
		b->llio.ioport_connector_name[i] = l->connector[i];
	b->llio.num_leds = l->num_leds;
	b->llio.threadsafe = 1;
	b->llio.split_read = 0;	/* a PCI-like board: read() sends its own request */
	b->llio.read = sim_read;
	b->llio.write = sim_write;
	b->llio.queue_read = sim_queue_read;
	b->llio.send_queued_reads = sim_send_queued_reads;
	b->llio.receive_queued_reads = sim_receive_queued_reads;
	b->llio.queue_write = sim_queue_write;
	b->llio.send_queued_writes = sim_send_queued_writes;
	b->llio.priv = b;
	b->fpga.done = 1;	/* configured by an earlier load, until firmware= resets it */
	info = hm2_board_find(l->board);
	if (info && info->config != HM2_CFG_FLASH) {
		b->llio.fpga_part_number = info->part[0];
		b->llio.reset = sim_reset;
		b->llio.program_fpga = sim_program_fpga;
	}
	rc = export_board(b, k);
	if (rc)
		return rc;
	rtapi_print_msg(RTAPI_MSG_INFO, "hm2_sim: board %d is a simulated %s running %s\n", k,
			l->board, l->firmware);
	rc = hm2_register(&b->llio, cfg);
	if (rc)
		return rc;
	b->registered = 1;
	return 0;
}

static void release_boards(void)
{
	int k;

	for (k = 0; k < num_boards; k++) {
		if (boards[k].registered)
			hm2_unregister(&boards[k].llio);
		hm2_sim_pci_detach(&boards[k]);
	}
}

/* board k of the module parameters, registered or (bus=pci) shown as a PCI card */
static int setup_entry(int k)
{
	if (strcmp(bus, "pci") == 0)
		return setup_pci_board(k, board[k], config[k], fault[k]);
	return setup_board(k, board[k], config[k], fault[k]);
}

int rtapi_app_main(void)
{
	int k;

	comp_id = hal_init("hm2_sim");
	if (comp_id < 0)
		return comp_id;
	for (num_boards = 0; num_boards < MAX_BOARDS && board[num_boards] && *board[num_boards];)
		num_boards++;
	if (!num_boards) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: board= is required (%s)\n", hm2_sim_layout_names());
		hal_exit(comp_id);
		return -EINVAL;
	}
	for (k = num_boards; k < MAX_BOARDS; k++) {
		if ((config[k] && *config[k]) || (fault[k] && *fault[k])) {
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: config= or fault= entry %d has no board= entry\n",
					k);
			hal_exit(comp_id);
			return -EINVAL;
		}
	}
	boards = hal_malloc(num_boards * sizeof(*boards));
	if (!boards) {
		hal_exit(comp_id);
		return -ENOMEM;
	}
	if (strcmp(bus, "") != 0 && strcmp(bus, "pci") != 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: bus=%s: unknown; bus=pci or none\n", bus);
		hal_exit(comp_id);
		return -EINVAL;
	}
	for (k = 0; k < num_boards; k++)
		boards[k].pci_handle = -1;
	return hm2_llio_setup_boards(comp_id, num_boards, setup_entry, release_boards);
}

void rtapi_app_exit(void)
{
	release_boards();
	hal_exit(comp_id);
}
