component not "Inverter";
pin in bit in;
pin out bit out "out is the opposite of in";
function _ nofp;
license "GPL";
;;
FUNCTION(_) { out = !in; }
