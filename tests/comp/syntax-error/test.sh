# Malformed .comp files: comp names the file and line and the problem, exit status 1.
tmp=${TEST_TMPDIR:-$(mktemp -d)}
cd "$tmp"
try() {	# try NAME: preprocess NAME.comp (read from stdin), print the message and status
	cat > "$1.comp"
	comp --preprocess "$1.comp" 2>&1
	echo "status $?"
}
try missing-semicolon <<'C'
component mything "x";
pin in float in0
pin out float out;
function _;
license "GPL";
;;
C
try bad-direction <<'C'
component mything;
pin inout float in0;
C
try bad-type <<'C'
component mything;
param rw double gain;
C
try array-without-hash <<'C'
component mything;
pin out bit out[8];
function _;
;;
C
try no-function <<'C'
component mything;
pin out bit out;
license "GPL";
;;
C
try unterminated-string <<'C'
component mything "never
ends;
C
try not-component <<'C'
pin in bit x;
C
try unknown-declaration <<'C'
component mything;
pins in bit x;
C
try duplicate <<'C'
component mything;
pin in bit x-y;
pin in bit x_y;
C
