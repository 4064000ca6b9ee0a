component invert "Compute the inverse of the input signal";
description """The output will be the mathematical inverse of the input, ie \\fBout\\fR = 1/\\fBin\\fR.
The parameter \\fBdeadband\\fR can be used to control how close to 0 the denominator can be
before the output is clamped to 0. \\fBdeadband\\fR must be at least 1e-8, and must be positive.""";
pin in float in "Analog input value";
pin out float out "Analog output value";
param rw float deadband "The \\fBout\\fR will be zero if \\fBin\\fR is between -\\fBdeadband\\fR and +\\fBdeadband\\fR";
function _;
license "GPL";
;;
FUNCTION(_)
{
	double db = deadband;
	double x = in;

	/* a deadband below the documented minimum (including 0 and
	 * negative values) acts as 1e-8, so out never becomes inf */
	if (!(db >= 1e-8))
		db = 1e-8;
	if (x > -db && x < db)
		out = 0;
	else
		out = 1.0 / x;
}
