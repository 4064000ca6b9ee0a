/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_plx.h - the PLX PCI bridges of the older Mesa PCI cards (hostmot2.md 12.2,
 * 12.3): where the FPGA's configuration pins sit in the bridge's local registers
 * (BAR1, I/O space), and the reset and programming sequences hm2_pci runs through
 * them; the bitstream goes, one bit-reversed byte per outb, to the configuration
 * data port (BAR2). The simulated bridge (sim/hm2_sim_plx.c) uses the same names.
 * Init code only. */
#ifndef HM2_PLX_H
#define HM2_PLX_H

#include "rtapi.h"
#include "rtapi_pci.h"

/* PLX 9030 (5i20, 4i65): GPIO control register */
#define PLX9030_CTRL		0x54
#define PLX9030_DONE		(1u << 11)	/* GPIO3 in: configured */
#define PLX9030_INIT		(1u << 14)	/* GPIO4 in: /INIT, low = clearing or CRC error */
#define PLX9030_LED		(1u << 17)	/* GPIO5 out: /LED */
#define PLX9030_WRITE		(1u << 23)	/* GPIO7 out: /WRITE */
#define PLX9030_PROGRAM		(1u << 26)	/* GPIO8 out: /PROGRAM */
/* local address space 0..3 bus region descriptors: READY# input enable */
#define PLX9030_LAS0BRD		0x28
#define PLX9030_LASBRD_READY	(1u << 1)

/* PLX 9054/9056 (5i21, 5i22, 5i23, 4i68, 4i69, 3x20): CNTRL register */
#define PLX9054_CNTRL		0x6C
#define PLX9054_PROGRAM		(1u << 16)	/* USERO: /PROGRAM */
#define PLX9054_DONE		(1u << 17)	/* USERI: DONE */
#define PLX9054_USERI_IN	(1u << 18)	/* USERI pin is an input */
#define PLX9054_USERO_OUT	(1u << 19)	/* USERO pin is an output */
#define PLX9054_DELAY_REG	0x54		/* read for the >= 100 us after /PROGRAM */

#define PLX_INIT_POLLS		3300	/* reads of the control register, >= 100 us */
#define PLX_DONE_POLLS		20000

/* Each returns 0 or -EIO after one message starting with 'name' (the board). */
void hm2_plx9030_fix_ready(struct rtapi_pci_bar *ctrl, const char *name);
int hm2_plx9030_reset(struct rtapi_pci_bar *ctrl, const char *name);
int hm2_plx9030_program(struct rtapi_pci_bar *ctrl, struct rtapi_pci_bar *data,
			const rtapi_u8 *bitstream, rtapi_u32 size, const char *name);
int hm2_plx9054_reset(struct rtapi_pci_bar *ctrl, const char *name);
int hm2_plx9054_program(struct rtapi_pci_bar *ctrl, struct rtapi_pci_bar *data,
			const rtapi_u8 *bitstream, rtapi_u32 size, const char *name);

#endif /* HM2_PLX_H */
