/* SPDX-License-Identifier: GPL-2.0-or-later */
/* lut5.comp - lut5(9): out is bit (in-4..in-0 as a binary number) of the function table. */
component lut5 "Arbitrary 5-input logic function based on a look-up table";
pin in bit in-#[5];
pin out bit out;
param rw u32 function_;
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	unsigned row = 0;
	int i;

	for (i = 0; i < 5; i++)
		if (in(i))
			row |= 1u << i;
	out = (function_ >> row) & 1u;
}
