/* SPDX-License-Identifier: GPL-2.0-or-later */
/* multiswitch.comp - multiswitch(9): a rotary selector: rising edges on up/down step position
 * through 0..top-position (wrapping), and bit-MM is TRUE for MM == position. cfg=2,4,6 makes
 * three instances with 2, 4 and 6 bits; get_count() turns cfg into the personalities. */
component multiswitch "This component toggles between a specified number of output bits";
pin in bit up = false "Receives signal to toggle up";
pin in bit down = false "Receives signal to toggle down";
pin out bit bit-##[32 : personality] = false "Output bits";
param rw u32 top_position "Number of positions";
param rw s32 position "Current state (may be set in the HAL)";
modparam dummy cfg """cfg should be a comma-separated list of sizes for example cfg=2,4,6 would
create 3 instances of 2, 4 and 6 bits respectively.  Ignore the "personality" parameter, that is
auto-generated.  Without cfg, personality=P,P,... gives the sizes; with neither, one instance of
4 bits.""";
variable int last_up;
variable int last_down;
function _;
option personality yes;
option count_function yes;
option extra_setup yes;
author "ArcEye schooner30@tiscali.co.uk / Andy Pugh andy@bodgesoc.org";
license "GPL";
;;
#define MULTISWITCH_MAX 64		/* = the size of the generated personality[] */
#define MULTISWITCH_DEFAULT_BITS 4
static int cfg[MULTISWITCH_MAX];
RTAPI_MP_ARRAY_INT(cfg, MULTISWITCH_MAX, "sizes of the instances, e.g. cfg=2,4,6");

/* Instances: one per cfg= entry (which become the personalities), else one per personality=
 * entry, else one with the default size. Init code only. Here "personality" must name the
 * personality= array, not the per-instance value the generated macro of that name gives. */
#pragma push_macro("personality")
#undef personality
static int get_count(void)
{
	int n, i;
	int *sizes = cfg[0] ? cfg : personality;

	for (n = 0; n < MULTISWITCH_MAX && sizes[n]; n++) {
		if (sizes[n] < 1 || sizes[n] > 32) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"multiswitch: %s entry %d is %d, must be 1..32 bits\n",
					sizes == cfg ? "cfg=" : "personality=", n + 1, sizes[n]);
			return -EINVAL;
		}
	}
	if (n == 0) {
		personality[0] = MULTISWITCH_DEFAULT_BITS;
		return 1;
	}
	for (i = 0; i < n; i++)
		personality[i] = sizes[i];
	return n;
}
#pragma pop_macro("personality")

EXTRA_SETUP()
{
	top_position = personality - 1;
	return 0;
}

FUNCTION(_)
{
	int i, pos = position;

	if (up && !last_up)
		pos++;
	if (down && !last_down)
		pos--;
	last_up = up;
	last_down = down;
	if (pos > (int)top_position)	/* wrap both ways; also mends a position set out of range */
		pos = 0;
	if (pos < 0)
		pos = top_position;
	position = pos;
	for (i = 0; i < personality; i++)
		bit(i) = i == pos;
}
