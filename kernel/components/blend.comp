component blend "Perform linear interpolation between two values";
pin in float in1 "First input. If select is equal to 0.0, the output is equal to in1";
pin in float in2 "Second input. If select is equal to 1.0, the output is equal to in2";
pin in float select "Select input. For values between 0.0 and 1.0, the output changes linearly from in1 to in2";
pin out float out "Output value.";
param rw bit open "If true, select values outside the range 0.0 to 1.0 give values outside the range in1 to in2. If false, outputs are clamped to the the range in1 to in2";
function _;
license "GPL";
;;
FUNCTION(_)
{
	double s = select;

	if (!open) {
		if (s < 0.0)
			s = 0.0;
		if (s > 1.0)
			s = 1.0;
	}
	/* this form gives exactly in1 at s = 0 and exactly in2 at s = 1 */
	out = in1 * (1.0 - s) + in2 * s;
}
