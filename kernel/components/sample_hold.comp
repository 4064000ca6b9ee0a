/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sample_hold.comp - sample_hold(9): out follows in while hold is FALSE, keeps its value while TRUE. */
component sample_hold "Sample and Hold";
pin in s32 in;
pin in bit hold;
pin out s32 out;
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	if (!hold)
		out = in;
}
