/* SPDX-License-Identifier: GPL-2.0-or-later */
/* and2.c - two-input AND gate, and2(9): loadrt and2 [count=N|names=name1[,name2...]].
 * Pins and the function come from logic_gate.h. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "logic_gate.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("two-input AND gate");

static int count = -1;		/* -1: not given (one instance, unless names= is) */
RTAPI_MP_INT(count, "number of and2 gates");
static char *names[LOGIC_GATE_MAX];
RTAPI_MP_ARRAY_STRING(names, LOGIC_GATE_MAX, "names of the and2 gates (instead of count)");

static int comp_id;

static void and2_funct(void *arg, long period)
{
	struct logic_gate *g = arg;

	*g->out = *g->in0 && *g->in1;
}

int rtapi_app_main(void)
{
	int id = logic_gate_load("and2", count, names, 2, and2_funct);

	if (id < 0)
		return id;
	comp_id = id;
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
