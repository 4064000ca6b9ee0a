component bldc "BLDC and AC-servo control component";
description """This component is designed as an interface between the most common forms of
three-phase motor feedback devices and the corresponding types of drive.

\\fBloadrt bldc cfg=qi6,aH\\fR

Each instance is described by a group of letters giving its input and output types; a comma
separates instances. Inputs (lower case): \\fBn\\fR no feedback (the rotor turns at
\\fBfrequency\\fR), \\fBh\\fR Hall sensors, \\fBa\\fR absolute encoder, \\fBq\\fR incremental
encoder (needs homing), \\fBi\\fR encoder index as home, \\fBf\\fR Fanuc 4-bit Gray code. Outputs
(upper case): \\fBB\\fR bit outputs, \\fB6\\fR six outputs instead of three, \\fBH\\fR emulated
Hall outputs, \\fBF\\fR emulated Fanuc Gray code, \\fBT\\fR force trapezoidal commutation.
Without output letters there are three bipolar phase values.

Angles are in electrical revolutions (0 to 1). Motor zero is where an unloaded motor aligns with
phase A positive and B and C negative. Sinusoidal outputs are out*cos(phase - 0/120/240 degrees);
trapezoidal outputs drive one phase pair, source +out and sink -out, chosen by the Hall
\\fBpattern\\fR or by the nearest of the six pair directions to the phase angle.

Homing: \\fBqh\\fR runs trapezoidally from the Halls until the first Hall edge fixes the encoder
offset; \\fBqi\\fR (with \\fBinit\\fR) and \\fBq\\fR alone wait for a rising edge on \\fBinit\\fR:
\\fBq\\fR holds the motor-zero vector at \\fBinitvalue\\fR for half a second and takes the
offset, \\fBqi\\fR turns the field at one electrical revolution per second (reversed by
\\fBrev\\fR) and sets \\fBindex-enable\\fR until the encoder reports the index, which is then
\\fBencoder-offset\\fR counts from motor zero.""";
pin in bit hall1 if personality & 0x01 "Hall sensor signal 1";
pin in bit hall2 if personality & 0x01 "Hall sensor signal 2";
pin in bit hall3 if personality & 0x01 "Hall sensor signal 3";
pin out bit hall_error if personality & 0x01 """Indicates that the selected hall pattern gives
inconsistent rotor position data. This can be due to the pattern being wrong for the motor, or one or
more sensors being unconnected or broken. A consistent pattern is not neceesarily valid, but an
inconsistent one can never be valid.""";
pin in bit C1 if (personality & 0x10) "Fanuc Gray-code bit 0 input";
pin in bit C2 if (personality & 0x10) "Fanuc Gray-code bit 1 input";
pin in bit C4 if (personality & 0x10) "Fanuc Gray-code bit 2 input";
pin in bit C8 if (personality & 0x10) "Fanuc Gray-code bit 3 input";
pin in float value "PWM master amplitude input";
pin in float lead_angle = 90 if personality & 0x06 "The phase lead between the electrical vector and the rotor position in degrees";
pin in bit rev """Set this pin true to reverse the motor. Negative PWM amplitudes will also reverse
the motor and there will generally be a Hall pattern that runs the motor in each direction too.""";
pin in float frequency if (personality & 0x0F) == 0 "Frequency input for motors with no feedback at all, or those with only an index (which is ignored)";
pin in float initvalue = 0.2 if personality & 0x04 "The current to be used for the homing sequence in applications where an incremental encoder is used with no hall-sensor feedback";
pin in s32 rawcounts = 0 if personality & 0x06 "Encoder counts input. This must be linked to the encoder rawcounts pin or encoder index resets will cause the motor commutation to fail";
pin io bit index_enable if personality & 0x08 """This pin should be connected to the associated
encoder index-enable pin to zero the encoder when it passes index This is only used indicate to the
bldc control component that an index has been seen""";
pin in bit init if (personality & 0x05) == 4 """A rising edge on this pin starts the motor alignment
sequence. The encoder counts are then stored in the offset parameter. Both pins can be ignored if the
encoder offset is known explicitly, such as is the case with an absolute encoder.""";
pin out bit init_done = 0 if (personality & 0x05) == 4 "Indicates homing sequence complete";
pin out float A_value if (personality & 0xF00) == 0 "Output amplitude for phase A";
pin out float B_value if (personality & 0xF00) == 0 "Output amplitude for phase B";
pin out float C_value if (personality & 0xF00) == 0 "Output amplitude for phase C";
pin out bit A_on if (personality & 0xF00) == 0x100 "Output bit for phase A";
pin out bit B_on if (personality & 0xF00) == 0x100 "Output bit for phase B";
pin out bit C_on if (personality & 0xF00) == 0x100 "Output bit for phase C";
pin out float A_high if (personality & 0xF00) == 0x200 "High-side driver for phase A";
pin out float B_high if (personality & 0xF00) == 0x200 "High-side driver for phase B";
pin out float C_high if (personality & 0xF00) == 0x200 "High-side driver for phase C";
pin out float A_low if (personality & 0xF00) == 0x200 "Low-side driver for phase A";
pin out float B_low if (personality & 0xF00) == 0x200 "Low-side driver for phase B";
pin out float C_low if (personality & 0xF00) == 0x200 "Low-side driver for phase C";
pin out bit A_high_on if (personality & 0xF00) == 0x300 "High-side driver for phase A";
pin out bit B_high_on if (personality & 0xF00) == 0x300 "High-side driver for phase B";
pin out bit C_high_on if (personality & 0xF00) == 0x300 "High-side driver for phase C";
pin out bit A_low_on if (personality & 0xF00) == 0x300 "Low-side driver for phase A";
pin out bit B_low_on if (personality & 0xF00) == 0x300 "Low-side driver for phase B";
pin out bit C_low_on if (personality & 0xF00) == 0x300 "Low-side driver for phase C";
pin out bit hall1_out if (personality & 0x400) "Hall 1 output";
pin out bit hall2_out if (personality & 0x400) "Hall 2 output";
pin out bit hall3_out if (personality & 0x400) "Hall 3 output";
pin out bit C1_out if (personality & 0x800) "Fanuc Gray-code bit 0 output";
pin out bit C2_out if (personality & 0x800) "Fanuc Gray-code bit 1 output";
pin out bit C4_out if (personality & 0x800) "Fanuc Gray-code bit 2 output";
pin out bit C8_out if (personality & 0x800) "Fanuc Gray-code bit 3 output";
pin out float phase_angle = 0 """Phase angle including lead/lag angle after encoder zeroing etc.
Useful for angle/current drives. This value has a range of 0 to 1 and measures electrical
revolutions. It will have two zeros for a 4 pole motor, three for a 6-pole etc""";
pin out float rotor_angle = 0 """Rotor angle after encoder zeroing etc. Useful for angle/current
drives which add their own phase offset such as the 8i20. This value has a range of 0 to 1 and
measures electrical revolutions. It will have two zeros for a 4 pole motor, three for a 6-pole etc""";
pin out float out "Current output, including the effect of the dir pin and the alignment sequence";
pin out bit out_dir "Direction output, high if \\fBvalue\\fR is negative XOR \\fBrev\\fR is true.";
pin out float out_abs "Absolute value of the input value";
param r s32 in_type = -1 "state machine output, will probably hide after debug (here: the input letters' bits of the personality)";
param r s32 out_type = -1 "state machine output, will probably hide after debug (here: the output letters' bits of the personality, shifted down 8)";
param rw s32 scale = 512 if personality & 0x06 "The number of encoder counts per rotor revolution.";
param rw s32 poles = 4 if personality & 0x06 """The number of motor poles. The encoder scale will be
divided by the number of pole pairs to give the number of encoder counts per electrical revolution""";
param rw s32 encoder_offset = 0 if personality & 0x0A """The offset, in encoder counts, between the
motor electrical zero and the encoder zero modulo the number of counts per electrical revolution""";
param r s32 offset_measured = 0 if personality & 0x04 "The encoder offset measured by the homing sequence (in certain modes)";
param rw float drive_offset = 0 """The angle, in degrees, applied to the commanded angle by the
drive in degrees. This value is only used during the homing sequence of drives with incremental
encoder feedback. It is used to back-calculate from commanded angle to actual phase angle. It is only
relevant to drives which expect rotor-angle input rather than phase-angle demand. Should be 0 for
most drives.""";
param rw u32 output_pattern = 25 if personality & 0x400 "Commutation pattern to be output in Hall Signal translation mode. See the description of \\fBpattern\\fR for details";
param rw u32 pattern = 25 if personality & 0x01 """Commutation pattern to use, from 0 to 47.
Default is type 25. The table (as in bldc_hall3(9)) gives, for each pattern, the Hall state
(H1 H2 H3) at which each phase pair B-A, C-A, C-B, A-B, A-C, B-C (source - sink) is driven.
Common patterns are: 0 (30 degree commutation) and 26, its reverse. 17 (120 degree). 18 (alternate
60 degree). 21 (300 degree, Bodine). 22 (240 degree). 25 (60 degree commutation).""";
modparam string cfg "one group of letters per instance, e.g. cfg=qi6,aH";
option personality yes;
option count_function yes;
variable double theta;		/* free-running angle (n, and qi homing), revolutions */
variable int homed;		/* q: the encoder offset is known */
variable int offset;		/* q: encoder counts at motor zero */
variable int old_init;
variable int aligning;		/* q/qi: the init sequence runs */
variable long align_ns;
variable int index_asked;	/* qi: index-enable set, waiting for the encoder */
variable int old_column;	/* qh: the Hall column of the previous period, -1 unknown */
function _;
author "Andy Pugh";
license "GPL";
;;
#define BLDC_H 0x01
#define BLDC_A 0x02
#define BLDC_Q 0x04
#define BLDC_I 0x08
#define BLDC_F 0x10
#define BLDC_OUT_MASK 0xF00
#define BLDC_B 0x100
#define BLDC_6 0x200
#define BLDC_HOUT 0x400
#define BLDC_FOUT 0x800
#define BLDC_T 0x1000
#define BLDC_ALIGN_NS 500000000L	/* q: how long the motor-zero vector is held */

/* For each pattern, the Hall state (H1*4 + H2*2 + H3) at which each phase
 * pair is driven, in the page's column order B-A C-A C-B A-B A-C B-C. */
static const unsigned char bldc_states[48][6] = {
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

/* Source (+) and sink (-) phase of each column: 0 = A, 1 = B, 2 = C. Column k's
 * field points at 150 + 60k degrees, so it pulls a rotor centred at 60 + 60k. */
static const unsigned char bldc_source[6] = {1, 2, 2, 0, 0, 1};
static const unsigned char bldc_sink[6] = {0, 0, 1, 1, 2, 2};

static double frac(double x)
{
	return x - floor(x);
}

/* The column of a Hall state in a pattern, or -1 when the state is not in it. */
static int hall_column(rtapi_u32 pat, int state)
{
	int k;

	if (pat >= 48)
		return -1;
	for (k = 0; k < 6; k++)
		if (bldc_states[pat][k] == state)
			return k;
	return -1;
}

/* The column whose rotor sector [30 + 60k, 90 + 60k) degrees holds the angle. */
static int angle_column(double turns)
{
	return (int)(frac(turns - 30.0 / 360.0) * 6.0) % 6;
}

/* Encoder counts per electrical revolution: scale over pole pairs (0 if unusable). */
static double counts_per_erev(rtapi_s32 counts_per_rev, rtapi_s32 npoles)
{
	if (npoles < 2)
		npoles = 2;
	return (double)counts_per_rev * 2.0 / (double)npoles;
}

static int gray_decode(int g)
{
	return g ^ (g >> 1) ^ (g >> 2) ^ (g >> 3);
}

FUNCTION(_)
{
	double amp[3] = {0.0, 0.0, 0.0};
	double v = rev ? -value : value;	/* reversing negates the drive */
	double lead = 0.25, rotor = 0.0, cper = 0.0;
	int trap = (personality & (BLDC_T | BLDC_B)) != 0;
	int column = -1;	/* trapezoidal: the phase pair to drive */
	int k;

	in_type = personality & 0xFF;
	out_type = (personality & 0xFF00) >> 8;
	if (personality & (BLDC_A | BLDC_Q)) {
		lead = lead_angle / 360.0;
		cper = counts_per_erev(scale, poles);
	}

	if (personality & BLDC_A) {
		/* absolute: the offset is a parameter, the angle always known */
		if (cper != 0.0)
			rotor = frac(fmod((double)rawcounts - (double)encoder_offset, cper) / cper);
	} else if (personality & BLDC_Q) {
		if ((personality & (BLDC_H | BLDC_I)) == BLDC_H) {
			/* qh: the first Hall edge gives the offset */
			int c = hall_column(pattern, hall1 * 4 + hall2 * 2 + hall3);

			if (!homed && c >= 0 && old_column >= 0 && c != old_column && cper != 0.0) {
				double edge = (c == (old_column + 1) % 6) ? 30.0 + 60.0 * c
								   : 30.0 + 60.0 * old_column;

				offset = (int)((double)rawcounts - edge / 360.0 * cper);
				offset_measured = offset;
				homed = 1;
			}
			old_column = c;
		} else if (personality & BLDC_I) {
			if (personality & BLDC_H) {
				if (!index_asked && !homed) {	/* qhi: ask at once, run on the Halls */
					index_enable = 1;
					index_asked = 1;
				}
			} else if (init && !old_init) {
				homed = 0;		/* qi: turn the field until the index */
				init_done = 0;
				aligning = 1;
				index_enable = 1;
				index_asked = 1;
			}
			if (index_asked && !index_enable) {
				/* the encoder saw the index: motor zero is encoder_offset on */
				offset = rawcounts + encoder_offset;
				offset_measured = offset;
				homed = 1;
				index_asked = 0;
				aligning = 0;
				if (!(personality & BLDC_H))
					init_done = 1;
			}
		} else if (init && !old_init) {
			homed = 0;		/* q: hold the motor-zero vector */
			init_done = 0;
			aligning = 1;
			align_ns = 0;
		}
		if (!(personality & BLDC_H))
			old_init = init;
		if (homed && cper != 0.0)
			rotor = frac(fmod((double)rawcounts - (double)offset, cper) / cper);
	} else if (personality & BLDC_F) {
		rotor = gray_decode(C1 + C2 * 2 + C4 * 4 + C8 * 8) / 16.0;
	} else if ((personality & 0x0F) == 0) {
		theta = frac(theta + frequency * fperiod);	/* no feedback: free running */
		rotor = theta;
		lead = 0.0;
	}

	if ((personality & BLDC_H) && !((personality & BLDC_Q) && homed)) {
		/* Halls decide: trapezoidal, at the centre of the Hall sector */
		column = hall_column(pattern, hall1 * 4 + hall2 * 2 + hall3);
		hall_error = column < 0;
		trap = 1;
		if (column >= 0)
			rotor = frac((60.0 + 60.0 * column) / 360.0);
		lead = 0.25;
	} else if (personality & BLDC_H) {
		hall_error = hall_column(pattern, hall1 * 4 + hall2 * 2 + hall3) < 0;
	}

	if (aligning && !(personality & BLDC_I)) {
		/* q: the motor-zero vector at initvalue, then take the offset */
		v = initvalue;
		rotor = 0.0;
		lead = 0.0;
		trap = 0;
		align_ns += period;
		if (align_ns >= BLDC_ALIGN_NS) {
			offset = rawcounts;
			offset_measured = offset;
			homed = 1;
			aligning = 0;
			init_done = 1;
		}
	} else if (aligning) {
		/* qi: drag the rotor round at one electrical revolution per second */
		v = initvalue;
		theta = frac(theta + (rev ? -fperiod : fperiod));
		rotor = theta;
		lead = 0.0;
		trap = 0;
	} else if ((personality & BLDC_Q) && !(personality & BLDC_H) && !homed) {
		v = 0.0;	/* not homed: no torque rather than the wrong one */
	}

	rotor_angle = rotor;
	phase_angle = frac(rotor + lead);
	out = v;
	out_dir = (value < 0) != (rev != 0);
	out_abs = fabs(value);

	if (trap) {
		if (column < 0 && !(personality & BLDC_H))
			column = angle_column(phase_angle - 0.25);
		if (column >= 0) {
			amp[bldc_source[column]] = v;
			amp[bldc_sink[column]] = -v;
		}
	} else {
		double ph = 2.0 * M_PI * phase_angle;

		amp[0] = v * cos(ph);
		amp[1] = v * cos(ph - 2.0 * M_PI / 3.0);
		amp[2] = v * cos(ph + 2.0 * M_PI / 3.0);
	}

	switch (personality & (BLDC_B | BLDC_6)) {
	case 0:
		if (!(personality & (BLDC_HOUT | BLDC_FOUT))) {
			A_value = amp[0];
			B_value = amp[1];
			C_value = amp[2];
		}
		break;
	case BLDC_B:
		if (!(personality & (BLDC_HOUT | BLDC_FOUT))) {
			A_on = amp[0] > 0;
			B_on = amp[1] > 0;
			C_on = amp[2] > 0;
		}
		break;
	case BLDC_6:
		if (!(personality & (BLDC_HOUT | BLDC_FOUT))) {
			A_high = amp[0] > 0 ? amp[0] : 0.0;
			B_high = amp[1] > 0 ? amp[1] : 0.0;
			C_high = amp[2] > 0 ? amp[2] : 0.0;
			A_low = amp[0] < 0 ? -amp[0] : 0.0;
			B_low = amp[1] < 0 ? -amp[1] : 0.0;
			C_low = amp[2] < 0 ? -amp[2] : 0.0;
		}
		break;
	default:
		if (!(personality & (BLDC_HOUT | BLDC_FOUT))) {
			A_high_on = amp[0] > 0;
			B_high_on = amp[1] > 0;
			C_high_on = amp[2] > 0;
			A_low_on = amp[0] < 0;
			B_low_on = amp[1] < 0;
			C_low_on = amp[2] < 0;
		}
		break;
	}
	if (personality & BLDC_HOUT) {
		k = output_pattern < 48 ? bldc_states[output_pattern][angle_column(rotor)] : 0;
		hall1_out = (k & 4) != 0;
		hall2_out = (k & 2) != 0;
		hall3_out = (k & 1) != 0;
	}
	if (personality & BLDC_FOUT) {
		k = (int)(rotor * 16.0) & 15;
		k ^= k >> 1;	/* binary to Gray */
		C1_out = (k & 1) != 0;
		C2_out = (k & 2) != 0;
		C4_out = (k & 4) != 0;
		C8_out = (k & 8) != 0;
	}
}

/* cfg= -> one personality per instance. The generated code keeps the
 * personality= module parameter in the array 'personality'; inside the
 * functions above that name means the instance's value, so it is undefined
 * here to reach the array (nothing after this uses the macro). */
#undef personality
static int get_count(void)
{
	int n = 0, p = 0, any = 0;
	const char *s;

	if (!cfg || !cfg[0]) {
		rtapi_print_msg(RTAPI_MSG_ERR, "bldc: cfg= is required, e.g. cfg=qi6,aH (one group of letters per motor)\n");
		return -EINVAL;
	}
	for (s = cfg;; s++) {
		if (*s == ',' || *s == '\0') {
			if (!any) {
				rtapi_print_msg(RTAPI_MSG_ERR, "bldc: cfg=%s: instance %d has no letters\n", cfg, n);
				return -EINVAL;
			}
			if (n >= __COMP_MAX_INSTANCES) {
				rtapi_print_msg(RTAPI_MSG_ERR, "bldc: cfg=%s: more than %d instances\n", cfg, __COMP_MAX_INSTANCES);
				return -EINVAL;
			}
			personality[n++] = p;
			p = 0;
			any = 0;
			if (*s == '\0')
				break;
			continue;
		}
		any = 1;
		switch (*s) {
		case 'n': break;
		case 'h': p |= BLDC_H; break;
		case 'a': p |= BLDC_A; break;
		case 'q': p |= BLDC_Q; break;
		case 'i': p |= BLDC_I; break;
		case 'f': p |= BLDC_F; break;
		case 'B': p |= BLDC_B; break;
		case '6': p |= BLDC_6; break;
		case 'H': p |= BLDC_HOUT; break;
		case 'F': p |= BLDC_FOUT; break;
		case 'T': p |= BLDC_T; break;
		default:
			rtapi_print_msg(RTAPI_MSG_ERR, "bldc: cfg=%s: unknown letter '%c' (inputs n h a q i f, outputs B 6 H F T)\n", cfg, *s);
			return -EINVAL;
		}
	}
	return n;
}
