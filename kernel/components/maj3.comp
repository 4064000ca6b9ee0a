/* SPDX-License-Identifier: GPL-2.0-or-later */
/* maj3.comp - maj3(9): out is TRUE when at least two inputs are (inverted when invert is set). */
component maj3 "Compute the majority of 3 inputs";
pin in bit in1;
pin in bit in2;
pin in bit in3;
pin out bit out;
param rw bit invert;
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	bool majority = (in1 && in2) || (in1 && in3) || (in2 && in3);

	out = invert ? !majority : majority;
}
