component feedcomp "Multiply the input by the ratio of current velocity to the feed rate";
pin out float out "Proportionate output value";
pin in float in "Reference value";
pin in bit enable "Turn compensation on or off";
pin in float vel "Current velocity";
param rw float feed "Feed rate reference value";
function _;
notes "Note that if enable is false, out = in";
license "GPL";
;;
FUNCTION(_)
{
	/* with feed 0 the ratio is undefined: pass in through rather than
	 * send inf or NaN downstream */
	if (enable && feed != 0.0)
		out = in * vel / feed;
	else
		out = in;
}
