component conv_s32_u32 "Convert a value from s32 to u32";
pin in s32 in;
pin out u32 out;
pin out bit out_of_range "TRUE when 'in' is not in the range of u32";
param rw bit clamp "If TRUE, then clamp to the range of u32. If FALSE, then allow the value to \"wrap around\".";
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	rtapi_s32 x = in;

	if (x < 0) {
		out_of_range = 1;
		out = clamp ? 0 : (rtapi_u32)x;	/* the cast wraps modulo 2^32 */
	} else {
		out = x;
		out_of_range = 0;
	}
}
