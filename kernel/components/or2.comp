component or2 "Two-input OR gate";
pin in bit in0;
pin in bit in1;
pin out bit out "out is TRUE when in0 or in1 (or both) is TRUE";
function _ nofp;
license "GPL";
;;
FUNCTION(_) { out = in0 || in1; }
