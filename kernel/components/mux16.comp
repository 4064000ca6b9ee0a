/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux16.comp - mux16(9): out-f / out-s follow one of sixteen inputs picked by four select bits
 * (binary or Gray code), with a debounce time and an option to ignore the all-false code. */
component mux16 "Select from one of sixteen input values";
pin in bit use_graycode """This signifies the input will use Gray code instead of binary.  Gray code
is a good choice when using physical switches because for each increment only one select input
changes at a time.""";
pin in bit suppress_no_input """This suppresses changing the output if all select lines are false.
This stops unwanted jumps in output between transitions of input, but makes in00 unavailable.""";
pin in float debounce_time """sets debounce time in seconds, e.g. .10 = a tenth of a second input must
be stable this long before outputs changes.  This helps to ignore 'noisy' switches.""";
pin in bit sel#[4] "Together, these determine which inN value is copied to out.";
pin out float out_f;
pin out s32 out_s """Follows the value of one of the inN values according to the four sel values and
whether use-graycode is active.  The s32 value will be truncated and limited to the max and min
values of signed values.""";
pin in float in##[16] "array of selectable outputs";
param r float elapsed "Current value of the internal debounce timer for debugging.";
param r s32 selected "Current value of the internal selection variable after conversion for debugging";
function _;
license "GPL";
;;
FUNCTION(_)
{
	int code = (sel(3) ? 8 : 0) | (sel(2) ? 4 : 0) | (sel(1) ? 2 : 0) | (sel(0) ? 1 : 0);
	double v;

	if (suppress_no_input && code == 0)
		return;			/* hold out-f and out-s as they are */
	if (use_graycode)
		code ^= (code >> 1) ^ (code >> 2) ^ (code >> 3);
	if (code == selected) {
		elapsed = 0;
	} else {
		/* the new code must hold for debounce-time; a millionth of a period absorbs the
		 * rounding of the summed fperiods, so whole periods count exactly */
		elapsed = elapsed + fperiod;
		if (elapsed >= debounce_time - fperiod * 1e-6) {
			selected = code;
			elapsed = 0;
		}
	}
	v = in(selected);
	out_f = v;
	if (v > 2147483647.0)
		out_s = 2147483647;
	else if (v < -2147483648.0)
		out_s = -2147483647 - 1;
	else
		out_s = (hal_s32_t)v;	/* C truncates toward zero */
}
