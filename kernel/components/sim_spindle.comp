/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sim_spindle.comp - sim_spindle(9): integrate a velocity command into a spindle position, and
 * clear index-enable (rebasing the position) when it passes a whole revolution. */
component sim_spindle "Simulated spindle with index pulse";
pin in float velocity_cmd "Commanded speed";
pin out float position_fb "Feedback position, in revolutions";
pin io bit index_enable "Reset position-fb to 0 at the next full rotation";
param rw float scale = 1.0 """factor applied to velocity-cmd.

The result of 'velocity-cmd * scale' be in revolutions per second.  For example, if
velocity-cmd is in revolutions/minute, scale should be set to 1/60 or 0.016666667.""";
function _;
license "GPL";
;;
FUNCTION(_)
{
	double old_pos = position_fb;
	double new_pos = old_pos + velocity_cmd * scale * fperiod;

	if (index_enable && floor(new_pos) != floor(old_pos)) {
		/* the index sits at every whole revolution: position 0 is where it was passed */
		double index = new_pos > old_pos ? floor(new_pos) : floor(old_pos);

		new_pos -= index;
		index_enable = 0;
	}
	position_fb = new_pos;
}
