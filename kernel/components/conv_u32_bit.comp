component conv_u32_bit "Convert a value from u32 to bit";
pin in u32 in;
pin out bit out;
pin out bit out_of_range "TRUE when 'in' is not in the range of bit";
param rw bit clamp "If TRUE, then clamp to the range of bit. If FALSE, then allow the value to \"wrap around\".";
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	rtapi_u32 x = in;

	if (x > 1) {
		out_of_range = 1;
		/* clamped or not, a value above 1 reads TRUE: clamping gives 1,
		 * and storing a nonzero integer in a bool gives TRUE */
		out = 1;
	} else {
		out = x;
		out_of_range = 0;
	}
}
