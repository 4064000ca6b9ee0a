component ilowpass "Low-pass filter with integer inputs and outputs";
description """While it may find other applications, this component was written to create smoother
motion while jogging with an MPG.

In a machine with high acceleration, a short jog can behave almost like a step function. By putting
the \\fBilowpass\\fR component between the MPG \\fBencoder\\fR counts output and the axis
\\fBjog-counts\\fR input, this can be smoothed.

Choose \\fBscale\\fR conservatively so that during a single session there will never be more than
about 2e9/\\fBscale\\fR pulses seen on the MPG. Choose \\fBgain\\fR according to the smoothing level
desired. Divide the \\fBaxis.N.jog-scale\\fR values by \\fBscale\\fR.""";
pin in s32 in;
pin out s32 out "\\fBout\\fR tracks \\fBin\\fR*\\fBscale\\fR through a low-pass filter of \\fBgain\\fR per period.";
param rw float scale = 1024 "A scale factor applied to the output value of the low-pass filter.";
param rw float gain = .5 """Together with the period, sets the rate at which the output changes.
Useful range is between 0 and 1, with higher values causing the input value to be tracked more
quickly. For instance, a setting of 0.9 causes the output value to go 90% of the way towards the
input value in each period""";
variable double value;
function _ "Update the output based on the input and parameters";
author "Jeff Epler <jepler@unpythonic.net>";
license "GPL";
;;
FUNCTION(_)
{
	double r;

	/* LinuxCNC's arithmetic, which users' jog scales were tuned against: the filter
	 * runs on the unscaled input, the output is floor(value * scale + 0.5) converted
	 * through 64 bits and kept modulo 2^32, so a count past the s32 range wraps
	 * around as the MPG's own counts do (past +-2^63 it reads 0, as x86 gives). */
	value += (in - value) * gain;
	r = floor(value * scale + 0.5);
	if (r > -9223372036854775808.0 && r < 9223372036854775808.0)
		out = (rtapi_s32)(rtapi_u32)(rtapi_u64)(rtapi_s64)r;
	else
		out = 0;
}
