component conv_u64_s64 "Convert a value from u64 to s64";
pin in u64 in;
pin out s64 out;
pin out bit out_of_range "TRUE when 'in' is not in the range of s64";
param rw bit clamp "If TRUE, then clamp to the range of s64. If FALSE, then allow the value to \"wrap around\".";
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	rtapi_u64 x = in;

	if (x > 0x7fffffffffffffffULL) {
		out_of_range = 1;
		out = clamp ? (rtapi_s64)0x7fffffffffffffffLL : (rtapi_s64)x;	/* wraps modulo 2^64 */
	} else {
		out = (rtapi_s64)x;
		out_of_range = 0;
	}
}
