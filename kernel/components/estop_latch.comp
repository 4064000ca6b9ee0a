component estop_latch """ESTOP latch which sets \\fBok-out\\fR true and \\fBfault-out\\fR false only if
\\fBok-in\\fR is true, \\fBfault-in\\fR is false, and a rising edge is seen on \\fBreset\\fR.
While \\fBok-out\\fR is true, \\fBwatchdog\\fR toggles, and can be used for chargepumps or similar needs.""";
pin in bit ok_in;
pin in bit fault_in;
pin in bit reset;
pin out bit ok_out;
pin out bit fault_out;
pin out bit watchdog;
variable int old_reset;
variable int ok;
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	if (!ok_in || fault_in)
		ok = 0;		/* any fault drops the latch at once */
	else if (reset && !old_reset)
		ok = 1;		/* only a fresh reset edge sets it again */
	old_reset = reset;
	if (ok)
		watchdog = !watchdog;
	ok_out = ok;
	fault_out = !ok;
}
