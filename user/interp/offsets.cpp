// SPDX-License-Identifier: GPL-2.0-or-later
// offsets.cpp - program <-> machine transform (gcode.md 7.1), coordinate system
// selection, G10 L1/L2/L10/L11/L20/L0, G52/G92 family, G28/G30 and tool length offset.
// Stored offsets (#5211.., #5221.., #5161..) and the active G92/TLO are machine units.
#include <cmath>

#include "impl.hpp"

namespace rs274 {

static const char axis_letters[] = "xyzabcuvw";

double Interp::Impl::unit_factor(int axis) const
{
	if (axis >= AX_A && axis <= AX_C)
		return 1;
	if (units == cfg.machine_units)
		return 1;
	return units == Units::INCH ? 25.4 : 1 / 25.4;
}

Pos Interp::Impl::g5x(int index) const
{
	Pos p{};
	for (int a = 0; a < NUM_AXES; a++)
		p[a] = params[5201 + 20 * index + a];
	return p;
}

double Interp::Impl::rotation(int index) const { return params[5201 + 20 * index + 9]; }

Pos Interp::Impl::to_machine(const Pos& prog) const
{
	Pos q{}, m{};
	for (int a = 0; a < NUM_AXES; a++)
		q[a] = prog[a] * unit_factor(a) + g92[a];
	double r = rotation(coord);
	if (r != 0) {
		double c = std::cos(r * M_PI / 180), s = std::sin(r * M_PI / 180);
		double x = q[AX_X] * c - q[AX_Y] * s, y = q[AX_X] * s + q[AX_Y] * c;
		q[AX_X] = x;
		q[AX_Y] = y;
	}
	Pos off = g5x(coord);
	for (int a = 0; a < NUM_AXES; a++)
		m[a] = axis_on[a] ? q[a] + off[a] + tlo[a] : 0;
	return m;
}

Pos Interp::Impl::to_program(const Pos& m) const
{
	Pos q{}, p{};
	Pos off = g5x(coord);
	for (int a = 0; a < NUM_AXES; a++)
		q[a] = m[a] - off[a] - tlo[a];
	double r = rotation(coord);
	if (r != 0) {
		double c = std::cos(r * M_PI / 180), s = std::sin(r * M_PI / 180);
		double x = q[AX_X] * c + q[AX_Y] * s, y = -q[AX_X] * s + q[AX_Y] * c;
		q[AX_X] = x;
		q[AX_Y] = y;
	}
	for (int a = 0; a < NUM_AXES; a++)
		p[a] = axis_on[a] ? (q[a] - g92[a]) / unit_factor(a) : 0;
	return p;
}

void Interp::Impl::select_coord(int index)
{
	if (comp != 400 && index != coord)
		fail("Cannot change coordinate systems with cutter radius compensation on");
	coord = index;
	params[5220] = index;
	canon.set_g5x_offset(index, g5x(index));
	canon.set_xy_rotation(rotation(index));
}

void Interp::Impl::report_offsets()
{
	canon.set_g5x_offset(coord, g5x(coord));
	canon.set_xy_rotation(rotation(coord));
	canon.set_g92_offset(g92);
}

static int g10_p(const Block& b, int l)
{
	if (!b.w('p'))
		fail("P word missing with G10 L%d", l);
	double p = b.v('p');
	if (!(std::fabs(p - std::nearbyint(p)) <= 0.0001 && std::fabs(p) < 1e6))
		fail("P value not an integer with G10");
	return (int)std::nearbyint(p);
}

void Interp::Impl::do_g10(const Block& b)
{
	int l = b.w('l') ? (int)b.v('l') : -1;
	if (l != 0 && l != 1 && l != 2 && l != 10 && l != 11 && l != 20)
		fail("Line with G10 does not have L0, L1, L10, L11, L2, or L20");
	if (l == 0) {
		load_tool_table();
		canon.reload_tool_table();
		return;
	}
	int p = g10_p(b, l);
	if (l == 2 || l == 20) {
		if (p < 0 || p > 9)
			fail("P value out of range (0-9) with G10 L%d", l);
		if (b.w('i') || b.w('j'))
			fail("I J words not allowed with G10 L%d", l);
		if (l == 20 && b.w('r'))
			fail("R not allowed in G10 L20");
		int sys = p == 0 ? coord : p;
		if (comp != 400 && sys == coord)
			fail("Cannot change axis offsets with cutter radius comp");
		int base = 5201 + 20 * sys;
		if (l == 2) {
			for (int a = 0; a < NUM_AXES; a++)
				if (b.w(axis_letters[a]))
					params[base + a] = b.v(axis_letters[a]) * unit_factor(a);
			if (b.w('r'))
				params[base + 9] = b.v('r');
		} else {
			// make the current point read the given values in system `sys`
			Pos w{}, off = g5x(sys);
			for (int a = 0; a < NUM_AXES; a++)
				w[a] = mpos[a] - tlo[a];
			double r = rotation(sys) * M_PI / 180, c = std::cos(r), s = std::sin(r);
			Pos v{};   // current reading in sys, machine units (before G92 removal)
			for (int a = 0; a < NUM_AXES; a++)
				v[a] = w[a] - off[a];
			double vx = v[AX_X] * c + v[AX_Y] * s, vy = -v[AX_X] * s + v[AX_Y] * c;
			v[AX_X] = vx;
			v[AX_Y] = vy;
			Pos d = v;   // desired q-space point
			for (int a = 0; a < NUM_AXES; a++)
				if (b.w(axis_letters[a]))
					d[a] = b.v(axis_letters[a]) * unit_factor(a) + g92[a];
			double dx = d[AX_X] * c - d[AX_Y] * s, dy = d[AX_X] * s + d[AX_Y] * c;
			d[AX_X] = dx;
			d[AX_Y] = dy;
			for (int a = 0; a < NUM_AXES; a++)
				if (b.w(axis_letters[a]))
					params[base + a] = w[a] - d[a];
		}
		if (sys == coord) {
			canon.set_g5x_offset(sys, g5x(sys));
			canon.set_xy_rotation(rotation(sys));
		}
		return;
	}
	// L1, L10, L11: tool table entries
	if (comp != 400)
		fail("Cannot change the tool table with cutter radius compensation on");
	if (p < 1)
		fail("P value out of range with G10 L%d", l);
	auto it = tools.find(p);
	if (it == tools.end())
		fail("Tool %d not found in the tool table (G10 L%d)", p, l);
	Tool& t = it->second;
	if (l == 1) {
		for (int a = 0; a < NUM_AXES; a++)
			if (b.w(axis_letters[a]))
				t.offset[a] = b.v(axis_letters[a]) * unit_factor(a);
	} else {
		int sys = l == 10 ? coord : 9;
		Pos off = g5x(sys);
		Pos cur = program_pos();
		Pos q{};
		for (int a = 0; a < NUM_AXES; a++) {
			double v = b.w(axis_letters[a]) ? b.v(axis_letters[a]) : cur[a];
			q[a] = v * unit_factor(a) + (l == 10 ? g92[a] : 0);
		}
		double r = rotation(sys) * M_PI / 180, c = std::cos(r), s = std::sin(r);
		double qx = q[AX_X] * c - q[AX_Y] * s, qy = q[AX_X] * s + q[AX_Y] * c;
		q[AX_X] = qx;
		q[AX_Y] = qy;
		for (int a = 0; a < NUM_AXES; a++)
			if (b.w(axis_letters[a]))
				t.offset[a] = mpos[a] - q[a] - off[a];
	}
	if (b.w('r'))
		t.diameter = 2 * b.v('r') * unit_factor(AX_X);
	if (b.w('i'))
		t.frontangle = b.v('i');
	if (b.w('j'))
		t.backangle = b.v('j');
	if (b.w('q'))
		t.orientation = (int)std::lround(b.v('q'));
	canon.set_tool_table_entry(p, t.pocket, t.offset, t.diameter, t.frontangle, t.backangle,
	                           t.orientation);
}

void Interp::Impl::do_g92(const Block& b, int code)
{
	if (comp != 400)
		fail("Cannot change axis offsets with cutter radius comp");
	if (code == 920 || code == 520) {
		Pos cur = program_pos();
		for (int a = 0; a < NUM_AXES; a++) {
			if (!b.w(axis_letters[a]))
				continue;
			double v = b.v(axis_letters[a]) * unit_factor(a);
			if (code == 920)
				g92[a] = cur[a] * unit_factor(a) + g92[a] - v;
			else
				g92[a] = v;
		}
		params[5210] = 1;
		for (int a = 0; a < NUM_AXES; a++)
			params[5211 + a] = g92[a];
	} else if (code == 921) {
		g92 = Pos{};
		for (int i = 5210; i <= 5219; i++)
			params[i] = 0;
	} else if (code == 922) {
		g92 = Pos{};
		params[5210] = 0;
	} else {   // 923
		for (int a = 0; a < NUM_AXES; a++)
			g92[a] = axis_on[a] ? params[5211 + a] : 0;
		params[5210] = 1;
	}
	canon.set_g92_offset(g92);
}

void Interp::Impl::do_g28(const Block& b, int code)
{
	int base = code == 280 || code == 281 ? 5161 : 5181;
	if (code == 281 || code == 301) {
		for (int a = 0; a < NUM_AXES; a++)
			params[base + a] = mpos[a];
		return;
	}
	if (comp != 400)
		fail("Cannot use g28 or g30 with cutter radius comp");
	Pos cur = program_pos();
	traverse(end_point(b, cur));
	bool any = b.any_axis();
	Pos m = mpos;
	for (int a = 0; a < NUM_AXES; a++)
		if (axis_on[a] && (!any || b.w(axis_letters[a])))
			m[a] = params[base + a];
	canon.straight_traverse(m);
	mpos = m;
}

void Interp::Impl::do_tool_length(const Block& b, int code)
{
	if (comp != 400)
		fail("Cannot change tool offset with cutter radius compensation on");
	auto tool_offset = [&](int n) {
		const Tool* t = tool(n);
		if (!t) {
			if (n == 0)
				return Pos{};
			fail("Tool %d not found in the tool table", n);
		}
		return t->offset;
	};
	auto h_word = [&]() {
		double h = b.v('h');
		if (!(std::fabs(h - std::nearbyint(h)) <= 0.0001 && h < 1e9))
			fail("Non integer value for integer");
		return (int)std::nearbyint(h);
	};
	switch (code) {
	case 430: {
		int n = current_tool;
		if (b.w('h') && h_word() != 0)
			n = h_word();
		tlo = tool_offset(n);
		break;
	}
	case 431:
		if (b.w('h'))
			fail("H word with no G43 or G76 to use it");
		tlo = Pos{};
		for (int a = 0; a < NUM_AXES; a++)
			if (b.w(axis_letters[a]))
				tlo[a] = b.v(axis_letters[a]) * unit_factor(a);
		break;
	case 432: {
		bool axes = b.any_axis();
		if (b.w('h') && axes)
			fail("Cannot use both H word and axis words with G43.2");
		if (!b.w('h') && !axes)
			fail("G43.2 needs an H word or axis words");
		if (b.w('h')) {
			Pos o = tool_offset(h_word() == 0 ? current_tool : h_word());
			for (int a = 0; a < NUM_AXES; a++)
				tlo[a] += o[a];
		} else {
			for (int a = 0; a < NUM_AXES; a++)
				if (b.w(axis_letters[a]))
					tlo[a] += b.v(axis_letters[a]) * unit_factor(a);
		}
		break;
	}
	default:
		tlo = Pos{};
		break;
	}
	for (int a = 0; a < NUM_AXES; a++)
		if (!axis_on[a])
			tlo[a] = 0;
	tlo_mode = code;
	canon.use_tool_length_offset(tlo);
}

}  // namespace rs274
