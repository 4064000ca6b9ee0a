/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_boards.c - the board table (hm2_boards.h). Facts: hostmot2.md sections 12.1
 * and 13 (IDs, parts, connectors, LEDs) and hm2-transports.md (7i43, Ethernet). */
#include "rtapi.h"
#include "rtapi_string.h"
#include "rtapi_export.h"
#include "hm2_boards.h"

static const struct hm2_board_info boards[] = {
	{ "5i20", HM2_BUS_PCI, HM2_CFG_PLX9030, { "2s200pq208" }, 3, 24, 8, { "P2", "P3", "P4" } },
	{ "4i65", HM2_BUS_PCI, HM2_CFG_PLX9030, { "2s200pq208" }, 3, 24, 8, { "P1", "P3", "P4" } },
	{ "5i21", HM2_BUS_PCI, HM2_CFG_PLX9054, { "3s400pq208" }, 2, 32, 8, { "P1", "P1" } },
	{ "5i22", HM2_BUS_PCI, HM2_CFG_PLX9054, { "3s1000fg320", "3s1500fg320" }, 4, 24, 8,
	  { "P2", "P3", "P4", "P5" } },
	{ "5i23", HM2_BUS_PCI, HM2_CFG_PLX9054, { "3s400pq208" }, 3, 24, 2, { "P2", "P3", "P4" } },
	{ "4i68", HM2_BUS_PCI, HM2_CFG_PLX9054, { "3s400pq208" }, 3, 24, 4, { "P1", "P2", "P4" } },
	{ "4i69", HM2_BUS_PCI, HM2_CFG_PLX9054, { "6slx16ftg256", "6slx25ftg256" }, 3, 24, 0,
	  { "P1", "P3", "P4" } },
	{ "3x20", HM2_BUS_PCI, HM2_CFG_PLX9054, { "3s1000fg456", "3s1500fg456", "3s2000fg456" }, 6,
	  24, 0, { "P4", "P5", "P6", "P9", "P8", "P7" } },
	{ "5i24", HM2_BUS_PCI, HM2_CFG_FLASH, { "6slx16ftg256" }, 3, 24, 2, { "P4", "P3", "P2" } },
	{ "5i25", HM2_BUS_PCI, HM2_CFG_FLASH, { "6slx9tqg144", "t20f256" }, 2, 17, 2, { "P3", "P2" } },
	{ "6i25", HM2_BUS_PCI, HM2_CFG_FLASH, { "6slx9tqg144", "t20f256" }, 2, 17, 2, { "P3", "P2" } },
	{ "7i43", HM2_BUS_EPP, HM2_CFG_EPP_CPLD, { "3s200tq144", "3s400tq144" }, 2, 24, 8,
	  { "P4", "P3" } },
};

const struct hm2_board_info *hm2_board_at(int i)
{
	return i >= 0 && i < (int)(sizeof(boards) / sizeof(boards[0])) ? &boards[i] : 0;
}

const struct hm2_board_info *hm2_board_find(const char *name)
{
	const struct hm2_board_info *b;
	int i;

	for (i = 0; (b = hm2_board_at(i)); i++)
		if (strcmp(b->name, name) == 0)
			return b;
	return 0;
}

int hm2_board_fits(const struct hm2_board_info *b, const char *part)
{
	int i;

	if (b->config == HM2_CFG_FLASH)
		return 0;
	for (i = 0; i < HM2_BOARD_MAX_PARTS && b->part[i]; i++)
		if (strcmp(b->part[i], part) == 0)
			return 1;
	return 0;
}

/* for the board drivers (hm2_sim, hm2_pci, ...), which load after hostmot2 */
EXPORT_SYMBOL(hm2_board_find);
EXPORT_SYMBOL(hm2_board_at);
EXPORT_SYMBOL(hm2_board_fits);
