component bldc_sine "Sinusoidal Brushless DC motor drive, with optional self-zeroing";
description """Computes three sinusoidal phase amplitudes, 120 degrees apart, from the rotor
position given by an encoder. Motor zero is where an unloaded motor aligns with phase A positive
and B and C negative; the output vector leads the rotor by \\fBangle\\fR degrees.

A rising edge on \\fBinit\\fR drives that alignment vector at \\fBinitvalue\\fR for half a second,
then stores the encoder count in \\fBoffset\\fR and sets \\fBinit-done\\fR.""";
pin in s32 rawcounts "Encoder counts input";
pin in bit init """A rising edge on this pin starts the motor alignment sequence. This pin should be
connected in such a way that the motors re-align any time that encoder monitoring has been
interrupted. Typically this will only be at machine power-off. The alignment process involves
powering the motor phases in such a way as to put the motor in a known position. The encoder counts
are then stored in the \\fBoffset\\fR parameter. The alignment process will tend to cause a following
error if it is triggered while the axis is enabled, so should be set before the matching
axis.N.enable pin. The complementary \\fBinit-done\\fR pin can be used to handle the required
sequencing.

Both pins can be ignored if the encoder offset is known explicitly, such as is the case with an
absolute encoder. In that case the \\fBoffset\\fR parameter can be set directly in the HAL file""";
pin out bit init_done = 0 "indicates that the motor alignment process is completed";
pin in float dir = 1 """The peak output of the three *-value pins will be the product of the
\\fBvalue\\fR pin and the \\fBdir\\fR pin. The main purpose of the pin is to invert the motor
direction sense using a scale of -1, but there is no restriction on the valid values. Typically the
component will take a bipolar +/- fullscale input from a pid function and in that case this pin will
not be wired""";
pin in float value "PWM demand";
pin in float angle = 90 "The phase lead between the electrical vector and the rotor position";
pin in float initvalue = .1 "The PWM demand to use for motor initialisation";
pin out float A_value = 0 "Output amplitude for phase A";
pin out float B_value = 0 "Output amplitude for phase B";
pin out float C_value = 0 "Output amplitude for phase C";
param rw s32 offset = 0 """The offset in encoder counts between the encoder zero position and motor
electrical zero. Can be set directly for use in absolute feedback systems or will be initialised by
the \\fBinit\\fR pin.""";
param rw float scale = 512 """The number of encoder counts per electrical revolution. eg counts/2 for
a 4-pole motor, counts/3 for a 6 pole etc. There is a 50% chance that this parameter will need to be
negative for proper function.""";
variable int old_init;
variable int aligning;
variable long align_ns;
function _;
author "Andy Pugh";
license "GPL";
;;
/* how long the alignment vector is held before the offset is taken */
#define BLDC_SINE_ALIGN_NS 500000000L

FUNCTION(_)
{
	double amp, turns, th;

	if (init && !old_init) {
		aligning = 1;
		align_ns = 0;
		init_done = 0;
	}
	old_init = init;

	if (aligning) {
		/* the motor-zero vector: A positive, B and C negative */
		A_value = initvalue;
		B_value = -0.5 * initvalue;
		C_value = -0.5 * initvalue;
		align_ns += period;
		if (align_ns >= BLDC_SINE_ALIGN_NS) {
			offset = rawcounts;
			aligning = 0;
			init_done = 1;
		}
		return;
	}

	/* electrical position in revolutions; the difference is formed in
	 * double so it cannot overflow, fmod keeps it small for precision.
	 * A zero scale has no meaning: the rotor is taken to stay at zero. */
	turns = 0.0;
	if (scale != 0.0)
		turns = fmod((double)rawcounts - (double)offset, scale) / scale;
	th = 2.0 * M_PI * turns + angle * (M_PI / 180.0);
	amp = value * dir;
	A_value = amp * cos(th);
	B_value = amp * cos(th - 2.0 * M_PI / 3.0);
	C_value = amp * cos(th + 2.0 * M_PI / 3.0);
}
