/* SPDX-License-Identifier: GPL-2.0-or-later */
/* offset.comp - offset(9): out = in + offset; fb-out = fb-in - offset, in two functions so
 * each can sit where its signal is produced (command path and feedback path). */
component offset "Adds an offset to an input, and subtracts it from the feedback value";
pin in float offset "The offset value";
pin in float in "The input value";
pin out float out "The output value";
pin in float fb_in "The feedback input value";
pin out float fb_out "The feedback output value";
function update_output "Updated the output value by adding the offset to the input";
function update_feedback "Update the feedback value by subtracting the offset from the feedback";
license "GPL";
;;
FUNCTION(update_output)
{
	out = in + offset;
}

FUNCTION(update_feedback)
{
	fb_out = fb_in - offset;
}
