component clarke3 "Clarke (3 phase to cartesian) transform";
description """The Clarke transform can be used to translate a vector quantity from a three phase
system (three components 120 degrees apart) to a two phase Cartesian system (plus a homopolar
component if the three phases don't sum to zero).

\\fBclarke3\\fR implements the general case of the transform, using all three phases.""";
pin in float a;
pin in float b;
pin in float c "three phase input vector";
pin out float x;
pin out float y "cartesian components of output";
pin out float h "homopolar component of output";
function _;
see_also "\\fBclarke2\\fR for the 'a+b+c=0' case, \\fBclarkeinv\\fR for the inverse transform.";
license "GPL";
;;
#define CLARKE3_INV_SQRT3 0.57735026918962576451

FUNCTION(_)
{
	/* amplitude-invariant form: a unit vector along phase A gives x = 1 */
	x = (2.0 * a - b - c) / 3.0;
	y = (b - c) * CLARKE3_INV_SQRT3;
	h = (a + b + c) / 3.0;
}
