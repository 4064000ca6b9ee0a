component abs_s32 "Compute the absolute value and sign of the input signal";
pin in s32 in "input value";
pin out s32 out "output value, always non-negative";
pin out bit sign "Sign of input, false for positive, true for negative";
pin out bit is_positive "TRUE if input is positive, FALSE if input is 0 or negative";
pin out bit is_negative "TRUE if input is negative, FALSE if input is 0 or positive";
function _;
license "GPL";
;;
FUNCTION(_)
{
	rtapi_s32 x = in;

	/* -(-2147483648) does not fit in s32; the page promises a non-negative
	 * output, so that one input saturates to 2147483647. */
	if (x == -2147483647 - 1)
		out = 2147483647;
	else
		out = x < 0 ? -x : x;
	sign = x < 0;
	is_positive = x > 0;
	is_negative = x < 0;
}
