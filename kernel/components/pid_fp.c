/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pid_fp.c - the floating-point realtime functions of pid (see pid.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "pid_fp.h"

COMP_FP_LOCAL void pid_do_calcs(void *arg, long period_ns)
{
	struct pid_loop *p = arg;
	struct pid_gains g;
	struct pid_in in;
	struct pid_out o;

	pid_pins_read(&p->pins, &g, &in);
	pid_step(&p->st, &g, &in, period_ns, &o);
	pid_pins_write(&p->pins, &o);
}
