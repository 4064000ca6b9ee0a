/* SPDX-License-Identifier: GPL-2.0-or-later */
/* timedelta.comp - timedelta(9): measure the time between successive runs of this function
 * (out), its error against the thread period (err, avg-err) and its spread (min, max, jitter). */
component timedelta "EMC2 HAL component that measures thread scheduling timing behavior";
pin out s32 out "Time since the previous run, ns";
pin out s32 err = 0 "out minus the thread period, ns";
pin out s32 min_ = 0 "Smallest out since load or reset";
pin out s32 max_ = 0 "Largest out since load or reset";
pin out s32 jitter = 0 "Largest distance of out from the period since load or reset";
pin out float avg_err = 0 "Mean of err since load or reset";
pin in bit reset "While TRUE, clear the statistics; measuring restarts when it is released";
variable rtapi_s64 last_ns;	/* rtapi_get_time() of the previous run; 0 = none yet */
variable double err_sum;
variable rtapi_u32 samples;
function _;
license "GPL";
;;
FUNCTION(_)
{
	rtapi_s64 now = rtapi_get_time(), delta;
	rtapi_s64 dev;

	if (reset) {
		last_ns = 0;
		out = err = min_ = max_ = jitter = 0;
		avg_err = 0;
		err_sum = 0;
		samples = 0;
		return;
	}
	if (last_ns == 0) {	/* the first run after load or reset only starts the clock */
		last_ns = now;
		return;
	}
	delta = now - last_ns;
	last_ns = now;
	if (delta > 0x7fffffff)
		delta = 0x7fffffff;
	out = (hal_s32_t)delta;
	err = (hal_s32_t)(delta - period);
	if (samples == 0 || out < min_)
		min_ = out;
	if (samples == 0 || out > max_)
		max_ = out;
	dev = err < 0 ? -(rtapi_s64)err : err;
	if (dev > jitter)
		jitter = (hal_s32_t)dev;
	samples++;
	err_sum += err;
	avg_err = err_sum / samples;
}
