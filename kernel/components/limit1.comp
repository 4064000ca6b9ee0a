/* SPDX-License-Identifier: GPL-2.0-or-later */
/* limit1.comp - limit1(9): clamp the input to [min, max]. */
component limit1 "Limit the output signal to fall between min and max";
pin in float in;
pin out float out;
param rw float min_ = -1e20;
param rw float max_ = 1e20;
function _;
license "GPL";
;;
FUNCTION(_)
{
	double v = in;

	if (v > max_)
		v = max_;
	if (v < min_)
		v = min_;
	out = v;
}
