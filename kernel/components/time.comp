/* SPDX-License-Identifier: GPL-2.0-or-later */
/* time.comp - time(9): a cycle timer; counts hours, minutes and seconds while start is TRUE,
 * restarts from zero on each rising edge of start and holds its value while start is FALSE. */
component time "Time Converter";
description """Cycle Timer

Connect time.N.start to halui.program.is-running to complete the cycle timer.""";
pin in bit start "Run Timer";
pin out u32 seconds "Seconds";
pin out u32 minutes "Minutes";
pin out u32 hours "Hours";
variable rtapi_u64 total_ns;	/* whole nanoseconds: exact, however long the run */
variable int last_start;
function _;
author "John Thornton";
license "GPL";
;;
FUNCTION(_)
{
	rtapi_u64 s, min;
	rtapi_u32 sec, mins;

	if (start && !last_start)
		total_ns = 0;
	last_start = start;
	if (!start)
		return;
	total_ns += period;
	s = rtapi_div_u64(total_ns, 1000000000u);
	min = rtapi_div_u64_rem(s, 60, &sec);
	hours = (hal_u32_t)rtapi_div_u64_rem(min, 60, &mins);
	minutes = mins;
	seconds = sec;
}
