component conv_float_s32 "Convert a value from float to s32";
pin in float in;
pin out s32 out;
pin out bit out_of_range "TRUE when 'in' is not in the range of s32";
param rw bit clamp "If TRUE, then clamp to the range of s32. If FALSE, then allow the value to \"wrap around\".";
function _ "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	/* like a C cast, the fraction is dropped (towards zero) before the
	 * range check, so 2147483647.5 still fits */
	double t = trunc(in);

	if (isnan(t)) {
		out = 0;
		out_of_range = 1;
	} else if (t > 2147483647.0 || t < -2147483648.0) {
		out_of_range = 1;
		if (clamp)
			out = t > 0 ? 2147483647 : -2147483647 - 1;
		else	/* modulo 2^32, as two's complement wraps */
			out = (rtapi_s32)(rtapi_u32)(t - 4294967296.0 * floor(t / 4294967296.0));
	} else {
		out = (rtapi_s32)t;
		out_of_range = 0;
	}
}
