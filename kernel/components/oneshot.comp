/* SPDX-License-Identifier: GPL-2.0-or-later */
/* oneshot.comp - oneshot(9): a pulse of width seconds on out after each selected edge of in. */
component oneshot "one-shot pulse generator";
pin in bit in "Trigger input";
pin out bit out "Active high pulse";
pin out bit out_not "Active low pulse";
pin in float width = 0 "Pulse width in seconds";
pin out float time_left "Time left in current output pulse";
param rw bit retriggerable = TRUE "Allow additional edges to extend pulse";
param rw bit rising = TRUE "Trigger on rising edge";
param rw bit falling = FALSE "Trigger on falling edge";
variable int last_in;
function _ "Produce output pulses from input edges";
license "GPL";
;;
FUNCTION(_)
{
	double left = time_left;
	int edge = (in && !last_in && rising) || (!in && last_in && falling);

	last_in = in;
	if (edge && (retriggerable || left <= 0))
		left = width;
	if (left > 0) {
		out = 1;
		left -= fperiod;
		/* a width of a whole number of periods gives exactly that many periods: the sum of
		 * fperiods carries rounding error, so a millionth of a period counts as done */
		if (left < fperiod * 1e-6)
			left = 0;
	} else {
		out = 0;
	}
	out_not = !out;
	time_left = left;
}
