component twice "out = 2 * in; the code after ;; is the body of its one function";
pin in s32 in;
pin out s32 out;
function _ nofp;
license "GPL";
;;
out = 2 * in;
