/* SPDX-License-Identifier: GPL-2.0-or-later */
/* watchdog.c - watchdog(9): loadrt watchdog num_inputs=N. ok-out stays TRUE while every
 * watchdog.input-n keeps toggling within watchdog.timeout-n seconds and enable-in is TRUE.
 * Plain C, not .comp: the pins carry no instance number and their number is a module
 * parameter of its own (num_inputs), neither of which comp's count=/names= model offers.
 *
 * Two functions in two threads: watchdog.set-timeouts (FP, servo thread) turns the float
 * timeouts into nanoseconds and notices enable-in rising; watchdog.process (no FP, fast
 * thread) watches the inputs. They share only timeout_ns (written by set-timeouts) and
 * restarts (a counter set-timeouts bumps and process compares), so neither waits on the other. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "watchdog_fp.h"

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("monitor multiple inputs for a heartbeat");

COMP_FP_LOCAL int num_inputs = -1;	/* -1: not given; the page requires it */
RTAPI_MP_INT(num_inputs, "number of inputs, 1..32");

static int comp_id;

static void watchdog_process(void *arg, long period)
{
	struct watchdog *w = arg;
	rtapi_u32 restarts = __atomic_load_n(&w->restarts, __ATOMIC_ACQUIRE);
	int i;

	if (restarts != w->restarts_seen) {	/* enable-in rose: start watching afresh */
		w->restarts_seen = restarts;
		w->fault = 0;
		for (i = 0; i < num_inputs; i++) {
			w->input[i].left_ns = (rtapi_s64)rtapi_load_u64(&w->input[i].timeout_ns);
			w->input[i].last = *w->input[i].in;
		}
	}
	if (!*w->enable_in || w->fault) {
		*w->ok_out = 0;
		return;
	}
	for (i = 0; i < num_inputs; i++) {
		struct watchdog_input *in = &w->input[i];

		if (*in->in != in->last) {
			in->last = *in->in;
			in->left_ns = (rtapi_s64)rtapi_load_u64(&in->timeout_ns);
			continue;
		}
		in->left_ns -= period;
		if (in->left_ns <= 0)
			w->fault = 1;	/* latched until enable-in goes FALSE and TRUE again */
	}
	*w->ok_out = !w->fault;
}

static int watchdog_export(struct watchdog *w)
{
	int i, err;

	err = hal_pin_bit_new("watchdog.enable-in", HAL_IN, &w->enable_in, comp_id);
	if (!err)
		err = hal_pin_bit_new("watchdog.ok-out", HAL_OUT, &w->ok_out, comp_id);
	for (i = 0; !err && i < num_inputs; i++) {
		err = hal_pin_bit_newf(HAL_IN, &w->input[i].in, comp_id, "watchdog.input-%d", i);
		if (!err)
			err = hal_pin_float_newf(HAL_IN, &w->input[i].timeout, comp_id,
						 "watchdog.timeout-%d", i);
	}
	if (err)
		return err;
	*w->enable_in = 0;
	*w->ok_out = 0;
	w->fault = 1;		/* nothing is watched until enable-in rises */
	err = hal_export_funct("watchdog.process", watchdog_process, w, 0, 0, comp_id);
	if (!err)
		err = hal_export_funct("watchdog.set-timeouts", watchdog_set_timeouts, w, 1, 0,
				       comp_id);
	return err;
}

int rtapi_app_main(void)
{
	struct watchdog *w;
	int err;

	if (num_inputs == -1) {
		rtapi_print_msg(RTAPI_MSG_ERR, "watchdog: num_inputs= is required, 1..%d\n",
				WATCHDOG_MAX_INPUTS);
		return -EINVAL;
	}
	if (num_inputs < 1 || num_inputs > WATCHDOG_MAX_INPUTS) {
		rtapi_print_msg(RTAPI_MSG_ERR, "watchdog: num_inputs=%d is out of range, must be 1..%d\n",
				num_inputs, WATCHDOG_MAX_INPUTS);
		return -EINVAL;
	}
	comp_id = hal_init("watchdog");
	if (comp_id < 0)
		return comp_id;
	w = hal_malloc(sizeof(*w));
	if (!w) {
		rtapi_print_msg(RTAPI_MSG_ERR, "watchdog: out of HAL memory\n");
		err = -ENOMEM;
	} else {
		err = watchdog_export(w);
	}
	if (err) {
		hal_exit(comp_id);	/* removes every pin and function made so far */
		return err;
	}
	hal_ready(comp_id);
	return 0;
}

void rtapi_app_exit(void)
{
	hal_exit(comp_id);
}
