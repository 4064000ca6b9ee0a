component clarkeinv "Inverse Clarke transform";
description """The inverse Clarke transform can be used to translate a vector quantity from
Cartesian coordinate system to a three phase system (three components 120 degrees apart).""";
pin in float x;
pin in float y "cartesian components of input";
pin in float h "homopolar component of input (usually zero)";
pin out float a;
pin out float b;
pin out float c "three phase output vector";
function _;
see_also "\\fBclarke2\\fR and \\fBclarke3\\fR for the forward transform.";
license "GPL";
;;
#define CLARKEINV_SQRT3_2 0.86602540378443864676

FUNCTION(_)
{
	/* inverse of clarke3: clarke3(clarkeinv(x, y, h)) == (x, y, h) */
	a = x + h;
	b = -0.5 * x + CLARKEINV_SQRT3_2 * y + h;
	c = -0.5 * x - CLARKEINV_SQRT3_2 * y + h;
}
