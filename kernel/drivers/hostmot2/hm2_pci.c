/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_pci.c - the board driver for Mesa's PCI, PCI Express and PC/104-Plus cards
 * (hm2_pci(9)):
 *   loadrt hostmot2
 *   loadrt hm2_pci config="firmware=hm2/5i20/SVST8_4.BIT num_encoders=3,num_stepgens=2"
 * Every card matching the ID table (vendor, device and subsystem IDs; hostmot2.md
 * 12.1) is taken, simulated cards first, then real ones in PCI bus order; config
 * entry k goes to the k-th card taken, named hm2_<board>.<N> (N counts cards of the
 * same type). The HostMot2 registers are one memory BAR; cards behind a PLX bridge
 * also have the bridge's registers (BAR1) and the FPGA's configuration data port
 * (BAR2), through which firmware= programs the FPGA (hm2_plx.c). The 5i24, 5i25 and
 * 6i25 boot from flash: no programming, firmware= ignored. In the kernel flavor the
 * cards come through a pci_driver, in the simulated flavor through sysfs (root). */
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_pci.h"
#include "rtapi_string.h"
#include "hal.h"
#include "hm2_llio.h"
#include "hm2_boards.h"
#include "hm2_plx.h"
#include "hm2_pci_ids.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Mesa PCI/PCIe Anything I/O cards with HostMot2 firmware");

#define MAX_BOARDS 4

static char *config[MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(config, MAX_BOARDS, "hostmot2 config string of each card, in probe order");

#define AS_ID(v, d, sv, sd, board, part) { v, d, sv, sd },
#define AS_CARD(v, d, sv, sd, board, part) { board, part },
static const struct rtapi_pci_id ids[] = { HM2_PCI_CARDS(AS_ID) { 0, 0, 0, 0 } };
static const struct { const char *board, *part; } cards[] = { HM2_PCI_CARDS(AS_CARD) };

struct pci_board {
	struct hm2_llio llio;
	const struct hm2_board_info *info;
	struct rtapi_pci_bar *mem;	/* HostMot2 registers */
	struct rtapi_pci_bar *ctrl;	/* PLX local registers (I/O) */
	struct rtapi_pci_bar *data;	/* FPGA configuration data port (I/O) */
};

static int comp_id;
static struct pci_board boards[MAX_BOARDS];
static int num_boards;

static int pci_read(struct hm2_llio *llio, rtapi_u32 addr, void *buf, int size)
{
	struct pci_board *b = llio->priv;
	rtapi_u32 *w = buf;
	int i;

	for (i = 0; i < size / 4; i++)
		w[i] = rtapi_pci_readl(b->mem, addr + 4 * i);
	return 0;
}

static int pci_write(struct hm2_llio *llio, rtapi_u32 addr, const void *buf, int size)
{
	struct pci_board *b = llio->priv;
	const rtapi_u32 *w = buf;
	int i;

	for (i = 0; i < size / 4; i++)
		rtapi_pci_writel(b->mem, addr + 4 * i, w[i]);
	return 0;
}

static int plx9030_reset(struct hm2_llio *llio)
{
	return hm2_plx9030_reset(((struct pci_board *)llio->priv)->ctrl, llio->name);
}

static int plx9030_program(struct hm2_llio *llio, const void *bitstream, rtapi_u32 size)
{
	struct pci_board *b = llio->priv;

	return hm2_plx9030_program(b->ctrl, b->data, bitstream, size, llio->name);
}

static int plx9054_reset(struct hm2_llio *llio)
{
	return hm2_plx9054_reset(((struct pci_board *)llio->priv)->ctrl, llio->name);
}

static int plx9054_program(struct hm2_llio *llio, const void *bitstream, rtapi_u32 size)
{
	struct pci_board *b = llio->priv;

	return hm2_plx9054_program(b->ctrl, b->data, bitstream, size, llio->name);
}

static void unmap_board(struct pci_board *b)
{
	if (b->mem)
		rtapi_pci_unmap_bar(b->mem);
	if (b->ctrl)
		rtapi_pci_unmap_bar(b->ctrl);
	if (b->data)
		rtapi_pci_unmap_bar(b->data);
	b->mem = b->ctrl = b->data = 0;
}

/* The BARs of the card's bridge: the HostMot2 window, and for PLX cards the
 * bridge's registers and the configuration data port. */
static int map_board(struct pci_board *b, struct rtapi_pci_dev *dev)
{
	int cfg = b->info->config, rc;

	if (cfg == HM2_CFG_FLASH)
		return rtapi_pci_dev_map_bar(dev, HM2_PCI_BAR_DIRECT, &b->mem);
	rc = rtapi_pci_dev_map_bar(dev, cfg == HM2_CFG_PLX9030 ? HM2_PCI_BAR_9030 : HM2_PCI_BAR_9054,
				   &b->mem);
	if (!rc)
		rc = rtapi_pci_dev_map_bar(dev, HM2_PCI_BAR_PLX, &b->ctrl);
	if (!rc)
		rc = rtapi_pci_dev_map_bar(dev, HM2_PCI_BAR_CFGDATA, &b->data);
	return rc;
}

static int hm2_pci_probe(struct rtapi_pci_dev *dev, const struct rtapi_pci_id *id)
{
	int card = (int)(id - ids), same = 0, i, rc;
	struct pci_board *b = &boards[num_boards];
	const struct hm2_board_info *info = hm2_board_find(cards[card].board);

	if (num_boards == MAX_BOARDS) {
		rtapi_print_msg(RTAPI_MSG_WARN, "hm2_pci: skipping the %s at %s: this driver takes "
				"at most %d cards\n", cards[card].board, rtapi_pci_dev_name(dev),
				MAX_BOARDS);
		return 1;
	}
	if (!info)
		return -EINVAL;	/* the two tables disagree: caught by the tests */
	for (i = 0; i < num_boards; i++)
		if (boards[i].info == info)
			same++;
	memset(b, 0, sizeof(*b));
	b->info = info;
	rtapi_snprintf(b->llio.name, sizeof(b->llio.name), "hm2_%s.%d", info->name, same);
	rc = map_board(b, dev);
	if (rc) {
		unmap_board(b);
		return rc;
	}
	rtapi_print_msg(RTAPI_MSG_INFO, "hm2_pci: %s is a %s at %s\n", b->llio.name, info->name,
			rtapi_pci_dev_name(dev));
	b->llio.comp_id = comp_id;
	b->llio.num_ioport_connectors = info->connectors;
	b->llio.pins_per_connector = info->pins_per_connector;
	for (i = 0; i < info->connectors && i < HM2_LLIO_MAX_CONNECTORS; i++)
		b->llio.ioport_connector_name[i] = info->connector[i];
	b->llio.num_leds = info->leds;
	b->llio.threadsafe = 1;
	b->llio.read = pci_read;
	b->llio.write = pci_write;
	b->llio.priv = b;
	if (info->config == HM2_CFG_PLX9030) {
		hm2_plx9030_fix_ready(b->ctrl, b->llio.name);
		b->llio.reset = plx9030_reset;
		b->llio.program_fpga = plx9030_program;
	} else if (info->config == HM2_CFG_PLX9054) {
		b->llio.reset = plx9054_reset;
		b->llio.program_fpga = plx9054_program;
	}
	if (b->llio.program_fpga)
		b->llio.fpga_part_number = cards[card].part;
	rc = hm2_register(&b->llio, config[num_boards]);
	if (rc) {
		unmap_board(b);
		return rc;
	}
	rtapi_pci_set_drvdata(dev, b);
	num_boards++;
	return 0;
}

static void hm2_pci_remove(struct rtapi_pci_dev *dev)
{
	struct pci_board *b = rtapi_pci_get_drvdata(dev);

	hm2_unregister(&b->llio);
	unmap_board(b);
}

static struct rtapi_pci_driver driver = {
	.name = "hm2_pci", .ids = ids, .probe = hm2_pci_probe, .remove = hm2_pci_remove,
};

int rtapi_app_main(void)
{
	int rc, k;

	comp_id = hal_init("hm2_pci");
	if (comp_id < 0)
		return comp_id;
	num_boards = 0;
	rc = rtapi_pci_register_driver(&driver);
	if (rc == 0) {
		rtapi_print_msg(RTAPI_MSG_ERR, "hm2_pci: no Mesa PCI card found (5i20, 4i65, 5i21, "
				"5i22, 5i23, 4i68, 4i69, 3x20, 5i24, 5i25, 6i25)\n");
		rc = -ENODEV;
		rtapi_pci_unregister_driver(&driver);
	}
	for (k = num_boards; rc > 0 && k < MAX_BOARDS; k++)
		if (config[k] && *config[k]) {
			rtapi_print_msg(RTAPI_MSG_ERR, "hm2_pci: config entry %d (\"%s\") has no card: "
					"%d found\n", k + 1, config[k], num_boards);
			rtapi_pci_unregister_driver(&driver);
			rc = -EINVAL;
		}
	if (rc < 0) {
		hal_exit(comp_id);
		return rc;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	rtapi_pci_unregister_driver(&driver);
	hal_exit(comp_id);
}
