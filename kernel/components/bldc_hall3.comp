component bldc_hall3 "3-wire BLDC motor driver using Hall sensors and trapezoidal commutation.";
description """This component produces a 3-wire bipolar output. This suits upstream drivers that
interpret a negative input as a low-side drive and positive as a high-side drive. This includes the
Hostmot2 3pwmgen function, which is likely to be the most common application of this component.

The functionality of this component is now included in the generic "bldc" component.""";
pin in bit hall1 "Hall sensor signal 1";
pin in bit hall2 "Hall sensor signal 2";
pin in bit hall3 "Hall sensor signal 3";
pin in float value "PWM master amplitude input";
pin in bit dir """Forwards / reverse selection. Negative PWM amplitudes will also reverse the motor
and there will generally be a pattern that runs the motor in each direction too.""";
pin out float A_value "Output amplitude for phase A";
pin out float B_value "Output amplitude for phase B";
pin out float C_value "Output amplitude for phase C";
param rw u32 pattern = 25 """Commutation pattern to use, from 0 to 47. Default is type 25. The
table in bldc(9) lists, for each pattern, the Hall state (H1 H2 H3) at which each phase pair
B-A, C-A, C-B, A-B, A-C, B-C (source - sink) is driven. Common patterns are: 0 (30 degree
commutation) and 26, its reverse. 17 (120 degree). 18 (alternate 60 degree). 21 (300 degree,
Bodine). 22 (240 degree). 25 (60 degree commutation).""";
function _ "Interpret Hall sensor patterns and set 3-phase amplitudes";
see_also "bldc_hall6 6-wire unipolar driver for BLDC motors.";
author "Andy Pugh";
license "GPL";
;;
/* For each pattern, the Hall state (H1*4 + H2*2 + H3) at which each phase
 * pair is driven, in the page's column order B-A C-A C-B A-B A-C B-C. */
static const unsigned char bldc_hall3_states[48][6] = {
	{0, 1, 3, 7, 6, 4},	/*  0: 000 001 011 111 110 100 */
	{1, 0, 2, 6, 7, 5},	/*  1: 001 000 010 110 111 101 */
	{0, 2, 3, 7, 5, 4},	/*  2: 000 010 011 111 101 100 */
	{1, 3, 2, 6, 4, 5},	/*  3: 001 011 010 110 100 101 */
	{2, 3, 1, 5, 4, 6},	/*  4: 010 011 001 101 100 110 */
	{3, 2, 0, 4, 5, 7},	/*  5: 011 010 000 100 101 111 */
	{2, 0, 1, 5, 7, 6},	/*  6: 010 000 001 101 111 110 */
	{3, 1, 0, 4, 6, 7},	/*  7: 011 001 000 100 110 111 */
	{0, 1, 5, 7, 6, 2},	/*  8: 000 001 101 111 110 010 */
	{1, 0, 4, 6, 7, 3},	/*  9: 001 000 100 110 111 011 */
	{0, 2, 6, 7, 5, 1},	/* 10: 000 010 110 111 101 001 */
	{1, 3, 7, 6, 4, 0},	/* 11: 001 011 111 110 100 000 */
	{2, 3, 7, 5, 4, 0},	/* 12: 010 011 111 101 100 000 */
	{3, 2, 6, 4, 5, 1},	/* 13: 011 010 110 100 101 001 */
	{2, 0, 4, 5, 7, 3},	/* 14: 010 000 100 101 111 011 */
	{3, 1, 5, 4, 6, 2},	/* 15: 011 001 101 100 110 010 */
	{0, 4, 5, 7, 3, 2},	/* 16: 000 100 101 111 011 010 */
	{1, 5, 4, 6, 2, 3},	/* 17: 001 101 100 110 010 011 */
	{0, 4, 6, 7, 3, 1},	/* 18: 000 100 110 111 011 001 */
	{1, 5, 7, 6, 2, 0},	/* 19: 001 101 111 110 010 000 */
	{2, 6, 7, 5, 1, 0},	/* 20: 010 110 111 101 001 000 */
	{3, 7, 6, 4, 0, 1},	/* 21: 011 111 110 100 000 001 */
	{2, 6, 4, 5, 1, 3},	/* 22: 010 110 100 101 001 011 */
	{3, 7, 5, 4, 0, 2},	/* 23: 011 111 101 100 000 010 */
	{4, 5, 7, 3, 2, 0},	/* 24: 100 101 111 011 010 000 */
	{5, 4, 6, 2, 3, 1},	/* 25: 101 100 110 010 011 001 */
	{4, 6, 7, 3, 1, 0},	/* 26: 100 110 111 011 001 000 */
	{5, 7, 6, 2, 0, 1},	/* 27: 101 111 110 010 000 001 */
	{6, 7, 5, 1, 0, 2},	/* 28: 110 111 101 001 000 010 */
	{7, 6, 4, 0, 1, 3},	/* 29: 111 110 100 000 001 011 */
	{6, 4, 5, 1, 3, 2},	/* 30: 110 100 101 001 011 010 */
	{7, 5, 4, 0, 2, 3},	/* 31: 111 101 100 000 010 011 */
	{4, 5, 1, 3, 2, 6},	/* 32: 100 101 001 011 010 110 */
	{5, 4, 0, 2, 3, 7},	/* 33: 101 100 000 010 011 111 */
	{4, 6, 2, 3, 1, 5},	/* 34: 100 110 010 011 001 101 */
	{5, 7, 3, 2, 0, 4},	/* 35: 101 111 011 010 000 100 */
	{6, 7, 3, 1, 0, 4},	/* 36: 110 111 011 001 000 100 */
	{7, 6, 2, 0, 1, 5},	/* 37: 111 110 010 000 001 101 */
	{6, 4, 0, 1, 3, 7},	/* 38: 110 100 000 001 011 111 */
	{7, 5, 1, 0, 2, 6},	/* 39: 111 101 001 000 010 110 */
	{4, 0, 1, 3, 7, 6},	/* 40: 100 000 001 011 111 110 */
	{5, 1, 0, 2, 6, 7},	/* 41: 101 001 000 010 110 111 */
	{4, 0, 2, 3, 7, 5},	/* 42: 100 000 010 011 111 101 */
	{5, 1, 3, 2, 6, 4},	/* 43: 101 001 011 010 110 100 */
	{6, 2, 3, 1, 5, 4},	/* 44: 110 010 011 001 101 100 */
	{7, 3, 2, 0, 4, 5},	/* 45: 111 011 010 000 100 101 */
	{6, 2, 0, 1, 5, 7},	/* 46: 110 010 000 001 101 111 */
	{7, 3, 1, 0, 4, 6},	/* 47: 111 011 001 000 100 110 */
};

/* Source (+) and sink (-) phase of each column: 0 = A, 1 = B, 2 = C. */
static const unsigned char bldc_hall3_source[6] = {1, 2, 2, 0, 0, 1};
static const unsigned char bldc_hall3_sink[6] = {0, 0, 1, 1, 2, 2};

FUNCTION(_)
{
	double amp[3] = {0.0, 0.0, 0.0};
	double v = dir ? -value : value;	/* reversing swaps source and sink */
	int state = hall1 * 4 + hall2 * 2 + hall3;
	int k;

	/* a state missing from the pattern (a broken sensor, or a pattern
	 * number out of range) drives nothing rather than a wrong pair */
	if (pattern < 48) {
		for (k = 0; k < 6; k++) {
			if (bldc_hall3_states[pattern][k] == state) {
				amp[bldc_hall3_source[k]] = v;
				amp[bldc_hall3_sink[k]] = -v;
				break;
			}
		}
	}
	A_value = amp[0];
	B_value = amp[1];
	C_value = amp[2];
}
