component conv_s64_u64 "Convert a value from s64 to u64";
pin in s64 in;
pin out u64 out;
pin out bit out_of_range "TRUE when 'in' is not in the range of u64";
param rw bit clamp "If TRUE, then clamp to the range of u64. If FALSE, then allow the value to \"wrap around\".";
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	rtapi_s64 x = in;

	if (x < 0) {
		out_of_range = 1;
		out = clamp ? 0 : (rtapi_u64)x;	/* the cast wraps modulo 2^64 */
	} else {
		out = (rtapi_u64)x;
		out_of_range = 0;
	}
}
