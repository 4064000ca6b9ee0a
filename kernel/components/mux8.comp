/* SPDX-License-Identifier: GPL-2.0-or-later */
/* mux8.comp - mux8(9): out follows in[sel2*4 + sel1*2 + sel0]. */
component mux8 "Select from one of eight input values";
pin in bit sel0;
pin in bit sel1;
pin in bit sel2 "Together, these determine which inN value is copied to out.";
pin out float out "Follows the value of one of the inN values according to the three sel values";
pin in float in#[8];
function _;
license "GPL";
;;
FUNCTION(_)
{
	out = in((sel2 ? 4 : 0) | (sel1 ? 2 : 0) | (sel0 ? 1 : 0));
}
