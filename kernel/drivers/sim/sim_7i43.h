/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_7i43.h - a Mesa 7i43 on the cable of a simulated parallel port (sim_parport.c,
 * which owns it; hm2-transports.md 2.3-2.5): the CPLD that answers EPP cycles while
 * the FPGA is unconfigured (PROG_B latch, DONE, the FPGA size bit, one configuration
 * byte per data write), the FPGA's configuration port (hm2_sim_fpgacfg: DONE only
 * for a Xilinx bitstream sent bit-reversed, as the card needs), and once configured
 * the HostMot2 firmware's EPP protocol (16-bit address low byte first, bit 15 =
 * auto-increment, 32-bit byte-lane latches, the 0x7F7F/0x5A reconfigure cookie) in
 * front of hm2_sim's register model with the 7i43 layout (SVST4_4: 4 encoders and 4
 * PWM generators on P4, 4 stepgens on P3). */
#ifndef SIM_7I43_H
#define SIM_7I43_H

#include "hal.h"

struct sim_7i43;

/* Init code: the board's HAL pins, sim-parport.N.7i43.*, in HAL memory; fpga_k is
 * 200 or 400 (the 3s200tq144 or 3s400tq144 it carries). NULL after a message. */
struct sim_7i43 *sim_7i43_new(int comp_id, int n, int fpga_k);

/* The port's control register was written (/INIT low holds PROG_B low too). */
void sim_7i43_spp(struct sim_7i43 *b, unsigned char control);

/* EPP cycles: 0 when the board answered, -1 when no one asserted Wait (timeout). */
int sim_7i43_epp_addr(struct sim_7i43 *b, unsigned char byte);
int sim_7i43_epp_addr_read(struct sim_7i43 *b, unsigned char *byte);
int sim_7i43_epp_read(struct sim_7i43 *b, unsigned char *byte);
int sim_7i43_epp_write(struct sim_7i43 *b, unsigned char byte);

#endif /* SIM_7I43_H */
