/* SPDX-License-Identifier: GPL-2.0-or-later */
/* select8.comp - select8(9): outM is TRUE only for M == sel, and only while enable is TRUE. */
component select8 "8-bit binary match detector";
pin in s32 sel "The number of the output to set TRUE.  All other outputs well be set FALSE";
pin out bit out#[8] "Output bits.  If enable is set and the sel input is between 0 and 7, then the corresponding output bit will be set true";
param rw bit enable = TRUE "Set enable to FALSE to cause all outputs to be set FALSE";
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	int i;

	for (i = 0; i < 8; i++)
		out(i) = enable && sel == i;
}
