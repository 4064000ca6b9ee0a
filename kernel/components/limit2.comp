/* SPDX-License-Identifier: GPL-2.0-or-later */
/* limit2.comp - limit2(9): clamp to [min, max] and limit the slew rate to maxv per second. */
component limit2 """Limit the output signal to fall between min and max and limit its slew rate
to less than maxv per second.  When the signal is a position, this means that position and
velocity are limited.""";
pin in float in;
pin out float out;
pin in bit load "When TRUE, immediately set out to in, ignoring maxv";
param rw float min_ = -1e20;
param rw float max_ = 1e20;
param rw float maxv = 1e20;
variable double last_out;	/* out of the previous period: the slew limit is relative to it */
function _;
license "GPL";
;;
FUNCTION(_)
{
	double v = in, step = maxv * fperiod;

	if (v > max_)
		v = max_;
	if (v < min_)
		v = min_;
	if (!load) {
		if (v > last_out + step)
			v = last_out + step;
		if (v < last_out - step)
			v = last_out - step;
	}
	last_out = v;
	out = v;
}
