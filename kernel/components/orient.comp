/* SPDX-License-Identifier: GPL-2.0-or-later */
/* orient.comp - orient(9): on a rising edge of enable, compute the spindle position (in
 * revolutions) that puts the spindle at angle, turning the way mode asks. */
component orient "Provide a PID command input for orientation mode based on current spindle position, target angle and orient mode";
description """This component is designed to support a spindle orientation PID loop by providing a
command value, and fit with the motion spindle-orient support pins to support the M19 code.

The spindle is assumed to have stopped in an arbitrary position.  The spindle encoder position is
linked to the position pin.  The current value of the position pin is sampled on a positive edge
on the enable pin, and command is computed and set as follows: floor(number of full spindle
revolutions in the position sampled on positive edge) plus angle/360 (the fractional revolution)
+1/-1/0 depending on mode.

The mode pin is interpreted as follows:

0: the spindle rotates in the direction with the lesser angle, which may be clockwise or
counterclockwise.

1: the spindle always rotates clockwise (towards larger positions) to the new angle.

2: the spindle always rotates counterclockwise (towards smaller positions) to the new angle.""";
pin in bit enable "enable angular output for orientation mode";
pin in s32 mode "0: rotate - shortest move; 1: always rotate clockwise; 2: always rotate counterclockwise";
pin in float position "spindle position input, unit 1 rev";
pin in float angle "orient target position in degrees, 0 <= angle < 360";
pin out float command "target spindle position, input to PID command";
pin out float poserr "in degrees - aid for PID tuning";
variable int last_enable;
function _ "Update command based on enable, position, mode and angle.";
author "Michael Haberler";
license "GPL";
;;
FUNCTION(_)
{
	if (enable && !last_enable) {
		double pos = position;
		double turn = angle / 360.0;
		double target;

		turn -= floor(turn);	/* angles outside 0..360 name the same orientation */
		target = floor(pos) + turn;
		switch (mode) {
		case 1:			/* clockwise: only forwards */
			if (target < pos)
				target += 1.0;
			break;
		case 2:			/* counterclockwise: only backwards */
			if (target > pos)
				target -= 1.0;
			break;
		default:		/* the nearer way round */
			if (target - pos > 0.5)
				target -= 1.0;
			else if (pos - target > 0.5)
				target += 1.0;
			break;
		}
		command = target;
	}
	last_enable = enable;
	if (enable)
		poserr = (command - position) * 360.0;
}
