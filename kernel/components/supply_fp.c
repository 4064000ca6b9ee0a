/* SPDX-License-Identifier: GPL-2.0-or-later */
/* supply_fp.c - the floating-point realtime functions of supply (see supply.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "supply_fp.h"

COMP_FP_LOCAL void supply_update(void *arg, long period_ns)
{
	struct supply *s = arg;

	*s->q = s->d;
	*s->q_not = !s->d;
	*s->variable = s->value;
	*s->variable_neg = 0.0 - s->value;	/* -1 times value, but 0 stays 0, not -0 */
}
