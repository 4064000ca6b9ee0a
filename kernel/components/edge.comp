component edge "Edge detector";
pin in bit in;
pin out bit out "Goes high when the desired edge is seen on 'in'";
pin out bit out_invert "Goes low when the desired edge is seen on 'in'";
param rw bit both = FALSE "If TRUE, selects both edges. Otherwise, selects one edge according to in-edge";
param rw bit in_edge = TRUE "Selects the desired edge: TRUE means falling, FALSE means rising";
param rw s32 out_width_ns = 0 "Time in nanoseconds of the output pulse";
param r s32 time_left_ns "Time left in this output pulse";
param r bit last_in "Previous input value";
function _ nofp "Produce output pulses from input edges";
license "GPL";
;;
FUNCTION(_)
{
	bool x = in;
	bool pulse = false;

	/* the wanted edge: any change with 'both', else a change whose new
	 * level is the opposite of in-edge (rising when FALSE, falling when TRUE) */
	if (x != last_in && (both || x != in_edge)) {
		/* the edge's own period is the first of the pulse; the pulse
		 * lasts out-width-ns rounded up to whole periods, at least one */
		pulse = true;
		time_left_ns = out_width_ns - period;
	} else if (time_left_ns > 0) {
		pulse = true;
		time_left_ns -= period;
	}
	if (time_left_ns < 0)
		time_left_ns = 0;
	out = pulse;
	out_invert = !pulse;
	last_in = x;
}
