/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_board.h - one board of hm2_sim (hm2_sim.c), shared with its PCI front
 * (hm2_sim_pci.c): the register model, the HAL pins of the world outside the card,
 * the FPGA's configuration port and, on a simulated PCI card, the PLX bridge. */
#ifndef HM2_SIM_BOARD_H
#define HM2_SIM_BOARD_H

#include "rtapi.h"
#include "hal.h"
#include "../hm2_llio.h"
#include "hm2_sim_model.h"
#include "hm2_sim_fpgacfg.h"
#include "hm2_sim_plx.h"

#define HM2_SIM_MAX_QUEUE 64
#define HM2_SIM_MAX_QUEUED_WRITE_WORDS 1024

struct hm2_sim_queued_read {
	rtapi_u32 addr;
	void *buf;
	int size;
};

struct sim_board {
	struct hm2_llio llio;
	struct hm2_sim_model model;
	hal_bit_t **io_in, **io_out;	/* per IO pin */
	hal_u32_t *bus_words;
	hal_bit_t *bus_error;		/* in: every transfer fails (a cable pulled) */
	hal_bit_t *mux_in[SIM_MAX_INST][3];	/* muxed encoders: A, B, index */
	hal_s32_t *dac[SIM_7I65_CHANNELS];
	hal_bit_t *enable[SIM_7I65_CHANNELS], *din[SIM_7I65_INPUTS], *card_bitten;
	struct hm2_sim_queued_read rq[HM2_SIM_MAX_QUEUE];
	int num_rq;
	rtapi_u32 wq_addr[HM2_SIM_MAX_QUEUED_WRITE_WORDS], wq_val[HM2_SIM_MAX_QUEUED_WRITE_WORDS];
	int num_wq;
	int registered;
	int fault;			/* enum sim_fault, kept across programming */
	struct hm2_sim_fpgacfg fpga;	/* done = 0: unconfigured, registers read 0 */
	/* bus=pci: the simulated PCI card */
	int pci_handle;			/* rtapi_pcisim handle, -1: none */
	struct hm2_sim_plx plx;		/* PLX cards */
	int plx_card;			/* 1: behind a PLX bridge */
	char pci_name[24];
};

/* Before a transaction: the outside world's levels in, the model's time forward.
 * After it: the connector levels and the bus counters out. */
void hm2_sim_sync_in(struct sim_board *b);
void hm2_sim_sync_out(struct sim_board *b);

/* bus=pci: the board as a simulated PCI card called 'card' (a board of
 * hm2_pci_ids.h whose shape is the layout's), with one PLX fault. 0 or -errno after
 * a message. */
int hm2_sim_pci_attach(struct sim_board *b, int k, const char *card, enum sim_plx_fault fault);
void hm2_sim_pci_detach(struct sim_board *b);
/* the PLX faults fault= takes in bus=pci ("no-done", ...): enum sim_plx_fault or -1 */
int hm2_sim_plx_fault_find(const char *name);

#endif /* HM2_SIM_BOARD_H */
