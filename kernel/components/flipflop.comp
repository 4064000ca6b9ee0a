component flipflop "D type flip-flop";
pin in bit data_ "data input";
pin in bit clk "clock, rising edge writes data to out";
pin in bit set "when true, force out true";
pin in bit reset "when true, force out false; overrides set";
pin io bit out "output";
variable int oldclk;
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	if (reset)
		out = 0;
	else if (set)
		out = 1;
	else if (clk && !oldclk)
		out = data_;
	oldclk = clk;
}
