/* SPDX-License-Identifier: GPL-2.0-or-later */
/* match8.comp - match8(9): out is TRUE when in is TRUE and a0..a7 equal b0..b7. */
component match8 "8-bit binary match detector";
pin in bit in = TRUE "cascade input - if false, output is false regardless of other inputs";
pin in bit a#[8];
pin in bit b#[8];
pin out bit out "true only if in is true and a[m] matches b[m] for m = 0 thru 7";
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	bool match = in;
	int i;

	for (i = 0; i < 8 && match; i++)
		if (!a(i) != !b(i))
			match = false;
	out = match;
}
