component conv_bit_s32 "Convert a value from bit to s32";
pin in bit in_;
pin out s32 out;
function _ nofp "Update 'out' based on 'in'";
license "GPL";
;;
FUNCTION(_)
{
	out = in_ ? 1 : 0;
}
