// SPDX-License-Identifier: GPL-2.0-or-later
// comp.cpp - cutter radius compensation G40/G41/G42/G41.1/G42.1 (gcode.md 11.3) in
// the XY and XZ planes, with one move of look-ahead. Each move in the plane is held
// back (HoldCanon queues everything after it) until the next move in the plane is
// known; then the corner between the two is resolved:
//   outside corner: the held move ends at its nominal offset end (programmed end +
//       radius along its normal), then an arc of the tool radius around the programmed
//       corner point takes the tool to the next move's offset start;
//   inside corner: the held move ends where the two offset paths intersect (line/line,
//       line/arc, arc/line, arc/arc), the next move starts there;
//   straight-on (tangent) corner: the held move ends at its offset end.
// Moves with no motion in the plane (Z plunges in G17) are queued behind the held move
// and run at its final end point, so a plunge does not change how a corner is cut.
// Entry (first move in the plane after G41/G42): a line runs from the uncompensated
// point to the point where the tool touches the programmed end point with the tool
// beside its own path (the tangent from the start to the circle of the tool radius
// around the end); an arc ends at its programmed end moved by the radius along the
// normal, with the programmed centre (canon makes the spiral). Exit (first move in
// the plane after G40): the held move ends at its offset end, then a straight line
// runs to the programmed end point.
#include <cmath>

#include "impl.hpp"

namespace rs274 {

namespace {

struct V {
	double x, y;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y}; }
V operator*(double k, V a) { return {k * a.x, k * a.y}; }
double cross(V a, V b) { return a.x * b.y - a.y * b.x; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y; }
double len(V a) { return std::hypot(a.x, a.y); }
V unit(V a)
{
	double l = len(a);
	return l > 0 ? V{a.x / l, a.y / l} : V{0, 0};
}
V rot90(V a) { return {-a.y, a.x}; }
V rotate(V a, double ang) { return {a.x * std::cos(ang) - a.y * std::sin(ang), a.x * std::sin(ang) + a.y * std::cos(ang)}; }
V v2(const double* p) { return {p[0], p[1]}; }
void put2(double* p, V v) { p[0] = v.x; p[1] = v.y; }

constexpr double EPS = 1e-9;
// A corner turning less than this towards the tool's side counts as straight-on
// (LinuxCNC's TOLERANCE_CONCAVE_CORNER, radians).
constexpr double CONCAVE_SMALL = 0.05;

// Tangent of a move at a point on it.
V tangent(bool is_arc, V start, V end, V center, int rotation, V at)
{
	if (!is_arc)
		return unit(end - start);
	V t = rot90(unit(at - center));
	return rotation > 0 ? t : -1 * t;
}

// Intersections of the line p + s*d with the circle (c, r); false if none.
bool line_circle(V p, V d, V c, double r, V& a, V& b)
{
	V f = p - c;
	double A = dot(d, d), B = 2 * dot(f, d), C = dot(f, f) - r * r;
	double disc = B * B - 4 * A * C;
	if (disc < 0 || A < EPS)
		return false;
	double sq = std::sqrt(disc);
	a = p + ((-B - sq) / (2 * A)) * d;
	b = p + ((-B + sq) / (2 * A)) * d;
	return true;
}

bool circle_circle(V c1, double r1, V c2, double r2, V& a, V& b)
{
	double d = len(c2 - c1);
	if (d < EPS || d > r1 + r2 || d < std::fabs(r1 - r2))
		return false;
	double x = (d * d + r1 * r1 - r2 * r2) / (2 * d);
	double h = std::sqrt(std::max(0.0, r1 * r1 - x * x));
	V u = unit(c2 - c1);
	V m = c1 + x * u;
	a = m + h * rot90(u);
	b = m - h * rot90(u);
	return true;
}

V nearest(V a, V b, V to) { return len(a - to) <= len(b - to) ? a : b; }

}  // namespace

void Interp::Impl::comp_start_cmd(const Block& b, int code)
{
	if (comp != 400)
		fail("Cannot turn cutter radius comp on when on");
	if (plane != Plane::XY && plane != Plane::XZ)
		fail("Cutter radius compensation allowed only in XY, XZ planes");
	double radius = 0;
	if (code == 411 || code == 421) {
		if (!b.w('d'))
			fail("D word missing with G41.1 or G42.1");
		if (b.v('d') < 0)
			fail("Negative D word tool radius index used with G41.1 or G42.1");
		radius = b.v('d') / 2;
		comp_orientation = b.w('l') ? (int)b.v('l') : 0;
		if (comp_orientation > 9)
			fail("Invalid tool orientation L%d with G41.1/G42.1 (0-9)", comp_orientation);
		if (b.w('l') && plane != Plane::XZ)
			fail("Tool orientation (L word) with G41.1/G42.1 is for the XZ plane (G18) only");
	} else {
		int n = current_tool;
		if (b.w('d')) {
			double d = b.v('d');
			if (d < 0)
				fail("Negative D word tool radius index used with G41 or G42");
			if (!(std::fabs(d - std::nearbyint(d)) <= 0.0001 && d < 1e9))
				fail("Non integer value for integer");
			n = (int)std::nearbyint(d);
		}
		const Tool* t = tool(n);
		if (!t && b.w('d') && n != 0)
			fail("Tool %d not found in the tool table", n);
		radius = t ? t->diameter / 2 / unit_factor(AX_X) : 0;
	}
	if (comp_exit_next)       // G40 then G41/G42 before any move: finish the old path
		comp_flush();
	comp_exit_next = false;
	comp = code;
	comp_radius = std::fabs(radius);
}

void Interp::Impl::comp_stop_cmd()
{
	if (comp == 400)
		return;
	comp = 400;
	comp_exit_next = comp_pending;
	comp_exit_radius = comp_radius;
}

void Interp::Impl::comp_line_to(const Pos& prog, bool feed_move)
{
	if (feed_move)
		feed_to(prog);
	else
		traverse(prog);
}

// Emits the held move ending at plane point (ex, ey), then everything queued behind it
// (plane-less moves at that point). Afterwards nothing is held.
void Interp::Impl::comp_release(double ex, double ey)
{
	int a1, a2, a3;
	plane_axes(a1, a2, a3);
	comp_pending = false;
	canon.hold(false);
	std::vector<HoldCanon::Item> q = canon.take();
	const CompHeld& h = comp_held;
	canon.block_begin(h.file, h.line);
	Pos e = h.mv.end;
	e[a1] = ex;
	e[a2] = ey;
	if (h.mv.is_arc)
		arc_out(h.mv.end, e, h.mv.cx, h.mv.cy, h.mv.rotation);
	else
		comp_line_to(e, h.mv.feed);
	for (auto& it : q) {
		if (!it.move) {
			it.call(canon.machine());
			continue;
		}
		Pos p = it.prog;
		p[a1] = ex;
		p[a2] = ey;
		comp_line_to(p, it.feed);
	}
}

// Program end, '%', G40 followed by a move, G41 after G40: the held move ends at its
// nominal offset end.
void Interp::Impl::comp_flush()
{
	if (comp_pending)
		comp_release(comp_held.p1[0], comp_held.p1[1]);
}

void Interp::Impl::comp_move(const CompMove& mv)
{
	int a1, a2, a3;
	plane_axes(a1, a2, a3);
	Pos start = program_pos();
	V S{start[a1], start[a2]}, E{mv.end[a1], mv.end[a2]}, C{mv.cx, mv.cy};
	bool in_plane = mv.is_arc || len(E - S) >= EPS;

	if (!in_plane) {
		// a plunge: behind the held move, or (nothing held) where the tool is
		if (comp_pending) {
			canon.queue_move(mv.end, mv.feed);
			comp_prog = mv.end;
			return;
		}
		Pos p = mv.end;
		Pos tool = to_program(mpos);
		p[a1] = tool[a1];
		p[a2] = tool[a2];
		comp_line_to(p, mv.feed);
		return;
	}
	if (comp_exit_next) {
		if (mv.is_arc)
			fail("The move just after exiting cutter compensation mode must be straight, not an arc");
		comp_flush();
		Pos here = to_program(mpos);
		V H{here[a1], here[a2]};
		if (comp_exit_radius > 0 && len(E - H) <= comp_exit_radius)
			fail("Length of cutter compensation exit move is not greater than the tool radius");
		comp_line_to(mv.end, mv.feed);
		comp_exit_next = false;
		return;
	}
	double side = comp == 410 || comp == 411 ? 1 : -1;
	double r = comp_radius;
	double ro2 = 0;   // next arc: radius of the tool centre's path
	if (mv.is_arc) {
		double s = mv.rotation > 0 ? 1 : -1;
		ro2 = len(S - C) - side * s * r;
		if (ro2 <= EPS || len(E - C) - side * s * r <= EPS)
			fail("Tool radius not less than arc radius with comp");
	}
	V t2 = tangent(mv.is_arc, S, E, C, mv.rotation, S);
	V t_end = tangent(mv.is_arc, S, E, C, mv.rotation, E);
	V P2 = S + r * side * rot90(t2);   // the next move's nominal offset start
	CompHeld next;
	next.mv = mv;
	next.file = sources[src]->name;
	next.line = cur_line;
	next.side = side;
	next.radius = r;

	if (!comp_pending) {
		// entry move
		V T = S;   // nothing held: the tool is at the programmed point
		if (mv.is_arc) {
			if (len(E - C) <= r)
				fail("Radius of cutter compensation entry arc is not greater than the tool radius");
			V p1 = E + r * side * rot90(t_end);
			put2(next.p1, p1);
			put2(next.t1, t_end);
			next.ro = len(p1 - C);
		} else {
			double d = len(E - T);
			if (d <= r)
				fail("Length of cutter compensation entry move is not greater than the tool radius");
			// the tool path leaves S turned towards its side by asin(r/d) so that it
			// passes the programmed end point at the tool radius
			V t = rotate(unit(E - T), side * std::asin(r / d));
			put2(next.p1, T + std::sqrt(d * d - r * r) * t);
			put2(next.t1, t);
		}
		put2(next.ts, T);
		comp_held = next;
		comp_pending = true;
		comp_prog = mv.end;
		canon.hold(true);
		return;
	}

	// resolve the corner at S between the held move and this one
	const CompHeld& h = comp_held;
	V P1 = v2(h.p1), t1 = v2(h.t1), TS = v2(h.ts);
	double cr = cross(t1, t2), turn = std::atan2(cr, dot(t1, t2));
	double in_turn = side * turn;   // > 0: the corner turns towards the tool (inside)
	V end1 = P1, start2 = P2;
	bool corner_arc = false;
	int arc_rot = 0;
	if (r > 0 && std::fabs(turn) > 1e-12 && in_turn < 0) {
		corner_arc = true;
		arc_rot = std::fabs(cr) < EPS ? (side > 0 ? -1 : 1) : cr < 0 ? -1 : 1;
	} else if (r > 0 && in_turn > 1e-12) {
		const CompMove& pv = h.mv;
		V PC{pv.cx, pv.cy};
		V X{}, i1, i2;
		bool ok;
		const char* err;
		if (!pv.is_arc && !mv.is_arc) {
			X = TS + (cross(P2 - TS, t2) / cross(t1, t2)) * t1;
			ok = true;
			err = "";
		} else if (!pv.is_arc) {
			ok = line_circle(TS, t1, C, ro2, i1, i2);
			err = "Arc move in concave corner cannot be reached by the tool without gouging";
		} else if (!mv.is_arc) {
			ok = line_circle(P2, t2, PC, h.ro, i1, i2);
			err = "Arc to straight motion makes a corner the compensated tool can't fit in without gouging";
		} else {
			ok = circle_circle(PC, h.ro, C, ro2, i1, i2);
			err = "Arc move in concave corner cannot be reached by the tool without gouging";
		}
		if (ok && (pv.is_arc || mv.is_arc))
			X = nearest(i1, i2, S);
		if (!ok && in_turn >= CONCAVE_SMALL)
			fail("%s", err);
		if (ok) {
			if (len(X - S) > 10 * r + EPS)
				fail("Zero degree inside corner is invalid for cutter compensation");
			if (!pv.is_arc && dot(X - TS, t1) < -EPS)
				fail("Inside corner too tight: the compensated tool would gouge the previous move");
			if (!mv.is_arc && dot(X - P2, t2) > len(E - S) + EPS)
				fail("Inside corner too tight: the compensated tool would gouge the next move");
			end1 = start2 = X;
		}
	}
	comp_release(end1.x, end1.y);
	Pos here = to_program(mpos);
	Pos p2 = here;
	p2[a1] = start2.x;
	p2[a2] = start2.y;
	if (corner_arc)
		arc_out(here, p2, S.x, S.y, arc_rot);
	else if (len(start2 - end1) > EPS)
		comp_line_to(p2, mv.feed);   // nearly straight-on inside corner that has no intersection

	put2(next.ts, start2);
	put2(next.p1, E + r * side * rot90(t_end));
	put2(next.t1, t_end);
	if (mv.is_arc)
		next.ro = len(v2(next.p1) - C);
	comp_held = next;
	comp_pending = true;
	comp_prog = mv.end;
	canon.hold(true);
}

}  // namespace rs274
