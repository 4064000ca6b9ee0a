/* SPDX-License-Identifier: GPL-2.0-or-later */
/* tristate_float.comp - tristate_float(9): drive the io pin out only while enable is TRUE. */
component tristate_float "Place a signal on an I/O pin only when enabled, similar to a tristate buffer in electronics";
pin in float in "Input value";
pin io float out "Output value";
pin in bit enable "When TRUE, copy in to out";
function _ "If enable is TRUE, copy in to out.";
license "GPL";
;;
FUNCTION(_)
{
	if (enable)
		out = in;
}
