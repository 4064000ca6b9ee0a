component conv_s32_float "Convert a value from s32 to float";
pin in s32 in;
pin out float out;
function _ "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	out = in;	/* every s32 is exact in a double */
}
