component ddt "Compute the derivative of the input function";
pin in float in;
pin out float out;
variable double old;
function _;
license "GPL";
;;
FUNCTION(_)
{
	double x = in;

	/* old starts at 0, so the first period sees a step from 0 to in */
	out = (x - old) / fperiod;
	old = x;
}
