/* SPDX-License-Identifier: GPL-2.0-or-later */
/* siggen_fp.c - the floating-point realtime functions of siggen (see siggen.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "siggen_fp.h"

COMP_FP_LOCAL void siggen_update(void *arg, long period_ns)
{
	struct siggen *g = arg;
	struct siggen_out o;

	siggen_step(&g->st, *g->frequency, *g->amplitude, *g->offset, period_ns, &o);
	*g->sine = o.sine;
	*g->cosine = o.cosine;
	*g->triangle = o.triangle;
	*g->sawtooth = o.sawtooth;
	*g->square = o.square;
	*g->clock = o.clock;
}
