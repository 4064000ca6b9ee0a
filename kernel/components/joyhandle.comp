/* SPDX-License-Identifier: GPL-2.0-or-later */
/* joyhandle.comp - joyhandle(9): a non-linear joypad curve
 * y = scale * (a*x^power + b*x) + offset with a, b chosen so the curve runs from
 * (deadband, offset) to (1, scale + offset); odd-symmetric, zero inside the deadband. */
component joyhandle "sets nonlinear joypad movements, deadbands and scales";
description """The component joyhandle uses the following formula for a non linear joypad movements:

y = (scale * (a*x^power + b*x)) + offset

The parameters a and b are adjusted in such a way, that the function starts at
(deadband,offset) and ends at (1,scale+offset).

Negative values will be treated point symmetrically to origin.  Values -deadband < x <
+deadband will be set to zero.

Values x > 1 and x < -1 will be skipped to +-(scale+offset).  Inverse mirrors the curve
about the middle of its range (it starts steep and ends flat instead).

With power one can adjust the nonlinearity (default = 2).  Default for deadband is 0.

Valid values are: power >= 1.0 (reasonable values are 1.x .. 4-5, take higher power-values for
higher deadbands (>0.5), if you want to start with a nearly horizontal slope), 0 <= deadband <
0.99 (reasonable 0.1).  Values outside these ranges are used as the nearest valid value.

An additional offset component can be set in special cases (default = 0).""";
pin in float in;
pin out float out;
param rw float power = 2.0;
param rw float deadband = 0.;
param rw float scale = 1.;
param rw float offset = 0.;
param rw bit inverse = 0;
function _;
license "GPL";
;;
/* The unit curve f on [db, 1] with f(db) = 0 and f(1) = 1. */
static double unit_curve(double x, double db, double p)
{
	double knee = pow(db, p - 1);	/* a*db^p + b*db = 0 and a + b = 1 give a = 1/(1-db^(p-1)) */
	double a;

	if (knee >= 1.0)		/* power 1: the curve is the straight line through both ends */
		return (x - db) / (1.0 - db);
	a = 1.0 / (1.0 - knee);
	return a * pow(x, p) + (1.0 - a) * x;
}

FUNCTION(_)
{
	double p = power < 1.0 ? 1.0 : power;
	double db = deadband < 0.0 ? 0.0 : deadband > 0.99 ? 0.99 : deadband;
	double x = fabs(in), y;

	if (x < db) {
		out = 0;
		return;
	}
	if (x > 1.0)
		x = 1.0;
	if (inverse)	/* point mirror inside [db, 1] x [0, 1]: same ends, opposite bend */
		y = 1.0 - unit_curve(1.0 + db - x, db, p);
	else
		y = unit_curve(x, db, p);
	y = scale * y + offset;
	out = in < 0 ? -y : y;
}
