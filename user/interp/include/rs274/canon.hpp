// SPDX-License-Identifier: GPL-2.0-or-later
// canon.hpp - the canonical machining interface the interpreter drives.
//
// The interpreter (rs274::Interp) turns G-code into calls on a Canon. Task implements
// it to feed motion and I/O; rs274(1) implements it to print one call per line.
//
// Convention (differs from LinuxCNC's emccanon, where canon applies the offsets): every
// position passed here is already a MACHINE position in MACHINE units (mm or inch per
// [TRAJ]LINEAR_UNITS, degrees for A B C): the interpreter has applied G5x, rotation,
// G52/G92, tool length offset and unit conversion. The offset calls (SET_G5X_OFFSET,
// SET_G92_OFFSET, USE_TOOL_LENGTH_OFFSET, SET_XY_ROTATION) only report the new state
// (for displays and status); they must not move anything. Feed rates are machine
// units per minute (G94), 1/min (G93) or machine units per revolution (G95).
#pragma once
#include <array>
#include <string>

namespace rs274 {

// Axis order everywhere: X Y Z A B C U V W.
enum Axis { AX_X, AX_Y, AX_Z, AX_A, AX_B, AX_C, AX_U, AX_V, AX_W, NUM_AXES };
using Pos = std::array<double, NUM_AXES>;

enum class Plane { XY, YZ, XZ, UV, VW, UW };
enum class Units { INCH, MM };
enum class FeedMode { UNITS_PER_MINUTE, INVERSE_TIME, UNITS_PER_REV };
enum class MotionControl { EXACT_STOP, EXACT_PATH, CONTINUOUS };
enum class ProbeType { G38_2, G38_3, G38_4, G38_5 };
enum class WaitType { IMMEDIATE, RISE, FALL, HIGH, LOW };

const char* plane_name(Plane p);           // "CANON_PLANE_XY" ...
const char* units_name(Units u);           // "CANON_UNITS_INCHES" / "CANON_UNITS_MM"
const char* feed_mode_name(FeedMode m);    // "UNITS_PER_MINUTE" ...
const char* motion_control_name(MotionControl m);

// The result of a probe move, read by the interpreter right after STRAIGHT_PROBE
// (task answers once the move has finished; rs274(1) reports the target, not tripped).
struct ProbeResult {
	Pos position{};    // machine position where the probe stopped
	bool tripped = false;
};

class Canon {
public:
	virtual ~Canon() = default;

	// Each block's calls are preceded by this (file and 1-based line of the block).
	virtual void block_begin(const std::string& file, int line) = 0;

	// --- representation / settings (state reports) ---------------------------------
	virtual void use_length_units(Units u) = 0;                     // USE_LENGTH_UNITS
	virtual void select_plane(Plane p) = 0;                         // SELECT_PLANE
	virtual void set_g5x_offset(int index, const Pos& offset) = 0;  // SET_G5X_OFFSET, index 1..9
	virtual void set_xy_rotation(double degrees) = 0;               // SET_XY_ROTATION
	virtual void set_g92_offset(const Pos& offset) = 0;             // SET_G92_OFFSET
	virtual void use_tool_length_offset(const Pos& offset) = 0;     // USE_TOOL_LENGTH_OFFSET
	virtual void set_motion_control_mode(MotionControl m, double tolerance) = 0;
	virtual void set_naivecam_tolerance(double tolerance) = 0;

	// --- feed and motion ------------------------------------------------------------
	virtual void set_feed_mode(int spindle, FeedMode m) = 0;          // SET_FEED_MODE
	virtual void set_feed_rate(double rate) = 0;                      // SET_FEED_RATE
	virtual void straight_traverse(const Pos& end) = 0;               // STRAIGHT_TRAVERSE
	virtual void straight_feed(const Pos& end) = 0;                   // STRAIGHT_FEED
	// ARC_FEED: end and centre of the two plane axes (first, second: XY, YZ or ZX
	// order of the plane), rotation (+n CCW, -n CW, |n|-1 extra turns), the full end
	// position (helix axis and the other axes in it).
	virtual void arc_feed(double first_end, double second_end, double first_center,
	                      double second_center, int rotation, const Pos& end) = 0;
	virtual void straight_probe(const Pos& end, ProbeType type) = 0;  // STRAIGHT_PROBE
	virtual ProbeResult probe_result() = 0;
	virtual void rigid_tap(const Pos& end, double scale) = 0;         // RIGID_TAP
	virtual void start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode) = 0;
	virtual void stop_speed_feed_synch() = 0;
	virtual void dwell(double seconds) = 0;                           // DWELL

	// --- spindle ----------------------------------------------------------------------
	virtual void set_spindle_speed(int spindle, double rpm) = 0;
	// css_factor 0: rpm mode (G97); otherwise G96 factor k (rpm = k / radius), capped at max_rpm
	virtual void set_spindle_mode(int spindle, double css_factor, double max_rpm) = 0;
	virtual void start_spindle_clockwise(int spindle) = 0;
	virtual void start_spindle_counterclockwise(int spindle) = 0;
	virtual void stop_spindle_turning(int spindle) = 0;
	virtual void orient_spindle(int spindle, double degrees, int direction) = 0;
	virtual void wait_spindle_orient_complete(int spindle, double timeout) = 0;

	// --- coolant and overrides -------------------------------------------------------
	virtual void mist_on() = 0;
	virtual void mist_off() = 0;
	virtual void flood_on() = 0;
	virtual void flood_off() = 0;
	virtual void feed_override_enable(bool on) = 0;                   // ENABLE/DISABLE_FEED_OVERRIDE
	virtual void speed_override_enable(int spindle, bool on) = 0;     // ENABLE/DISABLE_SPEED_OVERRIDE
	virtual void adaptive_feed_enable(bool on) = 0;
	virtual void feed_hold_enable(bool on) = 0;

	// --- tools ---------------------------------------------------------------------------
	virtual void select_tool(int tool) = 0;                           // SELECT_TOOL (T)
	virtual void change_tool(int tool) = 0;                           // CHANGE_TOOL (M6)
	virtual void change_tool_number(int tool) = 0;                    // CHANGE_TOOL_NUMBER (M61)
	// SET_TOOL_TABLE_ENTRY (G10 L1/L10/L11): offsets machine units, diameter
	virtual void set_tool_table_entry(int tool, int pocket, const Pos& offset, double diameter,
	                                  double frontangle, double backangle, int orientation) = 0;
	virtual void reload_tool_table() = 0;                             // G10 L0

	// --- digital/analog I/O ----------------------------------------------------------
	virtual void set_motion_output_bit(int index, bool on) = 0;       // M62/M63
	virtual void set_aux_output_bit(int index, bool on) = 0;          // M64/M65
	virtual void set_motion_output_value(int index, double value) = 0; // M67
	virtual void set_aux_output_value(int index, double value) = 0;   // M68
	// M66: returns the value read (digital 0/1, analog value) or -1 on timeout.
	virtual double wait_input(int index, bool analog, WaitType type, double timeout) = 0;

	// --- program flow, messages ------------------------------------------------------
	virtual void comment(const std::string& text) = 0;                // COMMENT
	virtual void message(const std::string& text) = 0;                // MESSAGE (MSG, DEBUG)
	virtual void print_text(const std::string& text) = 0;             // (PRINT,...)
	virtual void program_stop() = 0;                                  // M0, M60
	virtual void optional_program_stop() = 0;                         // M1
	virtual void pallet_shuttle() = 0;                                // M60, M30
	virtual void program_end() = 0;                                   // M2, M30
	// M100..M199: run `path` with P and Q; returns the program's exit status.
	virtual int user_m_code(int code, const std::string& path, double p, double q) = 0;
	// #<_hal[name]>: the value of a HAL pin/param; false if the canon has no HAL.
	virtual bool hal_value(const std::string& name, double& value) = 0;
};

}  // namespace rs274
