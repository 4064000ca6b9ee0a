/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux2.comp - mux2(9): out follows in0 or in1 depending on sel. */
component mux2 "Select from one of two input values";
pin in bit sel;
pin out float out "Follows the value of in0 if sel is FALSE, or in1 if sel is TRUE";
pin in float in1;
pin in float in0;
function _;
license "GPL";
;;
FUNCTION(_)
{
	out = sel ? in1 : in0;
}
