/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_7i43_epp.h - EPP cycles to a Mesa 7i43 over a claimed parallel port
 * (hm2-transports.md 2.1-2.3): address and data cycles through the port's EPP
 * registers, the HostMot2 word transfers (16-bit address, low byte first, bit 15 =
 * auto-increment; each 32-bit word as four byte cycles LSB first, or one 32-bit
 * access in wide mode), and the port's EPP timeout flag (status bit 0). */
#ifndef HM2_7I43_EPP_H
#define HM2_7I43_EPP_H

#include "rtapi.h"

#define EPP_AUTOINC 0x8000	/* address bit 15: the address steps after each data cycle */
#define EPP_MAX_ADDR 0x8000	/* so the register space reachable over EPP ends here */

struct epp_port {
	unsigned int base;	/* data register; status +1, control +2, address +3, data +4 */
	int wide;		/* 32-bit port accesses (epp_wide) */
	int debug;		/* log every word transfer (debug_epp) */
	const char *name;	/* the board, for messages */
};

void epp_addr8(const struct epp_port *p, rtapi_u8 addr);
void epp_write8(const struct epp_port *p, rtapi_u8 byte);
rtapi_u8 epp_read8(const struct epp_port *p);

/* 'words' 32-bit words at HostMot2 byte address addr (4-aligned, below EPP_MAX_ADDR),
 * with auto-increment. The timeout flag is not checked here. */
void epp_read_words(const struct epp_port *p, rtapi_u32 addr, rtapi_u32 *buf, int words);
void epp_write_words(const struct epp_port *p, rtapi_u32 addr, const rtapi_u32 *buf, int words);

/* 1 when a cycle since the last call timed out (the flag is then cleared: ports
 * differ in how, so every known way is tried), else 0. */
int epp_timed_out(const struct epp_port *p);

#endif /* HM2_7I43_EPP_H */
