component conv_u32_float "Convert a value from u32 to float";
pin in u32 in;
pin out float out;
function _ "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	out = in;	/* every u32 is exact in a double */
}
