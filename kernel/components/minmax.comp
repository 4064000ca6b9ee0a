/* SPDX-License-Identifier: GPL-2.0-or-later */
/* minmax.comp - minmax(9): max and min hold the extremes of in since the last reset. */
component minmax "Track the minimum and maximum values of the input to the outputs";
pin in float in;
pin in bit reset "When reset is asserted, 'in' is copied to the outputs";
pin out float max_;
pin out float min_;
function _;
license "GPL";
;;
FUNCTION(_)
{
	double v = in;

	if (reset) {
		max_ = v;
		min_ = v;
		return;
	}
	if (v > max_)
		max_ = v;
	if (v < min_)
		min_ = v;
}
