component conv_u32_s32 "Convert a value from u32 to s32";
pin in u32 in;
pin out s32 out;
pin out bit out_of_range "TRUE when 'in' is not in the range of s32";
param rw bit clamp "If TRUE, then clamp to the range of s32. If FALSE, then allow the value to \"wrap around\".";
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	rtapi_u32 x = in;

	if (x > 2147483647u) {
		out_of_range = 1;
		out = clamp ? 2147483647 : (rtapi_s32)x;	/* two's complement wrap */
	} else {
		out = x;
		out_of_range = 0;
	}
}
