component conv_s32_bit "Convert a value from s32 to bit";
pin in s32 in;
pin out bit out;
pin out bit out_of_range "TRUE when 'in' is not in the range of bit";
param rw bit clamp "If TRUE, then clamp to the range of bit. If FALSE, then allow the value to \"wrap around\".";
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	rtapi_s32 x = in;

	if (x > 1 || x < 0) {
		out_of_range = 1;
		/* unclamped, the value is stored as C stores any integer in a
		 * bool (and as LinuxCNC does): nonzero is TRUE */
		out = clamp ? x > 1 : x != 0;
	} else {
		out = x;
		out_of_range = 0;
	}
}
