component xor2 "Two-input XOR (exclusive OR) gate";
pin in bit in0;
pin in bit in1;
pin out bit out "out is TRUE when exactly one of in0 and in1 is TRUE";
function _ nofp;
license "GPL";
;;
FUNCTION(_) { out = (in0 != 0) != (in1 != 0); }
