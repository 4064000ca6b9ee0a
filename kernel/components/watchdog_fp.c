/* SPDX-License-Identifier: GPL-2.0-or-later */
/* watchdog_fp.c - the floating-point realtime functions of watchdog (see watchdog.c), alone in
 * this file: the kernel flavor compiles only *_fp.c files with SSE, and these run only
 * on a thread that opened an FPU section (exported with uses_fp = 1). */
#include "watchdog_fp.h"

COMP_FP_LOCAL void watchdog_set_timeouts(void *arg, long period)
{
	struct watchdog *w = arg;
	int i;

	for (i = 0; i < num_inputs; i++) {
		double t = *w->input[i].timeout;

		if (t < 0)		/* the page forbids negative timeouts: treat as 0 */
			t = 0;
		if (t > 9e9)		/* ~285 years; keeps the conversion in range */
			t = 9e9;
		rtapi_store_u64(&w->input[i].timeout_ns, (rtapi_u64)(t * 1e9));
	}
	if (*w->enable_in && !w->last_enable)
		__atomic_store_n(&w->restarts, w->restarts + 1, __ATOMIC_RELEASE);
	w->last_enable = *w->enable_in;
}
