/* SPDX-License-Identifier: GPL-2.0-or-later */
/* thc.comp - thc(9): torch height control. Arc volts come from an encoder velocity (a
 * voltage-to-frequency card); while cutting at speed, Z is offset to hold volts-requested. */
component thc "Torch Height Control";
description """Torch Height Control Mesa THC > Mesa 5i20 Encoder > EMC THC.  The Mesa THC sends
a frequency based on the voltage detected to the encoder.  The velocity from the encoder is
converted to volts with the velocity scale parameter: volts = (encoder-vel - scale-offset) *
vel-scale.  The THCAD card sends a frequency at 0 volts so the scale offset parameter is used
to correct this.

If enabled and torch is on and X + Y velocity is within tolerance of set speed allow the THC to
offset the Z axis as needed to maintain voltage.  The tolerance is the larger of velocity-tol
percent of requested-vel and vel-tol (in velocity units).

If enabled and torch is off and the Z axis is moving up remove any correction at a rate not to
exceed the rate of movement of the Z axis.

If enabled and torch is off and there is no correction pass the Z position and feed back untouched.

If not enabled pass the Z position and feed back untouched (and forget any correction).""";
pin in float encoder_vel "Connect to hm2_5i20.0.encoder.00.velocity";
pin in float current_vel "Connect to motion.current-vel";
pin in float requested_vel "Connect to motion.requested-vel";
pin in float volts_requested "Tip Volts requested (set point)";
pin in float vel_tol "Velocity Tolerance (Corner Lock)";
pin in bit torch_on "Connect to motion.spindle-on";
pin in bit arc_ok "Arc OK from Plasma Torch";
pin in bit enable "Enable the THC, if not enabled Z position is passed through";
pin in float z_pos_in "Z Motor Position Command in from axis.n.motor-pos-cmd";
pin out float z_pos_out "Z Motor Position Command Out";
pin out float z_fb_out "Z Position Feedback to Axis";
pin out float volts "The Calculated Volts";
pin out bit vel_status "When the THC thinks we are at requested speed";
param rw float vel_scale "The scale to convert the Velocity signal to Volts";
param rw float scale_offset "The offset of the velocity input at 0 volts";
param rw float velocity_tol "The deviation percent from planned velocity";
param rw float voltage_tol "The deviation of Tip Voltage before correction takes place";
param rw float correction_vel "The amount of change in user units per period to move Z to correct";
variable double correction;	/* current Z offset, user units */
variable double last_z;		/* z-pos-in of the previous period, to see Z move up */
function _;
option singleton yes;
author "John Thornton";
license "GPLv2 or greater";
;;
FUNCTION(_)
{
	double z = z_pos_in, tol, dz;

	volts = (encoder_vel - scale_offset) * vel_scale;
	tol = requested_vel * velocity_tol * 0.01;
	if (vel_tol > tol)
		tol = vel_tol;
	vel_status = current_vel > 0 && current_vel >= requested_vel - tol;
	dz = z - last_z;
	last_z = z;
	if (!enable) {
		correction = 0;
		z_pos_out = z;
		z_fb_out = z;
		return;
	}
	if (torch_on && arc_ok && vel_status) {
		/* high volts mean the torch is too high: move down; low volts: move up */
		if (volts > volts_requested + voltage_tol)
			correction -= correction_vel;
		else if (volts < volts_requested - voltage_tol)
			correction += correction_vel;
	} else if (!torch_on && dz > 0 && correction != 0) {
		/* Z rising after the cut: take the correction out, no faster than Z moves */
		if (correction > 0)
			correction = correction > dz ? correction - dz : 0;
		else
			correction = -correction > dz ? correction + dz : 0;
	}
	z_pos_out = z + correction;
	z_fb_out = z;	/* axis sees its own command back: the offset is no following error */
}
