component pers "personality and compile-time gain";
pin out s32 out;
option personality yes;
function _ nofp;
license "GPL";
;;
FUNCTION(_) { out = personality * GAIN; }
