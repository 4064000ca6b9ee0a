component and2 "Two-input AND gate";
pin in bit in0;
pin in bit in1;
pin out bit out "out is computed from the value of in0 and in1 according to the following rule: both TRUE gives TRUE, anything else FALSE";
function _ nofp;
license "GPL";
;;
FUNCTION(_) { out = in0 && in1; }
