/* SPDX-License-Identifier: GPL-2.0-or-later */
/* near.comp - near(9): out is TRUE when in1 and in2 are within a factor scale of each other
 * or at most difference apart. */
component near "Determine whether two values are roughly equal.";
pin in float in1;
pin in float in2;
pin out bit out """out is true if in1 and in2 are within a factor of scale (i.e., for in1
positive, in1/scale <= in2 <= in1*scale), OR if their absolute difference is no greater than
difference (i.e., |in1-in2| <= difference).  out is false otherwise.""";
param rw float scale = 1;
param rw float difference = 0;
function _;
license "GPL";
;;
FUNCTION(_)
{
	double a = in1, b = in2;
	double lo = a / scale, hi = a * scale;

	if (lo > hi) {		/* negative in1 (or scale < 1): the factor band runs the other way */
		double t = lo;

		lo = hi;
		hi = t;
	}
	out = (b >= lo && b <= hi) || fabs(a - b) <= difference;
}
