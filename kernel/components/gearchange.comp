component gearchange "Select from one two speed ranges";
description """The output will be a value scaled for the selected gear, and clamped to the min/max
values for that gear. The scale of gear 1 is assumed to be 1, so the output device scale should be
chosen accordingly. The scale of gear 2 is relative to gear 1, so if gear 2 runs the spindle 2.5 times
as fast as gear 1, scale2 should be set to 2.5.""";
pin in bit sel "Gear selection input";
pin in float speed_in "Speed command input";
pin out float speed_out "Speed command to DAC/PWM";
pin in bit dir_in "Direction command input";
pin out bit dir_out "Direction output - possibly inverted for second gear";
param rw float min1 = 0 "Minimum allowed speed in gear range 1";
param rw float max1 = 100000 "Maximum allowed speed in gear range 1";
param rw float min2 = 0 "Minimum allowed speed in gear range 2";
param rw float max2 = 100000 "Maximum allowed speed in gear range 2";
param rw float scale2 = 1.0 """Relative scale of gear 2 vs. gear 1 Since it is assumed that gear 2
is "high gear", \\fBscale2\\fR must be greater than 1, and will be reset to 1 if set lower.""";
param rw bit reverse = 0 "Set to 1 to reverse the spindle in second gear";
function _;
license "GPL";
;;
/* Clamp the magnitude of a speed to [lo, hi], keeping its sign: a negative
 * command means the other direction and must not be clamped to zero. */
static double clamp_speed(double s, double lo, double hi)
{
	double m = fabs(s);

	if (m < lo)
		m = lo;
	if (m > hi)
		m = hi;
	return s < 0 ? -m : m;
}

FUNCTION(_)
{
	if (scale2 < 1.0)
		scale2 = 1.0;	/* the page: reset to 1 if set lower */
	if (sel) {
		/* limits are spindle speeds; the motor turns scale2 times slower */
		speed_out = clamp_speed(speed_in, min2, max2) / scale2;
		dir_out = reverse ? !dir_in : dir_in;
	} else {
		speed_out = clamp_speed(speed_in, min1, max1);
		dir_out = dir_in;
	}
}
