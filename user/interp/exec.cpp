// SPDX-License-Identifier: GPL-2.0-or-later
// exec.cpp - one block in the documented order (gcode.md 3): comments, spindle and
// feed modes, F S T, M codes by group, the non-motion G codes, motion, stops. Also
// the M2/M30 reset and the M70-M73 modal state.
#include <cctype>
#include <cmath>
#include <cstring>
#include <unistd.h>

#include "impl.hpp"

namespace rs274 {

static bool keyword(const std::string& c, const char* word, std::string& rest)
{
	size_t i = 0;
	while (i < c.size() && (c[i] == ' ' || c[i] == '\t'))
		i++;
	size_t n = std::strlen(word);
	if (c.size() - i < n)
		return false;
	for (size_t k = 0; k < n; k++)
		if (std::tolower((unsigned char)c[i + k]) != word[k])
			return false;
	i += n;
	size_t j = i;
	while (j < c.size() && (c[j] == ' ' || c[j] == '\t'))
		j++;
	if (j < c.size() && c[j] == ',') {
		rest = c.substr(j + 1);
		return true;
	}
	if (j >= c.size()) {
		rest.clear();
		return true;
	}
	// PROBEOPEN/LOGOPEN take the file name after blanks too
	if (j > i) {
		rest = c.substr(j);
		return true;
	}
	return false;
}

void Interp::Impl::do_comment(const Block& b)
{
	if (!b.has_comment)
		return;
	const std::string& c = b.comment;
	std::string rest;
	auto text = [&rest] {   // the text after "KEYWORD," without leading blanks
		size_t i = rest.find_first_not_of(" \t");
		return i == std::string::npos ? std::string() : rest.substr(i);
	};
	if (keyword(c, "msg", rest)) {
		canon.message(text());
	} else if (keyword(c, "debug", rest)) {
		if (params[5599] != 0)
			canon.message(substitute(text()));
	} else if (keyword(c, "print", rest)) {
		canon.print_text(substitute(text()));
	} else if (keyword(c, "logopen", rest) || keyword(c, "logappend", rest)) {
		if (!cfg.file_output)
			fail("Log files are disabled");
		if (log_file)
			std::fclose(log_file);
		bool append = keyword(c, "logappend", rest);
		log_file = std::fopen(rest.c_str(), append ? "a" : "w");
		if (!log_file)
			fail("Unable to open log file %s", rest.c_str());
	} else if (keyword(c, "logclose", rest)) {
		if (log_file)
			std::fclose(log_file);
		log_file = nullptr;
	} else if (keyword(c, "log", rest)) {
		if (log_file) {
			std::fprintf(log_file, "%s\n", substitute(text()).c_str());
			std::fflush(log_file);
		}
	} else if (keyword(c, "probeopen", rest)) {
		if (!cfg.file_output)
			fail("Probe files are disabled");
		if (probe_file)
			std::fclose(probe_file);
		probe_file = std::fopen(rest.c_str(), "w");
		if (!probe_file)
			fail("Unable to open probe file %s", rest.c_str());
	} else if (keyword(c, "probeclose", rest)) {
		if (probe_file)
			std::fclose(probe_file);
		probe_file = nullptr;
	} else if (keyword(c, "abort", rest)) {
		fail("%s", substitute(text()).c_str());
	} else {
		canon.comment(c);
	}
}

void Interp::Impl::send_feed()
{
	canon.set_feed_rate(feed_mode == FeedMode::INVERSE_TIME ? feed : feed * unit_factor(AX_X));
}

void Interp::Impl::set_units(Units u)
{
	if (u == units)
		return;
	units = u;
	canon.use_length_units(u);
	send_feed();
}

void Interp::Impl::execute_block(Block& b)
{
	if (cfg.max_blocks > 0 && ++blocks > cfg.max_blocks)
		fail("Program exceeded %ld blocks", cfg.max_blocks);
	if (nurbs_open) {
		// gcode.md 8: only control points (X Y [P]) and the closing G5.3 in a NURBS block
		bool ok = b.m.empty() && (b.g.empty() || (b.g.size() == 1 && b.g[0] == 53));
		for (int c = 0; c < 128 && ok; c++)
			ok = !b.has[c] || c == 'x' || c == 'y' || (c == 'p' && b.g.empty());
		if (!ok)
			fail("Only X Y P control point lines and G5.3 may follow G5.2");
	}
	if (src == main_src && frames.size() == 1 && !main_started)
		for (bool h : b.has)
			main_started = main_started || h;   // more than a comment: the program has begun
	do_comment(b);

	// G96/G97
	if (b.gmode[14] == 960) {
		if (!b.w('s'))
			fail("S word missing with G96");
		css = true;
		css_max = b.w('d') ? b.v('d') : 1e30;
		css_surface = b.v('s');
		double k = (units == Units::INCH ? 12.0 : 1000.0) / (2 * M_PI) * css_surface * unit_factor(AX_X);
		canon.set_spindle_mode(0, k, css_max);
	} else if (b.gmode[14] == 970) {
		css = false;
		canon.set_spindle_mode(0, 0, 0);
	}
	// G93/G94/G95
	if (b.gmode[5] != -1) {
		FeedMode m = b.gmode[5] == 930 ? FeedMode::INVERSE_TIME
		           : b.gmode[5] == 940 ? FeedMode::UNITS_PER_MINUTE : FeedMode::UNITS_PER_REV;
		if (m != feed_mode) {
			bool was_inverse = feed_mode == FeedMode::INVERSE_TIME;
			feed_mode = m;
			canon.set_feed_mode(0, m);
			if (was_inverse || m == FeedMode::INVERSE_TIME) {
				feed = 0;   // a new F must follow (gcode.md 12)
				send_feed();
			}
		}
	}
	if (b.w('f') && feed_mode != FeedMode::INVERSE_TIME) {
		feed = b.v('f');
		send_feed();
	}
	if (b.w('s')) {
		speed = b.v('s');
		canon.set_spindle_speed(0, speed);
	}
	if (b.w('t')) {
		int n = (int)b.v('t');
		const Tool* t = tool(n);
		if (!t && (n != 0 || cfg.random_toolchanger))
			fail("Requested tool %d not found in the tool table", n);
		selected_tool = n;
		selected_pocket = t ? t->pocket : 0;
		canon.select_tool(n);
	}
	do_m_io(b);
	do_m_tool(b);
	do_m_spindle(b);
	do_m_misc(b);

	// G codes in order
	if (b.gmode[0] == 40) {
		if (!b.w('p'))
			fail("Dwell time missing with g4");
		if (b.v('p') < 0)
			fail("Negative dwell time with g4");
		canon.dwell(b.v('p'));
	}
	if (b.gmode[2] != -1) {
		static const Plane planes[] = {Plane::XY, Plane::XZ, Plane::YZ};
		int c = b.gmode[2];
		Plane p = c == 171 ? Plane::UV : c == 181 ? Plane::UW : c == 191 ? Plane::VW
		        : planes[(c - 170) / 10];
		if (p != plane) {
			if (comp != 400)
				fail("Cannot change planes with cutter radius compensation on");
			plane = p;
		}
		canon.select_plane(p);
	}
	if (b.gmode[6] != -1)
		set_units(b.gmode[6] == 200 ? Units::INCH : Units::MM);
	if (b.gmode[15] != -1)
		lathe_diameter = b.gmode[15] == 70;
	if (b.gmode[7] == 400)
		comp_stop_cmd();
	else if (b.gmode[7] != -1)
		comp_start_cmd(b, b.gmode[7]);
	if (b.gmode[8] != -1)
		do_tool_length(b, b.gmode[8]);
	if (b.gmode[12] != -1) {
		int c = b.gmode[12];
		int idx = c <= 590 ? (c - 530) / 10 : 6 + (c - 590);
		select_coord(idx);
	}
	if (b.gmode[13] != -1) {
		if (comp != 400)
			fail("Cannot change path control mode with cutter radius compensation on");
		int c = b.gmode[13];
		mc = c == 610 ? MotionControl::EXACT_PATH : c == 611 ? MotionControl::EXACT_STOP
		                                                     : MotionControl::CONTINUOUS;
		p_tol = c == 640 && b.w('p') ? b.v('p') : 0;
		q_tol = c == 640 && b.w('q') ? b.v('q') : p_tol;
		canon.set_motion_control_mode(mc, p_tol * unit_factor(AX_X));
		if (c == 640)
			canon.set_naivecam_tolerance(q_tol * unit_factor(AX_X));
	}
	if (b.gmode[3] != -1)
		incremental = b.gmode[3] == 910;
	if (b.gmode[4] != -1)
		ijk_absolute = b.gmode[4] == 901;
	if (b.gmode[10] != -1) {
		if (comp != 400)
			fail("Cannot change retract mode with cutter radius compensation on");
		retract_old_z = b.gmode[10] == 980;
	}
	switch (b.gmode[0]) {
	case 100: do_g10(b); break;
	case 53: nurbs_end(); break;
	case 280: case 281: case 300: case 301: do_g28(b, b.gmode[0]); break;
	case 520: case 920: do_g92(b, b.gmode[0]); break;
	default: break;
	}
	if (b.gmode[16] != -1)
		do_g92(b, b.gmode[16]);
	if (b.gmode[1] != -1) {
		motion = b.gmode[1];
		if (motion == 800)
			cycle_code = -1;
	}
	if (b.motion != -1)
		do_motion(b, b.gmode[0] == 530);
	do_stop(b);
}

void Interp::Impl::do_m_io(const Block& b)
{
	int c = b.mmode[5];
	if (c == -1)
		return;
	if (comp != 400)
		fail("Cannot use M62-M68 with cutter radius compensation on");
	if (c >= 62 && c <= 65) {
		if (!b.w('p'))
			fail("No valid P word with M%d", c);
		int idx = (int)std::lround(b.v('p'));
		if (c <= 63)
			canon.set_motion_output_bit(idx, c == 62);
		else
			canon.set_aux_output_bit(idx, c == 64);
	} else if (c == 66) {
		if (b.w('p') && b.w('e'))
			fail("Invalid to select both a digital and an analog input with M66");
		if (!b.w('p') && !b.w('e'))
			fail("Need to have either a valid P or a valid E word with M66");
		int l = b.w('l') ? (int)b.v('l') : 0;
		if (l > 4)
			fail("Unknown wait type %d with M66", l);
		double q = b.w('q') ? b.v('q') : 0;
		if (l != 0 && q <= 0)
			fail("Zero timeout with wait type != immediate return");
		if (l != 0 && b.w('e'))
			fail("Can't select analog input with wait type != immediate return");
		bool analog = b.w('e');
		int idx = (int)std::lround(analog ? b.v('e') : b.v('p'));
		params[5399] = canon.wait_input(idx, analog, (WaitType)l, q);
	} else {
		if (!b.w('e'))
			fail("No valid E word with M%d", c);
		if (!b.w('q'))
			fail("No valid Q word with M%d", c);
		int idx = (int)std::lround(b.v('e'));
		if (c == 67)
			canon.set_motion_output_value(idx, b.v('q'));
		else
			canon.set_aux_output_value(idx, b.v('q'));
	}
}

void Interp::Impl::do_m_tool(const Block& b)
{
	int c = b.mmode[6];
	if (c == 6) {
		if (comp != 400)
			fail("Cannot change tools with cutter radius compensation on");
		if (selected_tool < 0)
			fail("Need tool prepared -Txx- for toolchange");
		if (!cfg.tool_change_with_spindle_on) {
			canon.stop_spindle_turning(0);
			spindle_dir = 0;
		}
		if (cfg.tool_change_quill_up) {
			Pos m = mpos;
			m[AX_Z] = 0;
			canon.straight_traverse(m);
			mpos = m;
		}
		if (cfg.tool_change_at_g30) {
			Pos m = mpos;
			for (int a = 0; a < NUM_AXES; a++)
				if (axis_on[a])
					m[a] = params[5181 + a];
			canon.straight_traverse(m);
			mpos = m;
		}
		canon.change_tool(selected_tool);
		current_tool = selected_tool;
		current_pocket = selected_pocket;
	} else if (c == 61) {
		if (!b.w('q') || b.v('q') < 0 || std::fabs(b.v('q') - std::nearbyint(b.v('q'))) > 0.0001)
			fail("Need non-negative Q-word to specify tool number with M61");
		int n = (int)std::lround(b.v('q'));
		if (n != 0 && !tool(n))
			fail("Requested tool %d not found in the tool table", n);
		canon.change_tool_number(n);
		current_tool = n;
		current_pocket = tool(n) ? tool(n)->pocket : 0;
	}
}

void Interp::Impl::do_m_spindle(const Block& b)
{
	switch (b.mmode[7]) {
	case 3: spindle_dir = 1; canon.start_spindle_clockwise(0); break;
	case 4: spindle_dir = -1; canon.start_spindle_counterclockwise(0); break;
	case 5: spindle_dir = 0; canon.stop_spindle_turning(0); break;
	case 19: {
		double r = b.w('r') ? b.v('r') : 0;
		int p = b.w('p') ? (int)std::lround(b.v('p')) : 0;
		if (b.w('q') && b.v('q') <= 0)
			fail("Q word with M19 requires a value > 0");
		spindle_dir = 0;
		canon.orient_spindle(0, r + cfg.orient_offset, p);
		if (b.w('q'))
			canon.wait_spindle_orient_complete(0, b.v('q'));
		break;
	}
	case 70: frames.back().m70 = save_modal(); break;
	case 71: frames.back().m70.reset(); frames.back().m73.reset(); break;
	case 72: {
		Frame& f = frames.back();
		if (f.m70)
			restore_modal(*f.m70);
		else if (f.m73)
			restore_modal(*f.m73);
		else
			fail("Cannot restore modal state: nothing saved by M70 or M73 at this call level");
		break;
	}
	case 73: frames.back().m73 = save_modal(); break;
	default: break;
	}
	switch (b.mmode[8]) {
	case 7: mist = true; canon.mist_on(); break;
	case 8: flood = true; canon.flood_on(); break;
	case 9: mist = flood = false; canon.mist_off(); canon.flood_off(); break;
	default: break;
	}
	if (b.has_m(7) && b.has_m(8) && b.mmode[8] == 8) {
		mist = true;
		canon.mist_on();
	}
}

void Interp::Impl::do_m_misc(const Block& b)
{
	int c = b.mmode[9];
	if (c != -1) {
		if (comp != 400)
			fail("Cannot enable overrides with cutter radius compensation on");
		bool on = !b.w('p') || b.v('p') != 0;
		switch (c) {
		case 48: case 49:
			feed_override = speed_override = c == 48;
			canon.feed_override_enable(c == 48);
			canon.speed_override_enable(0, c == 48);
			break;
		case 50: feed_override = on; canon.feed_override_enable(on); break;
		case 51: speed_override = on; canon.speed_override_enable(0, on); break;
		case 52: adaptive = on; canon.adaptive_feed_enable(on); break;
		case 53: feed_hold = on; canon.feed_hold_enable(on); break;
		default: break;
		}
	}
	c = b.mmode[10];
	if (c != -1) {
		std::string name = fmt("M%d", c), path;
		for (const auto& dir : cfg.user_m_path) {
			std::string p = dir + "/" + name;
			if (::access(p.c_str(), X_OK) == 0) {
				path = p;
				break;
			}
		}
		if (path.empty())
			fail("Unknown m code used: M%d", c);
		int st = canon.user_m_code(c, path, b.w('p') ? b.v('p') : 0, b.w('q') ? b.v('q') : 0);
		if (st != 0)
			fail("M%d (%s) exited with status %d", c, path.c_str(), st);
	}
}

void Interp::Impl::do_stop(const Block& b)
{
	switch (b.mmode[4]) {
	case 0: canon.program_stop(); break;
	case 1: canon.optional_program_stop(); break;
	case 60: canon.pallet_shuttle(); canon.program_stop(); break;
	case 2: case 30: program_end(b.mmode[4]); break;
	case 98: fanuc_call(b); break;
	case 99: fanuc_return(); break;
	default: break;
	}
}

void Interp::Impl::program_end(int code)
{
	if (comp != 400)
		comp_stop_cmd();
	comp_flush();
	comp = 400;
	coord = 1;
	params[5220] = 1;
	canon.set_g5x_offset(1, g5x(1));
	canon.set_xy_rotation(rotation(1));
	plane = Plane::XY;
	canon.select_plane(plane);
	incremental = false;
	feed_mode = FeedMode::UNITS_PER_MINUTE;
	canon.set_feed_mode(0, feed_mode);
	feed = 0;
	send_feed();
	feed_override = speed_override = true;
	canon.feed_override_enable(true);
	canon.speed_override_enable(0, true);
	spindle_dir = 0;
	canon.stop_spindle_turning(0);
	if (css) {
		css = false;
		canon.set_spindle_mode(0, 0, 0);
	}
	motion = 10;
	cycle_code = -1;
	mist = flood = false;
	canon.mist_off();
	canon.flood_off();
	if (cfg.disable_g92_persistence)
		for (int i = 5210; i <= 5219; i++)
			params[i] = 0;
	if (code == 30)
		canon.pallet_shuttle();
	canon.program_end();
	ended = true;
}

ModalState Interp::Impl::save_modal() const
{
	return ModalState{units, plane, comp, incremental, feed_mode, coord, tlo, retract_old_z, css,
	                  css_max, ijk_absolute, lathe_diameter, mc, p_tol, q_tol, feed, speed,
	                  spindle_dir, mist, flood, feed_override, speed_override, adaptive, feed_hold};
}

void Interp::Impl::restore_modal(const ModalState& s)
{
	set_units(s.units);
	if (s.plane != plane) {
		plane = s.plane;
		canon.select_plane(plane);
	}
	incremental = s.incremental;
	if (s.feed_mode != feed_mode) {
		feed_mode = s.feed_mode;
		canon.set_feed_mode(0, feed_mode);
	}
	if (s.coord != coord)
		select_coord(s.coord);
	if (s.tlo != tlo) {
		tlo = s.tlo;
		canon.use_tool_length_offset(tlo);
	}
	retract_old_z = s.retract_old_z;
	ijk_absolute = s.ijk_absolute;
	lathe_diameter = s.lathe_diameter;
	if (s.css != css || s.css_max != css_max) {
		css = s.css;
		css_max = s.css_max;
		canon.set_spindle_mode(0, css ? (units == Units::INCH ? 12.0 : 1000.0) / (2 * M_PI) * css_surface * unit_factor(AX_X) : 0, css ? css_max : 0);
	}
	if (s.mc != mc || s.p_tol != p_tol) {
		mc = s.mc;
		p_tol = s.p_tol;
		q_tol = s.q_tol;
		canon.set_motion_control_mode(mc, p_tol * unit_factor(AX_X));
	}
	if (s.feed != feed) {
		feed = s.feed;
		send_feed();
	}
	if (s.speed != speed) {
		speed = s.speed;
		canon.set_spindle_speed(0, speed);
	}
	if (s.spindle_dir != spindle_dir) {
		spindle_dir = s.spindle_dir;
		if (spindle_dir == 1)
			canon.start_spindle_clockwise(0);
		else if (spindle_dir == -1)
			canon.start_spindle_counterclockwise(0);
		else
			canon.stop_spindle_turning(0);
	}
	if (s.mist != mist) {
		mist = s.mist;
		mist ? canon.mist_on() : canon.mist_off();
	}
	if (s.flood != flood) {
		flood = s.flood;
		flood ? canon.flood_on() : canon.flood_off();
	}
	if (s.feed_override != feed_override) {
		feed_override = s.feed_override;
		canon.feed_override_enable(feed_override);
	}
	if (s.speed_override != speed_override) {
		speed_override = s.speed_override;
		canon.speed_override_enable(0, speed_override);
	}
	if (s.adaptive != adaptive) {
		adaptive = s.adaptive;
		canon.adaptive_feed_enable(adaptive);
	}
	if (s.feed_hold != feed_hold) {
		feed_hold = s.feed_hold;
		canon.feed_hold_enable(feed_hold);
	}
}

}  // namespace rs274
