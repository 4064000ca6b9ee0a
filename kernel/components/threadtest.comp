/* SPDX-License-Identifier: GPL-2.0-or-later */
/* threadtest.comp - threadtest(9): a counter that one function increments and another clears,
 * so tests can see which functions a thread ran and how often. */
component threadtest "EMC2 HAL component for testing thread behavior";
pin out u32 count;
function increment nofp;
function reset nofp;
license "GPL";
;;
FUNCTION(increment)
{
	count = count + 1;
}

FUNCTION(reset)
{
	count = 0;
}
