/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sum2.comp - sum2(9): out = in0 * gain0 + in1 * gain1 + offset. */
component sum2 "Sum of two inputs (each with a gain) and an offset";
pin in float in0;
pin in float in1;
pin out float out "out = in0 * gain0 + in1 * gain1 + offset";
param rw float gain0 = 1.0;
param rw float gain1 = 1.0;
param rw float offset;
function _;
license "GPL";
;;
FUNCTION(_)
{
	out = in0 * gain0 + in1 * gain1 + offset;
}
