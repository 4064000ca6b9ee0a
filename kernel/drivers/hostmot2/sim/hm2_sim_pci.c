/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_pci.c - hm2_sim bus=pci: a simulated board shown as a Mesa PCI card
 * (rtapi_pci.h's simulated cards) for hm2_pci to find, with the card's IDs and BARs
 * (hostmot2.md 12.1): the HostMot2 window in front of the register model, and on
 * PLX cards the bridge's registers (BAR0 memory and BAR1 I/O, the same registers)
 * and the FPGA's configuration data port (BAR2) in front of the PLX model
 * (hm2_sim_plx.c) and the configuration port model (hm2_sim_fpgacfg.c). */
#include "rtapi.h"
#include "rtapi_pci.h"
#include "rtapi_string.h"
#include "hm2_sim_board.h"
#include "../hm2_boards.h"
#include "../hm2_pci_ids.h"

#define WINDOW_LEN 0x10000
#define PLX_LEN 256

#define AS_CARD(v, d, sv, sd, board, part) { { v, d, sv, sd }, board },
static const struct {
	struct rtapi_pci_id id;
	const char *board;
} cards[] = { HM2_PCI_CARDS(AS_CARD) };

static int window_bar(const struct sim_board *b)
{
	if (!b->plx_card)
		return HM2_PCI_BAR_DIRECT;
	return b->plx.type == SIM_PLX_9030 ? HM2_PCI_BAR_9030 : HM2_PCI_BAR_9054;
}

static rtapi_u32 card_read(void *dev, int bar, unsigned long offset, int size)
{
	struct sim_board *b = dev;
	rtapi_u32 v;

	if (bar == window_bar(b)) {
		if (size != 4 || (b->plx_card && !hm2_sim_plx_window_ok(&b->plx)))
			return ~0u;	/* no READY#: the bridge times out */
		hm2_sim_sync_in(b);
		v = b->fpga.done ? hm2_sim_model_read(&b->model, (rtapi_u32)offset) : 0;
		hm2_sim_sync_out(b);
		return v;
	}
	if (bar == HM2_PCI_BAR_CFGDATA)
		return size == 1 ? 0xff : ~0u;	/* write-only port */
	v = hm2_sim_plx_read(&b->plx, offset & ~3ul);
	return size == 1 ? (v >> (8 * (offset & 3))) & 0xff : v;
}

static void card_write(void *dev, int bar, unsigned long offset, int size, rtapi_u32 value)
{
	struct sim_board *b = dev;

	if (bar == window_bar(b)) {
		if (size != 4 || (b->plx_card && !hm2_sim_plx_window_ok(&b->plx)))
			return;
		hm2_sim_sync_in(b);
		if (b->fpga.done)
			hm2_sim_model_write(&b->model, (rtapi_u32)offset, value);
		hm2_sim_sync_out(b);
	} else if (bar == HM2_PCI_BAR_CFGDATA) {
		/* configured: the FPGA starts with its registers at power-up values */
		if (size == 1 && hm2_sim_plx_data(&b->plx, (rtapi_u8)value))
			hm2_sim_model_init(&b->model, b->model.layout, b->fault, rtapi_get_time());
	} else if (size == 4) {
		hm2_sim_plx_write(&b->plx, offset, value);
	}
}

static const struct rtapi_pcisim_ops card_ops = { .read = card_read, .write = card_write };

static const char *const plx_faults[] = { "", "no-done", "done-stuck", "init-stuck" };

int hm2_sim_plx_fault_find(const char *name)
{
	int i;

	for (i = 1; i < (int)(sizeof(plx_faults) / sizeof(plx_faults[0])); i++)
		if (strcmp(plx_faults[i], name) == 0)
			return i;
	return -1;
}

int hm2_sim_pci_attach(struct sim_board *b, int k, const char *card, enum sim_plx_fault fault)
{
	const struct hm2_board_info *info = hm2_board_find(card);
	struct rtapi_pcisim_card c;
	unsigned i;

	memset(&c, 0, sizeof(c));
	for (i = 0; i < sizeof(cards) / sizeof(cards[0]); i++)
		if (strcmp(cards[i].board, card) == 0) {
			c.id = cards[i].id;
			break;
		}
	if (!info || !c.id.vendor) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: board=%s: not a Mesa PCI card\n", card);
		return -EINVAL;
	}
	b->plx_card = info->config != HM2_CFG_FLASH;
	if (!b->plx_card && fault != SIM_PLX_OK) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_sim: fault=%s: the %s has no PLX bridge\n",
				plx_faults[fault], card);
		return -EINVAL;
	}
	if (b->plx_card) {
		hm2_sim_plx_init(&b->plx, info->config == HM2_CFG_PLX9030 ? SIM_PLX_9030 : SIM_PLX_9054,
				 fault, &b->fpga);
		c.bar_len[0] = PLX_LEN;
		c.bar_len[HM2_PCI_BAR_PLX] = PLX_LEN;
		c.bar_len[HM2_PCI_BAR_CFGDATA] = PLX_LEN;
	}
	c.bar_len[window_bar(b)] = WINDOW_LEN;
	rtapi_snprintf(b->pci_name, sizeof(b->pci_name), "hm2_sim.%d (%s)", k, card);
	b->pci_handle = rtapi_pcisim_register_card(&c, &card_ops, b, b->pci_name);
	return b->pci_handle < 0 ? b->pci_handle : 0;
}

void hm2_sim_pci_detach(struct sim_board *b)
{
	if (b->pci_handle >= 0)
		rtapi_pcisim_unregister(b->pci_handle);
	b->pci_handle = -1;
}
