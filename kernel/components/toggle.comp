/* SPDX-License-Identifier: GPL-2.0-or-later */
/* toggle.comp - toggle(9): each debounced press of in inverts out ("push-on, push-off"). */
component toggle "'push-on, push-off' from momentary pushbuttons";
pin in bit in "button input";
pin io bit out "on/off output";
param rw u32 debounce = 2 "debounce delay in periods";
variable int pressed;		/* debounced button state */
variable unsigned stable;	/* periods for which in has differed from pressed */
function _ nofp;
license "GPL";
;;
FUNCTION(_)
{
	if (!in == !pressed) {
		stable = 0;
		return;
	}
	/* in must keep its new level for debounce periods (at least one) before it counts */
	stable++;
	if (stable < debounce)
		return;
	stable = 0;
	pressed = in;
	if (pressed)
		out = !out;
}
