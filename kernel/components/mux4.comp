/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux4.comp - mux4(9): out follows in[sel1*2 + sel0]. */
component mux4 "Select from one of four input values";
pin in bit sel0;
pin in bit sel1 "Together, these determine which inN value is copied to out.";
pin out float out "Follows the value of one of the inN values according to the two sel values";
pin in float in0;
pin in float in1;
pin in float in2;
pin in float in3;
function _;
license "GPL";
;;
FUNCTION(_)
{
	if (sel1)
		out = sel0 ? in3 : in2;
	else
		out = sel0 ? in1 : in0;
}
