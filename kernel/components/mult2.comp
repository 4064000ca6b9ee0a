/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mult2.comp - mult2(9): out = in0 * in1. */
component mult2 "Product of two inputs";
pin in float in0;
pin in float in1;
pin out float out "out = in0 * in1";
function _;
license "GPL";
;;
FUNCTION(_)
{
	out = in0 * in1;
}
