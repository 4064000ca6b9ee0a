component clarke2 "Two input version of Clarke transform";
description """The Clarke transform can be used to translate a vector quantity from a three phase
system (three components 120 degrees apart) to a two phase Cartesian system.

\\fBclarke2\\fR implements a special case of the Clarke transform, which only needs two of the
three input phases. It assumes that a+b+c = 0, so it only uses phases A and B of the input.
Since the H (homopolar) output will always be zero in this case, it is not generated.""";
pin in float a;
pin in float b "first two phases of three phase input";
pin out float x;
pin out float y "cartesian components of output";
function _;
see_also "\\fBclarke3\\fR for the general case, \\fBclarkeinv\\fR for the inverse transform.";
license "GPL";
;;
/* 1/sqrt(3), as a constant so no libm call is needed */
#define CLARKE2_INV_SQRT3 0.57735026918962576451

FUNCTION(_)
{
	/* amplitude-invariant transform with c = -(a + b) */
	x = a;
	y = (a + 2.0 * b) * CLARKE2_INV_SQRT3;
}
