// SPDX-License-Identifier: GPL-2.0-or-later
// interp.hpp - the RS274NGC interpreter (docs/interp.md). No task or HAL dependency:
// it reads G-code and calls a Canon (canon.hpp).
//
//   rs274::Config cfg = rs274::Config::from_ini("machine.ini");   // or fill by hand
//   rs274::Interp in(canon, cfg);
//   if (!in.init() || !in.open("part.ngc")) report(in.error());
//   while (true) { auto s = in.step(); if (s != rs274::Status::OK) break; }
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rs274/canon.hpp"

namespace rs274 {

struct Config {
	Units machine_units = Units::MM;       // [TRAJ]LINEAR_UNITS
	std::string axes = "XYZ";               // [TRAJ]COORDINATES (letters of X Y Z A B C U V W)
	std::string parameter_file;             // [RS274NGC]PARAMETER_FILE ("" = none)
	std::string startup_code;               // [RS274NGC]RS274NGC_STARTUP_CODE
	std::vector<std::string> subroutine_path;  // [DISPLAY]PROGRAM_PREFIX, then [RS274NGC]SUBROUTINE_PATH
	std::vector<std::string> user_m_path;      // PROGRAM_PREFIX, then [RS274NGC]USER_M_PATH
	std::string tool_table;                 // [EMCIO]TOOL_TABLE ("" = empty table)
	bool random_toolchanger = false;        // [EMCIO]RANDOM_TOOLCHANGER
	bool tool_change_quill_up = false;      // [EMCIO]TOOL_CHANGE_QUILL_UP
	bool tool_change_at_g30 = false;        // [EMCIO]TOOL_CHANGE_AT_G30
	bool tool_change_with_spindle_on = false;
	double orient_offset = 0;               // [RS274NGC]ORIENT_OFFSET
	double center_arc_tolerance_inch = 0.002828;
	double center_arc_tolerance_mm = 0.028284;
	bool disable_g92_persistence = false;
	bool disable_fanuc_style_sub = false;   // [RS274NGC]DISABLE_FANUC_STYLE_SUB: no M98/M99
	bool ini_vars = true;                   // #<_ini[section]key>
	bool hal_pin_vars = true;               // #<_hal[name]>
	std::map<std::string, std::string> ini; // "SECTION]KEY" -> value, for #<_ini[..]..>
	bool file_output = true;                // (LOGOPEN,..), (PROBEOPEN,..) may create files
	bool in_task = false;                   // #<_task>: 1 when a machine runs the program (milltask)
	// Resource limits (bad input must not hang or exhaust memory):
	long max_loop_iterations = 10000000;    // per while/do/repeat loop entry
	long max_blocks = 0;                    // blocks executed per program, 0 = unlimited
	size_t max_file_lines = 50000000;       // lines of one program or subroutine file
	// M99 in the main program restarts it; after this many restarts it ends the program
	// instead (END, as at a closing %). -1 = endless, as on a machine.
	long max_m99_restarts = -1;

	// Reads the keys above from an INI file; returns false and sets `error` on failure.
	static bool from_ini(const std::string& path, Config& cfg, std::string& error);
};

enum class Status { OK, END, ERROR };

struct Error {
	std::string file;   // program file ("" for MDI / startup code)
	int line = 0;       // 1-based line in that file
	std::string message;
	std::string to_string() const;   // "file:line: message"
};

class Interp {
public:
	Interp(Canon& canon, Config cfg);
	~Interp();
	Interp(const Interp&) = delete;
	Interp& operator=(const Interp&) = delete;

	// Loads the parameter file and tool table, reports offsets to canon and runs the
	// startup code. false on error (see error()).
	bool init();
	// Opens a program file (read whole, lines kept in memory).
	bool open(const std::string& path);
	// Opens a program given as text (tests, fuzzing); `name` is used in errors.
	bool open_text(const std::string& name, const std::string& text);
	// Reads and executes the next block. END after M2/M30 or the closing %.
	Status step();
	// Runs step() until END or ERROR.
	Status run();
	// Executes one MDI line (may call subroutines).
	Status execute_mdi(const std::string& line);
	// Abandons the open program (abort): call stack and loops dropped, modal state kept.
	void reset();
	// Writes the parameter file (gcode.md 4.2); false + error() on failure.
	bool save_parameters();
	bool save_parameters(const std::string& path);

	// Task's re-synch (after jogs, homing, abort): the machine position the next
	// move starts from, in machine units. Only when no cutter-comp move is pending.
	void set_machine_position(const Pos& p);

	void set_block_delete(bool on);
	void set_optional_stop(bool on);

	const Error& error() const;
	int line() const;                       // line of the block last read
	double parameter(int index) const;      // #index (0 if out of range)
	// The modal G codes in effect, times ten (G17 = 170, G91.1 = 911), one per group in
	// this order: motion, plane, cutter compensation, units, distance mode, feed mode,
	// coordinate system, tool length offset, canned-cycle return, path control,
	// spindle speed mode, arc distance mode, lathe diameter mode (status displays:
	// emcrsh PROGRAM_CODES).
	std::vector<int> active_g_codes() const;
	// The modal M codes in effect: spindle (3, 4, 5), mist (7), flood (8) or neither (9),
	// overrides (48 enabled, 49 disabled).
	std::vector<int> active_m_codes() const;
	bool named_parameter(const std::string& name, double& value) const;

	struct Impl;
private:
	std::unique_ptr<Impl> impl_;
};

}  // namespace rs274
