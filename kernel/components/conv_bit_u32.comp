component conv_bit_u32 "Convert a value from bit to u32";
pin in bit in;
pin out u32 out;
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	out = in ? 1 : 0;
}
