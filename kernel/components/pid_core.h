/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pid_core.h - the loop calculation of pid(9) (and of at_pid(9) outside tuning),
 * HAL-free so unit tests drive it directly. One call is one period:
 *   target   = previous command if error-previous-target, else command
 *   error    = target - feedback                          (the error pin)
 *   e        = error limited to +-maxerror, then deadband removed (|e| <= deadband
 *              is 0, else deadband is subtracted from |e|: no step at its edge)
 *   errorI  += e * period, limited to +-maxerrorI; held in a period whose output
 *              is limited by maxoutput (no windup)
 *   errorD   = (e - previous e) / period, or commandD - feedbackD when either
 *              derivative is given on a pin; limited to +-maxerrorD
 *   commandD/DD/DDD: successive derivatives of the command (commandD from the
 *              command-deriv pin when given), limited by maxcmdD/DD/DDD
 *   output   = bias + Pgain e + Igain errorI + Dgain errorD + FF0 command
 *              + FF1 commandD + FF2 commandDD + FF3 commandDDD, limited to +-maxoutput
 * A limit of 0 means no limit. Disabled: output 0, errorI/errorD and saturation
 * reset; the command and feedback are still tracked so enabling causes no spike.
 * On the falling edge of index-enable the numeric derivative estimates keep
 * their previous values (the encoder and the command both jumped). */
#ifndef PID_CORE_H
#define PID_CORE_H

#include "rtapi.h"

struct pid_gains {		/* the tuning pins, read once per period */
	double Pgain, Igain, Dgain, bias, FF0, FF1, FF2, FF3, deadband;
	double maxerror, maxerrorI, maxerrorD, maxcmdD, maxcmdDD, maxcmdDDD, maxoutput;
};

struct pid_in {			/* the input pins, read once per period */
	double command, feedback;
	double command_deriv, feedback_deriv;	/* used only when the has_ flag is set */
	bool has_command_deriv, has_feedback_deriv;	/* a signal drives that pin */
	bool enable, index_enable, error_previous_target;
};

struct pid_out {		/* written to the output pins after each period */
	double error, output, saturated_s;
	rtapi_s32 saturated_count;
	bool saturated;
	double errorI, errorD, commandD, commandDD, commandDDD;	/* debug pins */
};

struct pid_state {		/* private to the loop's function */
	bool primed;		/* false until the first period: no history yet */
	bool prev_index_enable;
	double prev_command, prev_feedback, prev_e;
	double errorI, commandD, commandDD, commandDDD, feedbackD;
	double saturated_s;
	rtapi_s32 saturated_count;
};

/* Clamp v to +-limit; a limit of 0 (or less) means none. */
static inline double pid_limit(double v, double limit)
{
	if (limit <= 0.0)
		return v;
	if (v > limit)
		return limit;
	if (v < -limit)
		return -limit;
	return v;
}

static inline double pid_deadband(double e, double deadband)
{
	if (deadband <= 0.0)
		return e;
	if (e > deadband)
		return e - deadband;
	if (e < -deadband)
		return e + deadband;
	return 0.0;
}

/* Derivatives of command and feedback, unless index-enable just fell: then the
 * command and the feedback both jumped and the previous estimates are kept. */
static inline void pid_derivatives(struct pid_state *s, const struct pid_gains *g,
				   const struct pid_in *in, double rate)
{
	bool index_fell = s->prev_index_enable && !in->index_enable;
	double cmd_d, cmd_dd;

	if (in->has_command_deriv)
		cmd_d = in->command_deriv;
	else if (index_fell)
		cmd_d = s->commandD;
	else
		cmd_d = (in->command - s->prev_command) * rate;
	cmd_d = pid_limit(cmd_d, g->maxcmdD);
	if (!index_fell) {
		cmd_dd = pid_limit((cmd_d - s->commandD) * rate, g->maxcmdDD);
		s->commandDDD = pid_limit((cmd_dd - s->commandDD) * rate, g->maxcmdDDD);
		s->commandDD = cmd_dd;
	}
	s->commandD = cmd_d;
	if (in->has_feedback_deriv)
		s->feedbackD = in->feedback_deriv;
	else if (!index_fell)
		s->feedbackD = (in->feedback - s->prev_feedback) * rate;
}

/* One period of the loop. period_ns > 0 is the calling thread's period.
 * Realtime, uses FP. */
static inline void pid_step(struct pid_state *s, const struct pid_gains *g,
			    const struct pid_in *in, long period_ns, struct pid_out *o)
{
	double period_s = period_ns > 0 ? period_ns * 1e-9 : 1e-9;
	double rate = 1.0 / period_s;
	double target, e, errorI, errorD, out;
	bool first = !s->primed;

	if (first) {	/* the first period has no history: pretend it was steady */
		s->prev_command = in->command;
		s->prev_feedback = in->feedback;
		s->prev_index_enable = in->index_enable;
		s->primed = true;
	}
	target = in->error_previous_target ? s->prev_command : in->command;
	o->error = target - in->feedback;
	e = pid_deadband(pid_limit(o->error, g->maxerror), g->deadband);
	if (first)
		s->prev_e = e;
	pid_derivatives(s, g, in, rate);

	if (in->has_command_deriv || in->has_feedback_deriv)
		errorD = s->commandD - s->feedbackD;
	else
		errorD = (e - s->prev_e) * rate;
	errorD = pid_limit(errorD, g->maxerrorD);

	if (in->enable) {
		errorI = pid_limit(s->errorI + e * period_s, g->maxerrorI);
		out = g->bias + g->Pgain * e + g->Igain * errorI + g->Dgain * errorD +
		      g->FF0 * in->command + g->FF1 * s->commandD + g->FF2 * s->commandDD +
		      g->FF3 * s->commandDDD;
		o->output = pid_limit(out, g->maxoutput);
		o->saturated = g->maxoutput > 0.0 && (out >= g->maxoutput || out <= -g->maxoutput);
		if (!o->saturated)
			s->errorI = errorI;	/* else hold: integrating would only wind up */
		if (o->saturated) {
			s->saturated_s += period_s;
			if (s->saturated_count < 0x7fffffff)
				s->saturated_count++;
		} else {
			s->saturated_s = 0.0;
			s->saturated_count = 0;
		}
	} else {
		s->errorI = 0.0;
		errorD = 0.0;
		o->output = 0.0;
		o->saturated = false;
		s->saturated_s = 0.0;
		s->saturated_count = 0;
	}
	o->saturated_s = s->saturated_s;
	o->saturated_count = s->saturated_count;
	o->errorI = s->errorI;
	o->errorD = errorD;
	o->commandD = s->commandD;
	o->commandDD = s->commandDD;
	o->commandDDD = s->commandDDD;

	s->prev_e = e;
	s->prev_command = in->command;
	s->prev_feedback = in->feedback;
	s->prev_index_enable = in->index_enable;
}

#endif /* PID_CORE_H */
