component abs "Compute the absolute value and sign of the input signal";
pin in float in "Analog input value";
pin out float out "Analog output value, always positive";
pin out bit sign "Sign of input, false for positive, true for negative";
pin out bit is_positive "TRUE if input is positive, FALSE if input is 0 or negative";
pin out bit is_negative "TRUE if input is negative, FALSE if input is 0 or positive";
function _;
license "GPL";
;;
FUNCTION(_)
{
	double x = in;

	/* fabs() also maps -0.0 to 0.0, so out is never negative */
	out = fabs(x);
	sign = x < 0;
	is_positive = x > 0;
	is_negative = x < 0;
}
