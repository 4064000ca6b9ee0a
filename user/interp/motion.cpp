// SPDX-License-Identifier: GPL-2.0-or-later
// motion.cpp - G0, G1, G2/G3 (centre and radius format, gcode.md 9), G38.x probes,
// G33/G33.1, G53 and polar coordinates. Canned cycles: cycles.cpp.
#include <cmath>

#include "impl.hpp"

namespace rs274 {

static const char axis_letters[] = "xyzabcuvw";

static bool is_cycle(int c) { return c == 730 || c == 740 || (c >= 810 && c <= 890); }

Pos Interp::Impl::end_point(const Block& b, const Pos& cur) const
{
	Pos p = cur;
	for (int a = 0; a < NUM_AXES; a++) {
		char l = axis_letters[a];
		if (!axis_on[a] || !b.w(l))
			continue;
		double v = b.v(l);
		if (a == AX_X && lathe_diameter)
			v /= 2;
		p[a] = incremental ? p[a] + v : v;
	}
	if (b.w('@') || b.w('^')) {
		if (plane != Plane::XY)
			fail("Polar coordinates are only allowed in the XY plane (G17)");
		if (b.w('x'))
			fail("Cannot specify both polar coordinate and X word");
		if (b.w('y'))
			fail("Cannot specify both polar coordinate and Y word");
		double r0 = std::hypot(cur[AX_X], cur[AX_Y]);
		double a0 = std::atan2(cur[AX_Y], cur[AX_X]) * 180 / M_PI;
		double r, ang;
		if (incremental) {
			if (r0 < 1e-12)
				fail("Incremental motion with polar coordinates is indeterminate when at the origin");
			r = r0 + (b.w('@') ? b.v('@') : 0);
			ang = a0 + (b.w('^') ? b.v('^') : 0);
		} else {
			r = b.w('@') ? b.v('@') : r0;
			ang = b.w('^') ? b.v('^') : a0;
		}
		p[AX_X] = r * std::cos(ang * M_PI / 180);
		p[AX_Y] = r * std::sin(ang * M_PI / 180);
	}
	return p;
}

void Interp::Impl::traverse(const Pos& prog)
{
	Pos m = to_machine(prog);
	canon.straight_traverse(m);
	mpos = m;
}

void Interp::Impl::feed_to(const Pos& prog)
{
	Pos m = to_machine(prog);
	canon.straight_feed(m);
	mpos = m;
}

void Interp::Impl::plane_axes(int& a1, int& a2, int& a3) const
{
	switch (plane) {
	case Plane::XY: a1 = AX_X; a2 = AX_Y; a3 = AX_Z; break;
	case Plane::XZ: a1 = AX_Z; a2 = AX_X; a3 = AX_Y; break;
	case Plane::YZ: a1 = AX_Y; a2 = AX_Z; a3 = AX_X; break;
	default: fail("Arcs and canned cycles are not supported in the UV, UW and VW planes");
	}
}

// G93 needs F on the line (and sends it); otherwise a non-zero feed must be set.
void Interp::Impl::check_feed(const Block& b, const char* what)
{
	if (feed_mode == FeedMode::INVERSE_TIME) {
		if (!b.w('f'))
			fail("F word missing with inverse time %s move", what);
		feed = b.v('f');
		send_feed();
	} else if (feed == 0) {
		if (std::string(what) == "g1")
			fail("Cannot do g1 with zero feed rate");
		if (std::string(what) == "arc")
			fail("Cannot make arc with zero feed rate");
		fail("Cannot probe with zero feed rate");
	}
}

void Interp::Impl::do_motion(Block& b, bool g53)
{
	int code = b.motion;
	if (is_cycle(code)) {
		do_cycle(b, code);
		return;
	}
	cycle_code = -1;
	if (g53) {
		if (code != 0 && code != 10)
			fail("Must use g0 or g1 with g53");
		if (incremental)
			fail("Cannot use g53 incremental");
		if (comp != 400)
			fail("Cannot use g53 with cutter radius comp");
		if (b.w('@') || b.w('^'))
			fail("Cannot use polar coordinates with g53");
		Pos m = mpos;
		for (int a = 0; a < NUM_AXES; a++)
			if (axis_on[a] && b.w(axis_letters[a]))
				m[a] = b.v(axis_letters[a]) * unit_factor(a);
		if (code == 10) {
			check_feed(b, "g1");
			canon.straight_feed(m);
		} else {
			canon.straight_traverse(m);
		}
		mpos = m;
		return;
	}
	Pos cur = program_pos();
	Pos end = end_point(b, cur);
	if (code != 50)
		g5_continues = false;
	switch (code) {
	case 0:
	case 10: {
		if (code == 10)
			check_feed(b, "g1");
		if (comp != 400 || comp_pending || comp_exit_next) {
			CompMove mv;
			mv.end = end;
			mv.feed = code == 10;
			mv.line = b.line;
			comp_move(mv);
		} else if (code == 0) {
			traverse(end);
		} else {
			feed_to(end);
		}
		break;
	}
	case 20:
	case 30: do_arc(b, code, end); break;
	case 330:
	case 331: do_g33(b, code, end); break;
	case 382: case 383: case 384: case 385: do_probe(b, code, end); break;
	case 760: do_g76(b); break;
	case 50: case 51: do_spline(b, code, end); break;
	case 52: nurbs_point(b, end); break;
	default: fail("Unknown g code used");
	}
}

void Interp::Impl::arc_out(const Pos& start, const Pos& end, double cx, double cy, int rot)
{
	(void)start;
	int a1, a2, a3;
	plane_axes(a1, a2, a3);
	Pos m = to_machine(end);
	Pos c = end;
	c[a1] = cx;
	c[a2] = cy;
	Pos mc = to_machine(c);
	canon.arc_feed(m[a1], m[a2], mc[a1], mc[a2], rot, m);
	mpos = m;
}

void Interp::Impl::do_arc(const Block& b, int code, const Pos& end)
{
	int a1, a2, a3;
	plane_axes(a1, a2, a3);
	static const char* const pname[] = {"xy", "xz", "yz"};
	int pi = plane == Plane::XY ? 0 : plane == Plane::XZ ? 1 : 2;
	// centre words of the first and second plane axis, and the forbidden one
	char w1 = "xyzabcuvw"[a1] == 'x' ? 'i' : "xyzabcuvw"[a1] == 'y' ? 'j' : 'k';
	char w2 = "xyzabcuvw"[a2] == 'x' ? 'i' : "xyzabcuvw"[a2] == 'y' ? 'j' : 'k';
	char bad = plane == Plane::XY ? 'k' : plane == Plane::XZ ? 'j' : 'i';
	if (b.w(bad))
		fail("%c word given for arc in %s plane", bad - 32, pname[pi]);
	bool has_r = b.w('r'), has_c = b.w(w1) || b.w(w2);
	if (has_r && has_c)
		fail("Mixed radius ijk format for arc");
	if (!has_r && !has_c)
		fail("R i j k words all missing for arc");
	check_feed(b, "arc");
	if (comp != 400 || comp_pending || comp_exit_next) {
		if (comp_exit_next && comp == 400)
			fail("The move just after exiting cutter compensation mode must be straight, not an arc");
	}
	int turns = b.w('p') ? (int)std::lround(b.v('p')) : 1;
	Pos cur = program_pos();
	double sx = cur[a1], sy = cur[a2], ex = end[a1], ey = end[a2];
	double tiny = units == Units::INCH ? 0.00005 : 0.00127;
	double cx, cy;
	if (has_r) {
		if (!b.w(axis_letters[a1]) && !b.w(axis_letters[a2]))
			fail("%c and %c words missing for arc in %s plane", pi == 2 ? 'Y' : 'X',
			     pi == 0 ? 'y' : 'z', pname[pi]);
		if (std::hypot(ex - sx, ey - sy) < 1e-12)
			fail("Current point same as end point of arc");
		double R = b.v('r');
		double mx = (sx + ex) / 2, my = (sy + ey) / 2;
		double h = std::hypot(ex - mx, ey - my);
		if (h - std::fabs(R) > tiny)
			fail("Arc radius too small to reach end point");
		if (R == 0)
			fail("Zero radius arc");
		double ratio = h / std::fabs(R);
		if (ratio > 1 - 1e-12)
			ratio = 1;
		double phi = std::atan2(ey - sy, ex - sx);
		double theta = ((code == 20 && R > 0) || (code == 30 && R < 0)) ? phi - M_PI / 2 : phi + M_PI / 2;
		double d = std::fabs(R) * std::cos(std::asin(ratio));
		cx = mx + d * std::cos(theta);
		cy = my + d * std::sin(theta);
	} else {
		if (ijk_absolute) {
			if (!b.w(w1))
				fail("%c word missing in absolute center arc", w1 - 32);
			if (!b.w(w2))
				fail("%c word missing in absolute center arc", w2 - 32);
			cx = b.v(w1);
			cy = b.v(w2);
			if (lathe_diameter && a1 == AX_X)
				cx /= 2;
			if (lathe_diameter && a2 == AX_X)
				cy /= 2;
		} else {
			cx = sx + (b.w(w1) ? b.v(w1) : 0);
			cy = sy + (b.w(w2) ? b.v(w2) : 0);
		}
		double r1 = std::hypot(sx - cx, sy - cy), r2 = std::hypot(ex - cx, ey - cy);
		if (r1 < tiny || r2 < tiny)
			fail("Zero radius arc");
		double T = units == Units::INCH ? cfg.center_arc_tolerance_inch : cfg.center_arc_tolerance_mm;
		double d = std::fabs(r1 - r2), rel = d / std::max(r1, r2);
		if (d > 100 * T || (rel > 0.001 && d > T))
			fail("Radius to end of arc differs from radius to start: start=(%.4f,%.4f) "
			     "center=(%.4f,%.4f) end=(%.4f,%.4f) r1=%.4f r2=%.4f abs_err=%.4g rel_err=%.4f%%",
			     sx, sy, cx, cy, ex, ey, r1, r2, d,
			     rel * 100);
	}
	int rot = code == 30 ? turns : -turns;
	if (comp != 400 || comp_pending) {
		CompMove mv;
		mv.is_arc = true;
		mv.end = end;
		mv.cx = cx;
		mv.cy = cy;
		mv.rotation = rot;
		mv.line = b.line;
		comp_move(mv);
		return;
	}
	comp_exit_next = false;
	arc_out(cur, end, cx, cy, rot);
}

void Interp::Impl::do_probe(const Block& b, int code, const Pos& end)
{
	if (comp != 400)
		fail("Cannot probe with cutter radius comp on");
	if (feed_mode == FeedMode::INVERSE_TIME)
		fail("Cannot probe in inverse time feed mode");
	check_feed(b, "probe");
	Pos cur = program_pos();
	double d2 = 0;
	for (int a = 0; a < NUM_AXES; a++)
		d2 += (end[a] - cur[a]) * (end[a] - cur[a]);
	double tiny = units == Units::INCH ? 0.01 : 0.254;
	if (std::sqrt(d2) < tiny)
		fail("Start point too close to probe point");
	ProbeType t = code == 382 ? ProbeType::G38_2 : code == 383 ? ProbeType::G38_3
	            : code == 384 ? ProbeType::G38_4 : ProbeType::G38_5;
	canon.straight_probe(to_machine(end), t);
	ProbeResult r = canon.probe_result();
	for (int a = 0; a < NUM_AXES; a++)
		if (!axis_on[a])
			r.position[a] = 0;
	mpos = r.position;
	Pos p = to_program(r.position);
	for (int a = 0; a < NUM_AXES; a++)
		params[5061 + a] = p[a];
	params[5070] = r.tripped ? 1 : 0;
	if (probe_file && r.tripped) {
		for (int a = 0; a < NUM_AXES; a++)
			std::fprintf(probe_file, "%s%f", a ? " " : "", p[a]);
		std::fprintf(probe_file, "\n");
		std::fflush(probe_file);
	}
}

void Interp::Impl::do_g33(const Block& b, int code, const Pos& end)
{
	if (!b.w('k'))
		fail("K word missing with g33/g33.1");
	if (b.w('f'))
		fail("F word used with a g33/g33.1");
	if (comp != 400)
		fail("Cannot use G33 or G33.1 with cutter radius compensation on");
	if (spindle_dir == 0)
		fail("Spindle not turning in g33/g33.1");
	if (code == 331 && spindle_dir != 1)
		fail("Spindle must turn clockwise for g33.1 (rigid tapping)");
	double k = b.v('k') * unit_factor(AX_Z);
	canon.start_speed_feed_synch(0, k, false);
	if (code == 330) {
		feed_to(end);
	} else {
		double scale = b.w('i') ? b.v('i') : 1;
		canon.rigid_tap(to_machine(end), scale);   // returns to the start point
	}
	canon.stop_speed_feed_synch();
}

}  // namespace rs274
