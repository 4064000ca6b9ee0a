/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_pluto.h - a Pluto-P board (pluto.md) on the cable of a simulated parallel port
 * (sim_parport.c, which owns it): the FPGA's configuration through SPP and, once
 * configured, the EPP register map of the pluto_servo or pluto_step design. */
#ifndef SIM_PLUTO_H
#define SIM_PLUTO_H

#include "hal.h"

enum sim_pluto_design { SIM_PLUTO_SERVO, SIM_PLUTO_STEP };

struct sim_pluto;

/* Init code: the board's HAL pins, sim-parport.N.pluto.*, in HAL memory. NULL after
 * a message on failure. */
struct sim_pluto *sim_pluto_new(int comp_id, int n, enum sim_pluto_design design);

/* The port's data or control register was written (the cable's levels changed). */
void sim_pluto_spp(struct sim_pluto *p, unsigned char data, unsigned char control);

/* EPP cycles: 0 when the board answered, -1 when no one asserted Wait (timeout). */
int sim_pluto_epp_addr(struct sim_pluto *p, unsigned char addr);
int sim_pluto_epp_read(struct sim_pluto *p, unsigned char *byte);
int sim_pluto_epp_write(struct sim_pluto *p, unsigned char byte);

#endif /* SIM_PLUTO_H */
