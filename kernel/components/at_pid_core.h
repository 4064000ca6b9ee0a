/* SPDX-License-Identifier: GPL-2.0-or-later */
/* at_pid_core.h - the auto tune of at_pid(9), HAL-free so unit tests drive it.
 * A relay sets up a limit cycle around the command (held still while tuning):
 * output = bias + tune-effort while command - feedback > 0, bias - tune-effort
 * while it is < 0 (at exactly 0 the relay keeps its side). Every change of side
 * ends a half cycle; the first two are the transient and are skipped, then
 * tune-cycles half cycles are averaged:
 *   ultimate-period = 2 * mean half-cycle time
 *   ultimate-gain   = 4 * tune-effort / (pi * mean peak |error| per half cycle)
 * and Ziegler-Nichols gives the gains (Ku = ultimate-gain, Pu = ultimate-period):
 *   tune-type 0: Pgain 0.6 Ku,  Igain 1.2 Ku/Pu,  Dgain 0.075 Ku Pu, FF1 0
 *   tune-type 1: Pgain 0.45 Ku, Igain 0.54 Ku/Pu, Dgain 0,           FF1 1
 * (type 1 expects output in user units per second, as the page says). */
#ifndef AT_PID_CORE_H
#define AT_PID_CORE_H

#include "rtapi.h"
#include "pid_core.h"

#define AT_PID_SKIP_HALF_CYCLES 2	/* transient before the limit cycle settles */

enum at_pid_tune_state { AT_PID_IDLE, AT_PID_TUNING };

struct at_pid_tune {		/* private to the loop's function */
	enum at_pid_tune_state state;
	bool relay_high;	/* which side the relay is on */
	rtapi_u32 half_cycles;	/* completed half cycles, transient included */
	double since_switch_s;	/* time since the relay last switched */
	double peak;		/* largest |error| in the current half cycle */
	double sum_time_s, sum_peak;	/* over the averaged half cycles */
	double ultimate_gain, ultimate_period;	/* last result, for the debug pins */
};

struct at_pid_tune_cfg {	/* the tune pins and parameters */
	bool tune_mode, tune_start;
	rtapi_u32 tune_type, tune_cycles;
	double tune_effort;
};

/* What at_pid_tune_step() asks the caller to do with the pins. */
enum at_pid_tune_result {
	AT_PID_NOT_TUNING,	/* run the normal loop */
	AT_PID_RELAY,		/* output is the relay's; the loop is reset */
	AT_PID_DONE,		/* output is the relay's; gains are new; clear tune-start */
	AT_PID_ABORTED,		/* enable or tune-mode fell: clear tune-start, run the loop */
};

static inline void at_pid_tune_gains(struct at_pid_tune *t, rtapi_u32 tune_type, double effort,
				     rtapi_u32 n, struct pid_gains *g)
{
	double pu = 2.0 * t->sum_time_s / n;
	double amplitude = t->sum_peak / n;
	double ku = amplitude > 0.0 ? 4.0 * effort / (3.14159265358979323846 * amplitude) : 0.0;

	t->ultimate_gain = ku;
	t->ultimate_period = pu;
	if (tune_type == 1) {
		g->Pgain = 0.45 * ku;
		g->Igain = pu > 0.0 ? 0.54 * ku / pu : 0.0;
		g->Dgain = 0.0;
		g->FF1 = 1.0;
	} else {
		g->Pgain = 0.6 * ku;
		g->Igain = pu > 0.0 ? 1.2 * ku / pu : 0.0;
		g->Dgain = 0.075 * ku * pu;
		g->FF1 = 0.0;
	}
}

/* One period of tuning. error = command - feedback. Writes *output when the
 * result is AT_PID_RELAY or AT_PID_DONE, and the gains on AT_PID_DONE.
 * Realtime, uses FP. */
static inline enum at_pid_tune_result at_pid_tune_step(struct at_pid_tune *t,
						       const struct at_pid_tune_cfg *c,
						       bool enable, double error, long period_ns,
						       struct pid_gains *g, double *output)
{
	double effort = c->tune_effort < 0.0 ? -c->tune_effort : c->tune_effort;
	double mag = error < 0.0 ? -error : error;
	rtapi_u32 n = c->tune_cycles ? c->tune_cycles : 1;
	bool high;

	if (t->state == AT_PID_IDLE) {
		if (!(enable && c->tune_mode && c->tune_start))
			return AT_PID_NOT_TUNING;
		t->state = AT_PID_TUNING;
		t->relay_high = error >= 0.0;
		t->half_cycles = 0;
		t->since_switch_s = 0.0;
		t->peak = 0.0;
		t->sum_time_s = 0.0;
		t->sum_peak = 0.0;
	} else if (!enable || !c->tune_mode) {
		t->state = AT_PID_IDLE;
		return AT_PID_ABORTED;
	}
	t->since_switch_s += period_ns * 1e-9;
	high = error > 0.0 ? true : error < 0.0 ? false : t->relay_high;
	if (high != t->relay_high) {	/* a half cycle ended; this error starts the next */
		if (t->half_cycles >= AT_PID_SKIP_HALF_CYCLES) {
			t->sum_time_s += t->since_switch_s;
			t->sum_peak += t->peak;
		}
		t->half_cycles++;
		t->relay_high = high;
		t->since_switch_s = 0.0;
		t->peak = mag;
	} else if (mag > t->peak) {
		t->peak = mag;
	}
	*output = g->bias + (t->relay_high ? effort : -effort);
	*output = pid_limit(*output, g->maxoutput);
	if (t->half_cycles >= AT_PID_SKIP_HALF_CYCLES + n) {
		at_pid_tune_gains(t, c->tune_type, effort, n, g);
		t->state = AT_PID_IDLE;
		return AT_PID_DONE;
	}
	return AT_PID_RELAY;
}

#endif /* AT_PID_CORE_H */
