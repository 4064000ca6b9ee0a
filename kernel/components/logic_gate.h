/* SPDX-License-Identifier: GPL-2.0-or-later */
/* logic_gate.h - what and2(9), or2(9), not(9) and xor2(9) share: per instance
 * bit pins PREFIX.in0/PREFIX.in1 (not: PREFIX.in) and PREFIX.out, and one
 * function PREFIX (no FP), with PREFIX from instance_names.h. Each gate's .c
 * file holds its module parameters and its one-line realtime function. */
#ifndef LOGIC_GATE_H
#define LOGIC_GATE_H

#include "rtapi.h"
#include "hal.h"
#include "instance_names.h"

#define LOGIC_GATE_MAX 64	/* names= entries per module */
#define LOGIC_GATE_MAX_COUNT 100000	/* count=: the standard benchmark loads 16,000 */

struct logic_gate {		/* in hal_malloc() memory, one per instance */
	hal_bit_t *in0;		/* "in" for the one-input gate */
	hal_bit_t *in1;		/* unused by the one-input gate */
	hal_bit_t *out;		/* written by the gate's function only */
};

static int logic_gate_export(struct logic_gate *g, int comp_id, const char *prefix,
			     int inputs, hal_funct_t funct)
{
	int err;

	if (inputs == 1) {
		err = hal_pin_bit_newf(HAL_IN, &g->in0, comp_id, "%s.in", prefix);
	} else {
		err = hal_pin_bit_newf(HAL_IN, &g->in0, comp_id, "%s.in0", prefix);
		if (!err)
			err = hal_pin_bit_newf(HAL_IN, &g->in1, comp_id, "%s.in1", prefix);
	}
	if (!err)
		err = hal_pin_bit_newf(HAL_OUT, &g->out, comp_id, "%s.out", prefix);
	if (!err)
		err = hal_export_funct(prefix, funct, g, 0, 0, comp_id);
	return err;
}

/* rtapi_app_main() of a gate module: validate count=/names=, make every
 * instance, hal_ready(). Returns the component id (> 0) or -errno; on failure
 * nothing is left behind. */
static int logic_gate_load(const char *comp, int count, char *const *names, int inputs,
			   hal_funct_t funct)
{
	char prefix[HAL_NAME_LEN + 1];
	struct logic_gate *all;
	int n, i, comp_id, err;

	n = instance_count(comp, "count", count, names, LOGIC_GATE_MAX, LOGIC_GATE_MAX_COUNT);
	if (n < 0)
		return n;
	comp_id = hal_init(comp);
	if (comp_id < 0)
		return comp_id;
	all = hal_malloc(n * (long)sizeof(*all));
	err = all ? 0 : -ENOMEM;
	if (!all)
		rtapi_print_msg(RTAPI_MSG_ERR, "%s: out of HAL memory for %d instances\n", comp, n);
	for (i = 0; !err && i < n; i++) {
		instance_prefix(prefix, sizeof(prefix), comp, names, i);
		err = logic_gate_export(&all[i], comp_id, prefix, inputs, funct);
	}
	if (err) {
		hal_exit(comp_id);	/* removes every pin and function made so far */
		return err;
	}
	hal_ready(comp_id);
	return comp_id;
}

#endif /* LOGIC_GATE_H */
