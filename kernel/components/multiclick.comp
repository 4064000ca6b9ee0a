/* SPDX-License-Identifier: GPL-2.0-or-later */
/* multiclick.comp - multiclick(9): single-, double-, triple- and quadruple-click detector.
 * The state pin shows where the detector is: 0 idle, 2k-1 the k-th press is down,
 * 2k the k-th click is done and the next press may come, 9 waiting for a press that
 * was held too long (or a fifth press) to be released. */
component multiclick "Single-, double-, triple-, and quadruple-click detector";
pin in bit in "The input line, this is where we look for clicks.";
pin out bit single_click "Goes high briefly when a single-click is detected on the 'in' pin.";
pin out bit single_click_only "Goes high briefly when a single-click is detected on the 'in' pin and no second click followed it.";
pin out bit double_click "Goes high briefly when a double-click is detected on the 'in' pin.";
pin out bit double_click_only "Goes high briefly when a double-click is detected on the 'in' pin and no third click followed it.";
pin out bit triple_click "Goes high briefly when a triple-click is detected on the 'in' pin.";
pin out bit triple_click_only "Goes high briefly when a triple-click is detected on the 'in' pin and no fourth click followed it.";
pin out bit quadruple_click "Goes high briefly when a quadruple-click is detected on the 'in' pin.";
pin out bit quadruple_click_only "Goes high briefly when a quadruple-click is detected on the 'in' pin and no fifth click followed it.";
pin out s32 state;
param rw bit invert_input = FALSE "If FALSE (the default), clicks start with rising edges. If TRUE, clicks start with falling edges.";
param rw u32 max_hold_ns = 250000000 "If the input is held down longer than this, it's not part of a multi-click.";
param rw u32 max_space_ns = 250000000 "If the input is released longer than this, it's not part of a multi-click.";
param rw u32 output_hold_ns = 100000000 "Positive pulses on the output pins last this long (rounded up to whole periods, at least one).";
variable int last_in;
variable rtapi_u64 elapsed_ns;
variable rtapi_u64 hold_left_ns[8];
function _ nofp "Detect single-, double-, triple-, and quadruple-clicks";
license "GPL";
;;
#define MC_IDLE 0
#define MC_WAIT_RELEASE 9

FUNCTION(_)
{
	int x = in != invert_input;
	int s = state;
	int fired = -1;		/* 0..3: the (n+1)-click pin, 4..7: the (n-3)-click-only pin */
	int k;

	if (s == MC_IDLE) {
		if (x && !last_in) {
			s = 1;
			elapsed_ns = 0;
		}
	} else if (s == MC_WAIT_RELEASE) {
		if (!x)
			s = MC_IDLE;
	} else if (s & 1) {		/* press (s + 1) / 2 is down */
		elapsed_ns += (rtapi_u64)period;
		if (!x) {
			fired = (s - 1) / 2;
			s++;
			elapsed_ns = 0;
		} else if (elapsed_ns > max_hold_ns) {
			s = MC_WAIT_RELEASE;
		}
	} else {			/* click s / 2 is done */
		elapsed_ns += (rtapi_u64)period;
		if (x) {
			s = s < 8 ? s + 1 : MC_WAIT_RELEASE;
			elapsed_ns = 0;
		} else if (elapsed_ns > max_space_ns) {
			fired = 4 + s / 2 - 1;
			s = MC_IDLE;
		}
	}
	state = s;
	last_in = x;
	if (fired >= 0)
		hold_left_ns[fired] = output_hold_ns ? output_hold_ns : 1;
	single_click = hold_left_ns[0] > 0;
	double_click = hold_left_ns[1] > 0;
	triple_click = hold_left_ns[2] > 0;
	quadruple_click = hold_left_ns[3] > 0;
	single_click_only = hold_left_ns[4] > 0;
	double_click_only = hold_left_ns[5] > 0;
	triple_click_only = hold_left_ns[6] > 0;
	quadruple_click_only = hold_left_ns[7] > 0;
	for (k = 0; k < 8; k++)
		hold_left_ns[k] = hold_left_ns[k] > (rtapi_u64)period ? hold_left_ns[k] - (rtapi_u64)period : 0;
}
