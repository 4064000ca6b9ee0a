/* SPDX-License-Identifier: GPL-2.0-or-later */
/* tristate_bit.comp - tristate_bit(9): drive the io pin out only while enable is TRUE. */
component tristate_bit "Place a signal on an I/O pin only when enabled, similar to a tristate buffer in electronics";
pin in bit in "Input value";
pin io bit out "Output value";
pin in bit enable "When TRUE, copy in to out";
function _ nofp "If enable is TRUE, copy in to out.";
license "GPL";
;;
FUNCTION(_)
{
	if (enable)
		out = in;
}
