/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_sim_plx.h - a model of the PLX PCI bridges of the older Mesa cards, the part
 * hm2_pci talks to before the FPGA holds a configuration (hostmot2.md 12.2, 12.3).
 * BAR1, the bridge's local registers, reads back what was written, except the
 * control register (9030 GPIO at 0x54, 9054/9056 CNTRL at 0x6C), whose input bits
 * are the FPGA's DONE and /INIT; /PROGRAM low clears the FPGA's configuration port
 * model (hm2_sim_fpgacfg.h) and holds /INIT low; /INIT rises a few control reads
 * after /PROGRAM goes high. BAR2 is the configuration data port: each byte written
 * while the bridge enables it (9030: /WRITE low; both: /PROGRAM high and, on the
 * 9030, /INIT high) is one configuration clock. Faults: DONE that never rises,
 * DONE stuck high, /INIT stuck low. Integer-only. */
#ifndef HM2_SIM_PLX_H
#define HM2_SIM_PLX_H

#include "rtapi.h"
#include "hm2_sim_fpgacfg.h"

#define SIM_PLX_REGS 64			/* BAR1: 256 bytes */
#define SIM_PLX_INIT_READS 5		/* control reads from /PROGRAM high to /INIT high */

enum sim_plx_type { SIM_PLX_9030, SIM_PLX_9054 };
enum sim_plx_fault { SIM_PLX_OK, SIM_PLX_NO_DONE, SIM_PLX_DONE_STUCK, SIM_PLX_INIT_STUCK };

struct hm2_sim_plx {
	enum sim_plx_type type;
	enum sim_plx_fault fault;
	struct hm2_sim_fpgacfg *fpga;	/* the FPGA behind the bridge */
	rtapi_u32 reg[SIM_PLX_REGS];
	int init_wait;			/* control reads until /INIT rises; -1: high */
	rtapi_u32 ignored;		/* data bytes sent while the port was disabled */
};

/* Power-up state: registers as an old EEPROM leaves them (READY# input off on the
 * 9030's local spaces), /PROGRAM high, the FPGA as *fpga is. */
void hm2_sim_plx_init(struct hm2_sim_plx *p, enum sim_plx_type type, enum sim_plx_fault fault,
		      struct hm2_sim_fpgacfg *fpga);
rtapi_u32 hm2_sim_plx_read(struct hm2_sim_plx *p, unsigned long offset);
void hm2_sim_plx_write(struct hm2_sim_plx *p, unsigned long offset, rtapi_u32 value);
/* One byte on the configuration data port: 1 when it completed the configuration
 * (DONE rose), else 0. */
int hm2_sim_plx_data(struct hm2_sim_plx *p, rtapi_u8 value);
/* 1 when the HostMot2 window answers: on the 9030, READY# enabled on all four local
 * spaces (HostMot2 ends every access with READY#); always on the 9054/9056. */
int hm2_sim_plx_window_ok(const struct hm2_sim_plx *p);

#endif /* HM2_SIM_PLX_H */
