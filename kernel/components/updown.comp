/* SPDX-License-Identifier: GPL-2.0-or-later */
/* updown.comp - updown(9): an up/down counter driven by rising edges, with optional clamp or
 * wraparound between min and max. */
component updown "Counts up or down, with optional limits and wraparound behavior";
pin in bit countup "Increment count when this pin goes from 0 to 1";
pin in bit countdown "Decrement count when this pin goes from 0 to 1";
pin in bit reset "Reset count when this pin goes from 0 to 1";
pin out s32 count "The current count";
param rw bit clamp "If TRUE, then clamp the output to the min and max parameters.";
param rw bit wrap """If TRUE, then wrap around when the count goes above or below the min and max
parameters.  Note that wrap implies (and overrides) clamp.""";
param rw s32 max_ = 0x7FFFFFFF "If clamp or wrap is set, count will never exceed this number";
param rw s32 min_ "If clamp or wrap is set, count will never be less than this number";
variable int last_up;		/* input levels of the previous period, for edge detection */
variable int last_down;
variable int last_reset;
function _ nofp "Process inputs and update count if necessary";
license "GPL";
;;
FUNCTION(_)
{
	/* 64-bit so that counting past the s32 range can be wrapped or clamped, never overflows */
	rtapi_s64 c = count;

	if (countup && !last_up)
		c++;
	if (countdown && !last_down)
		c--;
	if (reset && !last_reset)
		c = 0;
	last_up = countup;
	last_down = countdown;
	last_reset = reset;
	if (wrap) {
		if (c > max_)
			c = min_;
		else if (c < min_)
			c = max_;
	} else if (clamp) {
		if (c > max_)
			c = max_;
		else if (c < min_)
			c = min_;
	}
	count = (hal_s32_t)(rtapi_u32)(rtapi_u64)c;	/* unlimited: wrap at the s32 range */
}
