component conv_float_u32 "Convert a value from float to u32";
pin in float in;
pin out u32 out;
pin out bit out_of_range "TRUE when 'in' is not in the range of u32";
param rw bit clamp "If TRUE, then clamp to the range of u32. If FALSE, then allow the value to \"wrap around\".";
function _ "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	/* the fraction is dropped (towards zero) before the range check */
	double t = trunc(in);

	if (isnan(t)) {
		out = 0;
		out_of_range = 1;
	} else if (t > 4294967295.0 || t < 0.0) {
		out_of_range = 1;
		if (clamp)
			out = t > 0 ? 4294967295u : 0;
		else	/* modulo 2^32 */
			out = (rtapi_u32)(t - 4294967296.0 * floor(t / 4294967296.0));
	} else {
		out = (rtapi_u32)t;
		out_of_range = 0;
	}
}
