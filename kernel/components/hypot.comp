component hypot "Three-input hypotenuse (Euclidean distance) calculator";
pin in float in0;
pin in float in1;
pin in float in2;
pin out float out "out = sqrt(in0^2 + in1^2 + in2^2)";
function _;
license "GPL";
;;
FUNCTION(_)
{
	double a = fabs(in0), b = fabs(in1), c = fabs(in2);
	double m = fmax(fmax(a, b), c);

	if (isinf(a) || isinf(b) || isinf(c)) {
		out = __builtin_inf();	/* even when another input is NaN, as hypot(3) */
	} else if (m > 1e150 || (m < 1e-150 && m > 0.0)) {
		/* the squares would overflow or underflow: scale by the largest */
		a /= m;
		b /= m;
		c /= m;
		out = m * sqrt(a * a + b * b + c * c);
	} else {
		out = sqrt(a * a + b * b + c * c);	/* NaN stays NaN */
	}
}
