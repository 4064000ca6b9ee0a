/* SPDX-License-Identifier: GPL-2.0-or-later */
/* toggle2nist.comp - toggle2nist(9): turn a toggling level (from toggle) into separate on and
 * off requests for a device that reports its state on is-on. */
component toggle2nist "toggle button to nist logic";
description """toggle2nist can be used with a momentary push button connected to a toggle
component to control a device that has separate on and off inputs and has an is-on output.
If in changes state: if is-on is true then on is false and off is true; if is-on is false then
on is true and off is false.  The request stays asserted until is-on shows that the device
followed it.""";
pin in bit in;
pin in bit is_on;
pin out bit on;
pin out bit off;
variable int last_in;
variable int first = 1;		/* the first period only learns the level of in */
function _;
license "GPL";
;;
FUNCTION(_)
{
	if (first) {
		first = 0;
		last_in = in;
	}
	if (!in != !last_in) {
		last_in = in;
		on = !is_on;
		off = is_on;
	}
	/* a request ends once the device reports the state it asked for */
	if (on && is_on)
		on = 0;
	if (off && !is_on)
		off = 0;
}
