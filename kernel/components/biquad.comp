component biquad "Biquad IIR filter";
description """Biquad IIR filter. Implements the following transfer function:
H(z) = (n0 + n1z-1 + n2z-2) / (1+ d1z-1 + d2z-2)""";
pin in float in "Filter input.";
pin out float out "Filter output.";
pin in bit enable = 0 """Filter enable. When false, the \\fBin\\fR is passed to \\fBout\\fR without
any filtering. A transition from false to true causes filter coefficients to be calculated according
to parameters""";
pin out bit valid = 0 "When false, indicates an error occured when caclulating filter coefficients.";
param rw u32 type_ = 0 """Filter type determines the type of filter coefficients calculated. When 0,
coefficients must be loaded directly. When 1, a low pass filter is created. When 2, a notch filter is
created.""";
param rw float f0 = 250.0 "The corner frequency of the filter.";
param rw float Q = 0.7071 "The Q of the filter.";
param rw float d1 = 0.0 "1st-delayed denominator coef";
param rw float d2 = 0.0 "2nd-delayed denominator coef";
param rw float n0 = 1.0 "non-delayed numerator coef";
param rw float n1 = 0.0 "1st-delayed numerator coef";
param rw float n2 = 0.0 "2nd-delayed numerator coef";
param rw float s1 = 0.0;
param rw float s2 = 0.0;
variable int was_enabled;
function _;
license "GPL";
;;
enum { BIQUAD_DIRECT = 0, BIQUAD_LOWPASS = 1, BIQUAD_NOTCH = 2 };

/* Coefficients of a low pass or notch section at sample rate fs: the usual
 * bilinear-transform second-order sections, w0 = 2 pi f0 / fs and
 * alpha = sin(w0) / 2Q, normalised so the d0 term is 1. Returns 0, or -1
 * when type, f0 or Q cannot give a filter. c[] = n0 n1 n2 d1 d2. */
static int biquad_design(rtapi_u32 type, double f0_hz, double q, double fs, double c[5])
{
	double w0, cw, alpha, a0;

	if (type != BIQUAD_LOWPASS && type != BIQUAD_NOTCH)
		return -1;
	if (!(f0_hz > 0.0 && f0_hz < 0.5 * fs && q > 0.0))
		return -1;
	w0 = 2.0 * M_PI * f0_hz / fs;
	cw = cos(w0);
	alpha = sin(w0) / (2.0 * q);
	a0 = 1.0 + alpha;
	if (type == BIQUAD_LOWPASS) {
		c[0] = (1.0 - cw) / 2.0 / a0;
		c[1] = (1.0 - cw) / a0;
	} else {
		c[0] = 1.0 / a0;
		c[1] = -2.0 * cw / a0;
	}
	c[2] = c[0];
	c[3] = -2.0 * cw / a0;
	c[4] = (1.0 - alpha) / a0;
	return 0;
}

FUNCTION(_)
{
	double s0;

	if (!enable) {
		was_enabled = 0;
		out = in;
		return;
	}
	if (!was_enabled) {
		/* the enabling edge: design, and start from a clean state */
		was_enabled = 1;
		if (type_ == BIQUAD_DIRECT) {
			valid = 1;	/* the user's n and d parameters */
		} else {
			double c[5] = {0.0, 0.0, 0.0, 0.0, 0.0};

			valid = biquad_design(type_, f0, Q, 1.0 / fperiod, c) == 0;
			if (valid) {	/* into the parameters, so halcmd shows them */
				n0 = c[0];
				n1 = c[1];
				n2 = c[2];
				d1 = c[3];
				d2 = c[4];
			}
		}
		s1 = 0.0;
		s2 = 0.0;
	}
	if (!valid) {
		out = in;
		return;
	}
	/* direct form II: s holds the delayed intermediate values */
	s0 = in - d1 * s1 - d2 * s2;
	out = n0 * s0 + n1 * s1 + n2 * s2;
	s2 = s1;
	s1 = s0;
}
