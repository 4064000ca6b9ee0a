/* SPDX-License-Identifier: GPL-2.0-or-later */
/* knob2float.comp - knob2float(9): turn count changes (an encoder knob) into a float that moves
 * by scale per count, between min-out and max-out. */
component knob2float "Convert counts (probably from an encoder) to a float value";
pin in s32 counts "Counts";
pin in bit enable "When TRUE, output is controlled by count, when FALSE, output is fixed";
pin in float scale "Amount of output change per count";
pin out float out "Output value";
param rw float max_out = 1.0 "Maximum output value, further increases in count will be ignored";
param rw float min_out = 0.0 "Minimum output value, further decreases in count will be ignored";
variable hal_s32_t last_counts;
variable int first = 1;		/* the first period only learns the count, so loading never jumps */
function _;
license "GPL";
;;
FUNCTION(_)
{
	/* unsigned difference: correct across the s32 wrap of an encoder count */
	hal_s32_t delta = (hal_s32_t)((rtapi_u32)counts - (rtapi_u32)last_counts);
	double v = out;

	last_counts = counts;
	if (first) {
		first = 0;
		delta = 0;
	}
	if (!enable)
		return;
	v += delta * scale;
	if (v > max_out)
		v = max_out;
	if (v < min_out)
		v = min_out;
	out = v;
}
