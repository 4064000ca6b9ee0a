/* SPDX-License-Identifier: GPL-2.0-or-later */
/* timedelay.comp - timedelay(9): a time-delay relay; out follows in once in has held its new
 * level for on-delay (rising) or off-delay (falling) seconds. */
component timedelay "The equivalent of a time-delay relay";
pin in bit in;
pin out bit out "Follows the value of in after applying the delays on-delay and off-delay.";
pin in float on_delay = 0.5 "The time, in seconds, for which in must be true before out becomes true";
pin in float off_delay = 0.5 "The time, in seconds, for which in must be false before out becomes false";
pin out float elapsed "Current value of the internal timer";
function _;
author "Jeff Epler, based on works by Stephen Wille Padnos and John Kasunich";
license "GPL";
;;
FUNCTION(_)
{
	double delay = in ? on_delay : off_delay;

	if (!in == !out) {
		elapsed = 0;
		return;
	}
	elapsed = elapsed + fperiod;
	/* a delay that is a whole number of periods must take exactly that many periods, even
	 * though the sum of fperiods carries rounding error: allow a millionth of a period */
	if (elapsed >= delay - fperiod * 1e-6) {
		out = in;
		elapsed = 0;
	}
}
