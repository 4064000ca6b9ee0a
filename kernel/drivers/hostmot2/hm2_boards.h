/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_boards.h - what the board drivers declare about each Mesa card: HAL name,
 * FPGA part strings (a .BIT file's 'b' chunk must equal one), connectors in IOPort
 * order, pins per connector, LEDs, and how the FPGA is configured. One table for
 * hm2_pci, hm2_7i43, hm2_eth, hm2_sim and the hm2-bitinfo tool ("which boards does
 * this bitfile fit"). HAL-free and libc-free. */
#ifndef HM2_BOARDS_H
#define HM2_BOARDS_H

#include "rtapi.h"

#define HM2_BOARD_MAX_PARTS 3
#define HM2_BOARD_MAX_CONNECTORS 6

enum hm2_board_bus { HM2_BUS_PCI, HM2_BUS_EPP };

/* how the FPGA gets its configuration */
enum hm2_board_config {
	HM2_CFG_PLX9030,	/* firmware= through the PLX 9030 GPIO + data port */
	HM2_CFG_PLX9054,	/* PLX 9054/9056 */
	HM2_CFG_EPP_CPLD,	/* the 7i43's CPLD over EPP */
	HM2_CFG_FLASH,		/* boots from its own flash; firmware= is ignored (mesaflash) */
};

struct hm2_board_info {
	const char *name;			/* "5i20": HAL prefix hm2_5i20.N */
	enum hm2_board_bus bus;
	enum hm2_board_config config;
	const char *part[HM2_BOARD_MAX_PARTS];	/* FPGA part strings, NULL-terminated */
	int connectors, pins_per_connector, leds;
	const char *connector[HM2_BOARD_MAX_CONNECTORS];	/* IOPort order */
};

/* The board called name ("5i20"), or NULL. */
const struct hm2_board_info *hm2_board_find(const char *name);
/* The i-th board of the table (0, 1, ...), NULL past the end. */
const struct hm2_board_info *hm2_board_at(int i);
/* 1 when board can be configured with a bitfile for part (programmable, same die). */
int hm2_board_fits(const struct hm2_board_info *b, const char *part);

#endif /* HM2_BOARDS_H */
