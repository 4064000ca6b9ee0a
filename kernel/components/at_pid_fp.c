/* SPDX-License-Identifier: GPL-2.0-or-later */
/* at_pid_fp.c - the floating-point realtime functions of at_pid (see at_pid.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "at_pid_fp.h"

static void at_pid_write_gains(const struct pid_pins *p, const struct pid_gains *g)
{
	*p->Pgain = g->Pgain;
	*p->Igain = g->Igain;
	*p->Dgain = g->Dgain;
	*p->FF1 = g->FF1;
}

COMP_FP_LOCAL void at_pid_do_calcs(void *arg, long period_ns)
{
	struct at_pid *a = arg;
	struct at_pid_tune_cfg c;
	struct pid_gains g;
	struct pid_in in;
	struct pid_out o;
	double relay = 0.0;
	enum at_pid_tune_result r;

	pid_pins_read(&a->pins, &g, &in);
	c.tune_mode = *a->tune_mode;
	c.tune_start = *a->tune_start;
	c.tune_type = a->tune_type;
	c.tune_cycles = a->tune_cycles;
	c.tune_effort = a->tune_effort;
	r = at_pid_tune_step(&a->tune, &c, in.enable, in.command - in.feedback, period_ns,
			     &g, &relay);
	if (r == AT_PID_RELAY || r == AT_PID_DONE) {
		*a->pins.error = in.command - in.feedback;
		*a->pins.output = relay;
		a->st.primed = false;	/* restart the loop from scratch after tuning */
		a->st.errorI = 0.0;
		if (r == AT_PID_DONE) {
			at_pid_write_gains(&a->pins, &g);
			*a->tune_start = false;
		}
	} else {
		if (r == AT_PID_ABORTED)
			*a->tune_start = false;
		pid_step(&a->st, &g, &in, period_ns, &o);
		pid_pins_write(&a->pins, &o);
	}
	if (a->ultimate_gain) {
		*a->ultimate_gain = a->tune.ultimate_gain;
		*a->ultimate_period = a->tune.ultimate_period;
	}
}
