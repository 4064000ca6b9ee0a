component deadzone "Return the center if within the threshold";
pin in float in;
pin out float out;
param rw float center = 0.0 "The center of the dead zone";
param rw float threshhold = 1.0 "The dead zone is \\fBcenter\\fR \\(+- (\\fBthreshhold\\fR/2)";
function _ "Update \\fBout\\fR based on \\fBin\\fR and the parameters.";
license "GPL";
;;
FUNCTION(_)
{
	double half = 0.5 * threshhold;
	double x = in;

	/* outside the zone the output is shifted towards the center by half
	 * the threshold, so it is continuous at the zone's edges */
	if (x > center + half)
		out = x - half;
	else if (x < center - half)
		out = x + half;
	else
		out = center;
}
