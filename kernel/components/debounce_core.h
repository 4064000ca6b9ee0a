/* SPDX-License-Identifier: GPL-2.0-or-later */
/* debounce_core.h - one debounce(9) filter, HAL-free so unit tests drive it.
 * A counter climbs while the input is true and falls while it is false; the
 * output turns true when the counter would pass delay, false when it would go
 * below zero. So with delay D a change must last D+1 samples to get through,
 * every glitch of D samples or less is rejected, and delay 0 follows the input
 * exactly (the Debounce section of the realtime components chapter). */
#ifndef DEBOUNCE_CORE_H
#define DEBOUNCE_CORE_H

#include "rtapi.h"

struct debounce_filter {
	rtapi_s32 count;	/* 0..delay: owned by the group's function */
	bool out;
};

static inline bool debounce_step(struct debounce_filter *f, bool in, rtapi_s32 delay)
{
	if (delay < 0)
		delay = 0;
	if (f->count > delay)
		f->count = delay;	/* delay was lowered */
	if (in) {
		if (f->count < delay)
			f->count++;
		else
			f->out = true;
	} else {
		if (f->count > 0)
			f->count--;
		else
			f->out = false;
	}
	return f->out;
}

#endif /* DEBOUNCE_CORE_H */
