/* SPDX-License-Identifier: GPL-2.0-or-later */
/* pid_pins.h - the pins pid(9) and at_pid(9) share, and moving their values in
 * and out of pid_core.h's structs. Both pages name them PREFIX.<pin>. pid makes
 * every pin of its page (gains and limits are pins, RULINGS.md); at_pid makes
 * the subset its page lists, with the gains as I/O pins because the auto tune
 * writes them. debug=1 adds the derivative/integral pins of both pages. */
#ifndef PID_PINS_H
#define PID_PINS_H

#include "rtapi.h"
#include "hal.h"
#include "pid_core.h"

struct pid_pins {		/* in hal_malloc() memory; NULL: the pin is not made */
	hal_float_t *Pgain, *Igain, *Dgain, *bias, *FF0, *FF1, *FF2, *FF3, *deadband;
	hal_float_t *maxerror, *maxerrorI, *maxerrorD, *maxcmdD, *maxcmdDD, *maxcmdDDD;
	hal_float_t *maxoutput;
	hal_float_t *command, *command_deriv, *feedback, *feedback_deriv;
	hal_bit_t *enable, *index_enable, *error_previous_target;
	hal_float_t *error, *output, *saturated_s;	/* written by the loop only */
	hal_bit_t *saturated;
	hal_s32_t *saturated_count;
	hal_float_t *errorI, *errorD, *commandD, *commandDD, *commandDDD;	/* debug=1 */
	/* Where command-deriv/feedback-deriv point while no signal drives them: HAL
	 * aims a new pin at its own storage and re-aims it there on unlink, so a
	 * different address means a signal is linked (set at init, read-only after). */
	hal_float_t *command_deriv_unlinked, *feedback_deriv_unlinked;
};

#define PID_PIN_GAIN 1		/* a gain or limit: I/O in at_pid, which writes them */
#define PID_PIN_PID_ONLY 2	/* on the pid page only */
#define PID_PIN_DEBUG 4		/* made only with debug=1 */

struct pid_float_pin {
	const char *name;
	unsigned short off;	/* offsetof(struct pid_pins, the pointer) */
	unsigned char dir;	/* HAL_IN or HAL_OUT; gains become HAL_IO in at_pid */
	unsigned char flags;
};

#define PID_F(name, field, dir, flags) { name, offsetof(struct pid_pins, field), dir, flags }
static const struct pid_float_pin pid_float_pins[] = {
	PID_F("Pgain", Pgain, HAL_IN, PID_PIN_GAIN),
	PID_F("Igain", Igain, HAL_IN, PID_PIN_GAIN),
	PID_F("Dgain", Dgain, HAL_IN, PID_PIN_GAIN),
	PID_F("bias", bias, HAL_IN, PID_PIN_GAIN),
	PID_F("FF0", FF0, HAL_IN, PID_PIN_GAIN),
	PID_F("FF1", FF1, HAL_IN, PID_PIN_GAIN),
	PID_F("FF2", FF2, HAL_IN, PID_PIN_GAIN),
	PID_F("FF3", FF3, HAL_IN, PID_PIN_GAIN | PID_PIN_PID_ONLY),
	PID_F("deadband", deadband, HAL_IN, PID_PIN_GAIN),
	PID_F("maxerror", maxerror, HAL_IN, PID_PIN_GAIN),
	PID_F("maxerrorI", maxerrorI, HAL_IN, PID_PIN_GAIN),
	PID_F("maxerrorD", maxerrorD, HAL_IN, PID_PIN_GAIN),
	PID_F("maxcmdD", maxcmdD, HAL_IN, PID_PIN_GAIN),
	PID_F("maxcmdDD", maxcmdDD, HAL_IN, PID_PIN_GAIN),
	PID_F("maxcmdDDD", maxcmdDDD, HAL_IN, PID_PIN_GAIN | PID_PIN_PID_ONLY),
	PID_F("maxoutput", maxoutput, HAL_IN, PID_PIN_GAIN),
	PID_F("command", command, HAL_IN, 0),
	PID_F("command-deriv", command_deriv, HAL_IN, PID_PIN_PID_ONLY),
	PID_F("feedback", feedback, HAL_IN, 0),
	PID_F("feedback-deriv", feedback_deriv, HAL_IN, PID_PIN_PID_ONLY),
	PID_F("error", error, HAL_OUT, 0),
	PID_F("output", output, HAL_OUT, 0),
	PID_F("saturated-s", saturated_s, HAL_OUT, PID_PIN_PID_ONLY),
	PID_F("errorI", errorI, HAL_OUT, PID_PIN_DEBUG),
	PID_F("errorD", errorD, HAL_OUT, PID_PIN_DEBUG),
	PID_F("commandD", commandD, HAL_OUT, PID_PIN_DEBUG),
	PID_F("commandDD", commandDD, HAL_OUT, PID_PIN_DEBUG),
	PID_F("commandDDD", commandDDD, HAL_OUT, PID_PIN_DEBUG | PID_PIN_PID_ONLY),
};
#undef PID_F

/* Init bit pattern of 1.0: init code runs outside the kernel's FPU sections. */
#define PID_FLOAT_ONE_BITS 0x3ff0000000000000ULL

/* Make the pins of one loop. is_at_pid selects at_pid's set. Init only; returns
 * 0 or -errno (the failing hal_* call has logged the pin name). */
static inline int pid_pins_export(struct pid_pins *p, int comp_id, const char *prefix,
				  bool debug, bool is_at_pid)
{
	const struct pid_float_pin *f;
	hal_pin_dir_t dir;
	unsigned int i;
	int err = 0;

	for (i = 0; !err && i < sizeof(pid_float_pins) / sizeof(pid_float_pins[0]); i++) {
		f = &pid_float_pins[i];
		if ((f->flags & PID_PIN_DEBUG) && !debug)
			continue;
		if ((f->flags & PID_PIN_PID_ONLY) && is_at_pid)
			continue;
		dir = (hal_pin_dir_t)f->dir;
		if ((f->flags & PID_PIN_GAIN) && is_at_pid)
			dir = HAL_IO;
		err = hal_pin_float_newf(dir, (hal_float_t **)((char *)p + f->off), comp_id,
					 "%s.%s", prefix, f->name);
	}
	if (!err)
		err = hal_pin_bit_newf(HAL_IN, &p->enable, comp_id, "%s.enable", prefix);
	if (!err && !is_at_pid)
		err = hal_pin_bit_newf(HAL_IN, &p->index_enable, comp_id, "%s.index-enable", prefix);
	if (!err && !is_at_pid)
		err = hal_pin_bit_newf(HAL_IN, &p->error_previous_target, comp_id,
				       "%s.error-previous-target", prefix);
	if (!err && !is_at_pid)
		err = hal_pin_bit_newf(HAL_OUT, &p->saturated, comp_id, "%s.saturated", prefix);
	if (!err && !is_at_pid)
		err = hal_pin_s32_newf(HAL_OUT, &p->saturated_count, comp_id,
				       "%s.saturated-count", prefix);
	if (err)
		return err;
	*(volatile rtapi_u64 *)p->Pgain = PID_FLOAT_ONE_BITS;	/* Pgain defaults to 1.0 */
	if (p->error_previous_target)
		*p->error_previous_target = true;
	p->command_deriv_unlinked = p->command_deriv;
	p->feedback_deriv_unlinked = p->feedback_deriv;
	return 0;
}

static inline double pid_pin_or_zero(hal_float_t *pin)
{
	return pin ? *pin : 0.0;
}

/* Read the gains and inputs of one period. Realtime, uses FP. */
static inline void pid_pins_read(const struct pid_pins *p, struct pid_gains *g, struct pid_in *in)
{
	g->Pgain = *p->Pgain;
	g->Igain = *p->Igain;
	g->Dgain = *p->Dgain;
	g->bias = *p->bias;
	g->FF0 = *p->FF0;
	g->FF1 = *p->FF1;
	g->FF2 = *p->FF2;
	g->FF3 = pid_pin_or_zero(p->FF3);
	g->deadband = *p->deadband;
	g->maxerror = *p->maxerror;
	g->maxerrorI = *p->maxerrorI;
	g->maxerrorD = *p->maxerrorD;
	g->maxcmdD = *p->maxcmdD;
	g->maxcmdDD = *p->maxcmdDD;
	g->maxcmdDDD = pid_pin_or_zero(p->maxcmdDDD);
	g->maxoutput = *p->maxoutput;
	in->command = *p->command;
	in->feedback = *p->feedback;
	in->has_command_deriv = p->command_deriv && p->command_deriv != p->command_deriv_unlinked;
	in->has_feedback_deriv = p->feedback_deriv &&
				 p->feedback_deriv != p->feedback_deriv_unlinked;
	in->command_deriv = in->has_command_deriv ? *p->command_deriv : 0.0;
	in->feedback_deriv = in->has_feedback_deriv ? *p->feedback_deriv : 0.0;
	in->enable = *p->enable;
	in->index_enable = p->index_enable ? *p->index_enable : false;
	in->error_previous_target = p->error_previous_target ? *p->error_previous_target : false;
}

/* Write the outputs of one period. Realtime, uses FP. */
static inline void pid_pins_write(const struct pid_pins *p, const struct pid_out *o)
{
	*p->error = o->error;
	*p->output = o->output;
	if (p->saturated) {
		*p->saturated = o->saturated;
		*p->saturated_s = o->saturated_s;
		*p->saturated_count = o->saturated_count;
	}
	if (p->errorI) {
		*p->errorI = o->errorI;
		*p->errorD = o->errorD;
		*p->commandD = o->commandD;
		*p->commandDD = o->commandDD;
	}
	if (p->commandDDD)
		*p->commandDDD = o->commandDDD;
}

#endif /* PID_PINS_H */
