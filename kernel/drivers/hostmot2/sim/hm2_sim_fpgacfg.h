/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_fpgacfg.h - a model of a Xilinx FPGA's parallel configuration port, the
 * part of the simulated cards that firmware= programs (hm2_sim's programmable
 * boards; the PLX and 7i43-CPLD models hand it their data-port bytes). It checks
 * what matters to a driver: the bit order. The Mesa cards wire the port so that a
 * .BIT file's bytes must be sent bit-reversed; the model undoes that reversal and
 * looks for the Xilinx sync word 0xAA995566, then for the DESYNC command (a type-1
 * write to the CMD register, 0x30008001 0x0000000D) that ends every configuration:
 * only then is DONE raised. Bytes sent in file order never show the sync word, so
 * DONE stays low, as on the card. Integer-only. */
#ifndef HM2_SIM_FPGACFG_H
#define HM2_SIM_FPGACFG_H

#include "rtapi.h"

#define FPGACFG_SYNC	0xAA995566u
#define FPGACFG_CMD_HDR	0x30008001u	/* type 1, write, CMD register, 1 word */
#define FPGACFG_DESYNC	0x0000000Du

struct hm2_sim_fpgacfg {
	int done;		/* DONE pin: configured */
	int synced;
	rtapi_u32 shift;	/* last four bitstream bytes, big-endian */
	int word_bytes;		/* after sync: bytes of the current 32-bit word */
	rtapi_u32 prev_word;
	rtapi_u32 bytes;	/* bytes clocked in since the last clear */
};

/* PROG_B pulse: configuration cleared, DONE low. */
void hm2_sim_fpgacfg_clear(struct hm2_sim_fpgacfg *c);
/* One configuration clock with 'port' on the data lines D0..D7. */
void hm2_sim_fpgacfg_byte(struct hm2_sim_fpgacfg *c, rtapi_u8 port);

#endif /* HM2_SIM_FPGACFG_H */
