/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pumakins.h - what pumakins.c (init, pins, switch) and pumakins_fp.c share. */
#ifndef PUMAKINS_H
#define PUMAKINS_H

#include "hal.h"
#include "kins_glue.h"

/* In HAL memory: the pins pumakins.A2, A3, D3, D4, D6 (float IN), and the switch. */
struct pumakins_state {
	hal_float_t *a2, *a3, *d3, *d4, *d6;
	struct kins_switch sw;
};
COMP_FP_LOCAL extern struct pumakins_state *pumakins;

COMP_FP_LOCAL void pumakins_defaults(struct pumakins_state *s);

#endif /* PUMAKINS_H */
