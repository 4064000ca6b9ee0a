// SPDX-License-Identifier: GPL-2.0-or-later
// impl.hpp - the interpreter's internal state (Interp::Impl) and the parsed block.
// One member-function family per file: reader.cpp (lexing, words), expr.cpp
// (expressions, parameters), params.cpp (parameter store and file), oword.cpp (flow
// control), exec.cpp (per-block order, modes, M codes), offsets.cpp (coordinate
// systems, G10/G92/G28, tool length), motion.cpp (G0-G3, probes, G33),
// cycles.cpp (canned cycles, G76), comp.cpp (cutter radius compensation),
// tools.cpp (tool table), interp.cpp (program files, stepping, public API).
#pragma once
#include <array>
#include <cstdarg>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rs274/canon.hpp"
#include "rs274/interp.hpp"

namespace rs274 {

// Thrown by every check; caught in step() and turned into Error with file:line.
struct InterpError {
	std::string message;
};
[[noreturn]] void fail(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace rs274

#include "hold_canon.hpp"

namespace rs274 {

constexpr int MAX_PARAM = 5602;          // #1 .. #5601
constexpr size_t MAX_LINE = 255;         // "Command too long" at 255 characters or more
constexpr int MAX_EXPR_DEPTH = 40;       // nested [ ] and functions in one value
constexpr int MAX_CALL_DEPTH = 10;       // "Too many subroutine levels"
constexpr int MAX_SUB_ARGS = 30;
constexpr size_t MAX_NAMED_PARAMS = 100000;  // per scope: bounded memory on hostile input

// G codes are kept as value*10 (G38.2 -> 382).
enum OKind { O_NONE, O_SUB, O_ENDSUB, O_CALL, O_RETURN, O_IF, O_ELSEIF, O_ELSE, O_ENDIF,
             O_WHILE, O_ENDWHILE, O_DO, O_BREAK, O_CONTINUE, O_REPEAT, O_ENDREPEAT,
             O_FANUC };   // O_FANUC: a bare "O<n>", a Fanuc-style program number

struct Block {
	int line = 0;
	std::array<bool, 128> has{};
	std::array<double, 128> val{};
	std::vector<int> g;               // G codes on the line (x10)
	std::vector<int> m;               // M codes on the line
	std::array<int, 17> gmode;        // modal group -> code x10, -1 = none
	std::array<int, 11> mmode;        // M group -> code, -1 = none
	bool has_comment = false;
	std::string comment;              // last comment, original case, without ( )
	OKind o = O_NONE;
	std::string o_label;              // "123" or "<name>"
	std::string o_rest;               // text after the keyword (expressions), lower case
	std::vector<std::pair<int, double>> num_sets;
	std::vector<std::pair<std::string, double>> name_sets;
	int motion = -1;                  // motion code this block executes, -1 none
	bool empty = true;

	Block() { gmode.fill(-1); mmode.fill(-1); }
	bool w(char c) const { return has[(unsigned char)c]; }
	double v(char c) const { return val[(unsigned char)c]; }
	bool has_g(int code) const;
	bool has_m(int code) const;
	bool any_axis() const;
};

struct Tool {
	int pocket = 0;
	Pos offset{};        // machine units
	double diameter = 0, frontangle = 0, backangle = 0;
	int orientation = 0;
	std::string remark;
};

// State saved by M70/M73 and restored by M72 (gcode.md section 13).
struct ModalState {
	Units units; Plane plane; int comp; bool incremental; FeedMode feed_mode; int coord;
	Pos tlo; bool retract_old_z; bool css; double css_max; bool ijk_absolute; bool lathe_diameter;
	MotionControl mc; double p_tol, q_tol; double feed, speed; int spindle_dir; bool mist, flood;
	bool feed_override, speed_override, adaptive, feed_hold;
};

struct LoopBlock {
	OKind kind;            // O_WHILE, O_DO or O_REPEAT
	std::string label;
	size_t start;          // line index of the while/do/repeat line
	long remaining = 0;    // repeat count left
	long iterations = 0;
};

struct Frame {
	std::string label;     // subroutine ("" at main level)
	int ret_src = -1;
	size_t ret_pc = 0;
	std::array<double, MAX_SUB_ARGS> saved_args{};
	std::map<std::string, double> locals;
	std::vector<LoopBlock> loops;
	std::optional<ModalState> m70;      // M70 save at this level
	std::optional<ModalState> m73;      // M73: restored on return
	bool fanuc = false;                 // M98 call: no argument scope, M99 returns
	long fanuc_left = 0;                // M98 L: runs left including this one
	size_t fanuc_start = 0;             // line index of its O<n>
};

struct Source {
	std::string name;
	std::vector<std::string> lines;
	std::map<std::string, size_t> scan_cache;   // "from|label|kinds" -> line index
};

struct SubDef { int src; size_t line; };

struct Interp::Impl {
	Impl(Canon& c, Config cfg);
	HoldCanon canon;         // forwards to the machine's canon; queues behind a held comp move
	Config cfg;
	Error err;

	// --- program sources and position ---
	std::vector<std::unique_ptr<Source>> sources;
	int src = -1;            // current source
	size_t pc = 0;           // next line index to read
	int main_src = -1;
	int mdi_src = -1;        // the one-line source MDI commands run from
	bool percent_mode = false;
	bool seen_first = false; // a non-blank line has been read in the main source
	bool ended = false;
	int cur_line = 0;
	size_t restart_pc = 0;   // where M99 in the main program restarts it (after a leading %)
	bool main_started = false; // a block of the main program ran (an O<n> now is a subprogram)
	long m99_restarts = 0;
	int sub_style = 0;       // subroutines used by this program: 1 o-word, 2 Fanuc (M98/M99)
	long blocks = 0;
	std::vector<Frame> frames;
	std::map<std::string, SubDef> subs;
	std::map<std::string, int> sub_files;       // file path -> source index

	// --- parameters ---
	std::vector<double> params;
	std::vector<char> param_in_file;
	std::map<std::string, double> globals;      // #<_name>
	std::map<std::string, double> ini_cache;
	std::FILE* log_file = nullptr;
	std::FILE* probe_file = nullptr;

	// --- machine and modal state ---
	Pos mpos{};              // machine position, machine units
	Pos g92{};               // active G52/G92 offset, machine units
	Pos tlo{};               // active tool length offset, machine units
	std::array<bool, NUM_AXES> axis_on{};
	Units units = Units::MM;
	Plane plane = Plane::XY;
	bool incremental = false, ijk_absolute = false, lathe_diameter = false;
	FeedMode feed_mode = FeedMode::UNITS_PER_MINUTE;
	double feed = 0;         // program units (per min / per rev), 1/min in G93
	double speed = 0;
	bool css = false;
	double css_max = 1e30, css_surface = 0;
	int motion = 800;        // G80
	int coord = 1;           // 1..9 = G54..G59.3
	bool retract_old_z = false;  // G98 (true) / G99
	MotionControl mc = MotionControl::CONTINUOUS;
	double p_tol = 0, q_tol = 0;
	int comp = 400;          // 400 G40, 410 G41, 411 G41.1, 420 G42, 421 G42.1
	double comp_radius = 0;
	int comp_orientation = 0;
	int spindle_dir = 0;     // 1 CW, -1 CCW, 0 stopped
	bool mist = false, flood = false;
	bool feed_override = true, speed_override = true, adaptive = false, feed_hold = true;
	bool block_delete = false, optional_stop = false;
	int current_tool = 0, current_pocket = 0, selected_tool = -1, selected_pocket = -1;
	std::map<int, Tool> tools;
	int tlo_mode = 490;      // 430, 431, 432, 490

	// canned cycle memory (sticky words, initial level)
	int cycle_code = -1;
	double cycle_old_z = 0, cycle_r = 0, cycle_z = 0, cycle_p = 0, cycle_q = 0;
	double cycle_i = 0, cycle_j = 0, cycle_k = 0;
	bool cycle_has_r = false, cycle_has_z = false, cycle_has_p = false, cycle_has_q = false;
	bool cycle_has_ijk = false;

	// splines (splines.cpp)
	bool g5_continues = false;   // the last motion was a G5: I J may be omitted
	double g5_last_pq[2] = {0, 0};
	bool nurbs_open = false;     // between G5.2 and G5.3
	int nurbs_order = 3;
	std::vector<std::array<double, 3>> nurbs_cp;   // x, y, weight
	Pos nurbs_pos{};             // the last control point (the program's current point)

	// cutter radius compensation (comp.cpp)
	struct CompMove {
		bool is_arc = false;
		Pos end{};            // program coordinates, end of the programmed move
		double cx = 0, cy = 0;// arc centre (plane coordinates, program units)
		int rotation = 0;     // arc turns (sign = direction)
		bool feed = true;     // feed or traverse
		int line = 0;
	};
	// The move held back until the next one is known (its end depends on that corner).
	struct CompHeld {
		CompMove mv;
		std::string file;     // where it came from (block_begin when it is emitted)
		int line = 0;
		double ts[2] = {0, 0};   // where the tool starts it (plane coordinates)
		double p1[2] = {0, 0};   // its nominal tool end: programmed end + radius along the normal
		double t1[2] = {0, 0};   // its end tangent
		double ro = 0;           // arc: radius of the tool centre's path at the end
		double side = 1, radius = 0;
	};
	bool comp_pending = false;   // comp_held is waiting
	CompHeld comp_held;
	Pos comp_prog{};             // programmed current point while a move is held
	bool comp_exit_next = false; // the next move in the plane follows G40
	double comp_exit_radius = 0;

	// --- reader.cpp ---
	Block read_block(const std::string& raw, int line);
	void read_o_word(const std::string& t, size_t& i, Block& b);
	void read_items(const std::string& t, size_t& i, Block& b);
	void read_comment(const std::string& text, Block& b);
	void check_block(Block& b);
	// --- expr.cpp ---
	double read_real(const std::string& t, size_t& i, int depth = 0);
	double read_expression(const std::string& t, size_t& i, int depth);
	double read_unary(const std::string& t, size_t& i, int depth);
	double read_param_ref(const std::string& t, size_t& i, int depth);
	std::string read_param_name(const std::string& t, size_t& i);
	int read_int(const std::string& t, size_t& i);
	// --- params.cpp ---
	double get_param(int idx) const;
	void set_param(int idx, double v);
	bool get_named(const std::string& name, double& v);
	void set_named(const std::string& name, double v);
	bool predefined(const std::string& name, double& v) const;
	void load_param_file();
	bool write_param_file(const std::string& path);
	std::string substitute(const std::string& text);   // DEBUG/PRINT/LOG
	// --- oword.cpp ---
	void execute_o(Block& b);
	size_t scan(const std::string& label, std::initializer_list<OKind> kinds, size_t from, bool stop_at_sub);
	void call_sub(const std::string& label, const std::vector<double>& args);
	void return_sub(bool has_value, double value);
	double eval_rest(const std::string& rest, bool required, bool& present);
	void sub_style_is(int style);
	void fanuc_call(const Block& b);
	void fanuc_return();
	size_t fanuc_find_m99(size_t from, const std::string& label);
	// --- exec.cpp ---
	void execute_block(Block& b);
	void do_comment(const Block& b);
	void do_m_io(const Block& b);
	void do_m_tool(const Block& b);
	void do_m_spindle(const Block& b);
	void do_m_misc(const Block& b);
	void do_stop(const Block& b);
	void program_end(int code);
	void set_units(Units u);
	ModalState save_modal() const;
	void restore_modal(const ModalState& s);
	void send_feed();
	// --- offsets.cpp ---
	double unit_factor(int axis) const;
	Pos g5x(int index) const;
	double rotation(int index) const;
	Pos to_machine(const Pos& prog) const;
	Pos to_program(const Pos& mach) const;
	// The programmed current point: with cutter comp a move may be pending (its end
	// is where the program is, the tool has not got there yet).
	Pos program_pos() const { return comp_pending ? comp_prog : nurbs_open ? nurbs_pos : to_program(mpos); }
	void select_coord(int index);
	void do_g10(const Block& b);
	void do_g92(const Block& b, int code);
	void do_g28(const Block& b, int code);
	void do_tool_length(const Block& b, int code);
	void report_offsets();
	// --- motion.cpp ---
	void do_motion(Block& b, bool g53);
	Pos end_point(const Block& b, const Pos& cur) const;
	void traverse(const Pos& prog);
	void feed_to(const Pos& prog);
	void do_arc(const Block& b, int code, const Pos& end);
	void arc_out(const Pos& start, const Pos& end, double cx, double cy, int rot);
	void do_probe(const Block& b, int code, const Pos& end);
	void do_g33(const Block& b, int code, const Pos& end);
	void plane_axes(int& a1, int& a2, int& a3) const;
	void check_feed(const Block& b, const char* what);
	// --- cycles.cpp ---
	void do_cycle(Block& b, int code);
	void do_g76(const Block& b);
	// --- splines.cpp ---
	double spline_tolerance() const;
	void spline_checks(const Block& b, const char* what);
	void do_spline(const Block& b, int code, const Pos& end);
	void nurbs_point(const Block& b, const Pos& end);
	void nurbs_end();
	// --- comp.cpp ---
	void comp_start_cmd(const Block& b, int code);
	void comp_stop_cmd();
	void comp_move(const CompMove& mv);
	void comp_flush();
	void comp_release(double ex, double ey);
	void comp_line_to(const Pos& prog, bool feed);
	// --- tools.cpp ---
	void load_tool_table();
	const Tool* tool(int n) const;
};

}  // namespace rs274

namespace rs274 {
// reader.cpp: the line with comments cut out (each replaced by '\x01'), blanks removed
// and lower-cased; the last comment's text in `comment`. Throws on bad comments.
std::string normalize_line(const std::string& raw, std::string* comment, bool* has_comment);
// The O-word of a line, without evaluating anything (used while skipping and scanning):
// false if the line has no O-word or its label is computed (o[...]).
bool o_header(const std::string& raw, std::string& label, OKind& kind);
bool has_m99(const std::string& raw);   // the line has an M99 word
int g_group(int code);   // modal group of G code x10, -1 unknown
int m_group(int code);   // M group, -1 unknown
std::string fmt(const char* f, ...) __attribute__((format(printf, 1, 2)));
}  // namespace rs274
