// SPDX-License-Identifier: GPL-2.0-or-later
// comp.cpp - cutter radius compensation G40/G41/G42/G41.1/G42.1 (gcode.md 11.3) in
// the XY and XZ planes, with one move of look-ahead: each programmed move waits
// until the next one is known, then ends at its offset end point (straight-on
// corner), at the intersection of the two offset paths (inside corner), or at its
// offset end followed by an arc of the tool radius around the corner (outside corner).
//   entry (first move after G41/G42): a straight line from the uncompensated point to
//       the offset start of the following move; must be longer than the radius.
//   exit (first move after G40): the pending move ends at its offset end point, then
//       a straight line to the programmed (uncompensated) end.
//   a move with no motion in the plane ends the pending move at its own offset end
//       point; the next move in the plane then joins from there (arc outside, line inside).
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

constexpr double EPS = 1e-9;

// Tangent of a move at its start (at_end false) or end. start/end: plane points.
V tangent(bool is_arc, V start, V end, V center, int rotation, bool at_end)
{
	if (!is_arc)
		return unit(end - start);
	V q = at_end ? end : start;
	V t = rot90(unit(q - center));
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
		radius = b.v('d') / 2;
		comp_orientation = b.w('l') ? (int)b.v('l') : 0;
		if (comp_orientation > 9)
			fail("Invalid tool orientation L%d with G41.1/G42.1 (0-9)", comp_orientation);
	} else {
		int n = current_tool;
		if (b.w('d')) {
			double d = b.v('d');
			if (!(std::fabs(d - std::nearbyint(d)) <= 0.0001 && d < 1e9))
				fail("Non integer value for integer");
			n = (int)std::nearbyint(d);
		}
		const Tool* t = tool(n);
		if (!t && b.w('d') && n != 0)
			fail("Tool %d not found in the tool table", n);
		radius = t ? t->diameter / 2 / unit_factor(AX_X) : 0;
	}
	comp = code;
	comp_radius = std::fabs(radius);
	comp_exit_next = false;
}

void Interp::Impl::comp_stop_cmd()
{
	if (comp == 400)
		return;
	comp = 400;
	comp_exit_next = comp_pending || comp_corner;
}

void Interp::Impl::comp_line_to(const Pos& prog, bool feed_move)
{
	if (feed_move)
		feed_to(prog);
	else
		traverse(prog);
}

// Emits the pending move `mv` ending at plane point (ex, ey).
void Interp::Impl::comp_emit(const CompMove& mv, double ex, double ey)
{
	int a1, a2, a3;
	plane_axes(a1, a2, a3);
	Pos e = mv.end;
	e[a1] = ex;
	e[a2] = ey;
	bool other_feed = mv.feed && mv.feedrate != feed;
	if (other_feed)
		canon.set_feed_rate(feed_mode == FeedMode::INVERSE_TIME ? mv.feedrate : mv.feedrate * unit_factor(AX_X));
	if (mv.is_arc)
		arc_out(mv.end, e, mv.cx, mv.cy, mv.rotation);
	else
		comp_line_to(e, mv.feed);
	if (other_feed)
		send_feed();
}

void Interp::Impl::comp_flush()
{
	if (!comp_pending)
		return;
	int a1, a2, a3;
	plane_axes(a1, a2, a3);
	CompMove mv = comp_prev;
	comp_pending = false;
	double side = comp_prev_side_;
	V B{mv.end[a1], mv.end[a2]};
	V S{comp_start[a1], comp_start[a2]};
	V t1 = tangent(mv.is_arc, S, B, V{mv.cx, mv.cy}, mv.rotation, true);
	V P1 = B + comp_prev_radius_ * side * 1.0 * rot90(t1);
	comp_emit(mv, P1.x, P1.y);
	comp_corner = true;
	comp_corner_prog = mv.end;
	comp_corner_t[0] = t1.x;
	comp_corner_t[1] = t1.y;
	comp_first = false;
}

void Interp::Impl::comp_move(const CompMove& mv0)
{
	CompMove mv = mv0;
	mv.feedrate = feed;
	int a1, a2, a3;
	plane_axes(a1, a2, a3);
	Pos start = program_pos();
	V S{start[a1], start[a2]}, E{mv.end[a1], mv.end[a2]}, C{mv.cx, mv.cy};
	double plane_len = len(E - S);

	if (comp_exit_next) {
		if (mv.is_arc)
			fail("The move just after exiting cutter compensation mode must be straight, not an arc");
		comp_flush();
		Pos here = to_program(mpos);
		V H{here[a1], here[a2]};
		if (comp_prev_radius_ > 0 && len(E - H) <= comp_prev_radius_)
			fail("Length of cutter compensation exit move is not greater than the tool radius");
		comp_line_to(mv.end, mv.feed);
		comp_exit_next = comp_pending = comp_corner = false;
		return;
	}
	double side = comp == 410 || comp == 411 ? 1 : -1;
	double r = comp_radius;
	if (!mv.is_arc && plane_len < EPS) {
		// no motion in the plane (a Z move in G17)
		if (!comp_pending && !comp_corner) {
			comp_line_to(mv.end, mv.feed);
			return;
		}
		comp_flush();
		Pos p = to_program(mpos);
		for (int a = 0; a < NUM_AXES; a++)
			if (a != a1 && a != a2)
				p[a] = mv.end[a];
		comp_line_to(p, mv.feed);
		comp_corner_prog = mv.end;
		return;
	}
	if (mv.is_arc) {
		double R = len(S - C);
		double s = mv.rotation > 0 ? 1 : -1;
		if (R - side * s * r <= EPS)
			fail("Tool radius not less than arc radius with comp");
	}
	if (!comp_pending && !comp_corner) {
		// entry move: wait for the next move to know where the offset path starts
		if (mv.is_arc)
			fail("Cutter compensation entry move must be a straight line (G0 or G1)");
		if (plane_len <= r)
			fail("Length of cutter compensation entry move is not greater than the tool radius");
		comp_prev = mv;
		comp_start = start;
		comp_first = true;
		comp_pending = true;
		comp_prev_side_ = side;
		comp_prev_radius_ = r;
		return;
	}
	V t2 = tangent(mv.is_arc, S, E, C, mv.rotation, false);
	V n2 = side * 1.0 * rot90(t2);
	V B = S;
	V P2 = B + r * n2;
	if (comp_corner) {
		V t1{comp_corner_t[0], comp_corner_t[1]};
		double cr = cross(t1, t2);
		if (r > 0 && side * cr < -EPS)
			arc_out(comp_corner_prog, [&] { Pos p = to_program(mpos); p[a1] = P2.x; p[a2] = P2.y; return p; }(),
			        B.x, B.y, cr < 0 ? -1 : 1);
		else if (r > 0)
			comp_line_to([&] { Pos p = to_program(mpos); p[a1] = P2.x; p[a2] = P2.y; return p; }(), mv.feed);
		comp_corner = false;
	} else {
		const CompMove& pv = comp_prev;
		V PS{comp_start[a1], comp_start[a2]}, PC{pv.cx, pv.cy};
		V t1 = tangent(pv.is_arc, PS, B, PC, pv.rotation, true);
		V P1 = B + r * side * 1.0 * rot90(t1);
		double cr = cross(t1, t2), dt = dot(t1, t2);
		if (comp_first) {
			comp_emit(pv, P2.x, P2.y);
			comp_first = false;
		} else if (r == 0 || (std::fabs(cr) < EPS && dt > 0)) {
			comp_emit(pv, P1.x, P1.y);
		} else if (side * cr < 0 || std::fabs(cr) < EPS) {
			// outside corner: around the corner point on an arc of the tool radius
			comp_emit(pv, P1.x, P1.y);
			int rot = cr < -EPS ? -1 : cr > EPS ? 1 : (side > 0 ? -1 : 1);
			Pos e = pv.end;
			e[a1] = P2.x;
			e[a2] = P2.y;
			arc_out(pv.end, e, B.x, B.y, rot);
		} else {
			// inside corner: both offset paths end/start at their intersection
			V X{}, i1, i2;
			bool ok;
			double s2 = mv.rotation > 0 ? 1 : -1, s1 = pv.rotation > 0 ? 1 : -1;
			if (!pv.is_arc && !mv.is_arc) {
				X = P1 + (cross(P2 - P1, t2) / cr) * t1;
				ok = dot(X - P2, t2) <= len(E - S) + EPS;
				if (!ok)
					fail("Inside corner too tight: the compensated tool would gouge the next move");
			} else if (!pv.is_arc) {
				ok = line_circle(P1, t1, C, len(S - C) - side * s2 * r, i1, i2);
				if (!ok)
					fail("Straight to arc motion makes a corner the compensated tool can't fit in without gouging");
				X = nearest(i1, i2, B);
			} else if (!mv.is_arc) {
				ok = line_circle(P2, t2, PC, len(B - PC) - side * s1 * r, i1, i2);
				if (!ok)
					fail("Arc to straight motion makes a corner the compensated tool can't fit in without gouging");
				X = nearest(i1, i2, B);
			} else {
				ok = circle_circle(PC, len(B - PC) - side * s1 * r, C, len(S - C) - side * s2 * r, i1, i2);
				if (!ok)
					fail("Arc move in concave corner cannot be reached by the tool without gouging");
				X = nearest(i1, i2, B);
			}
			if (len(X - B) > 10 * r + EPS)
				fail("Zero degree inside corner is invalid for cutter compensation");
			comp_emit(pv, X.x, X.y);
		}
	}
	comp_prev = mv;
	comp_start = start;
	comp_pending = true;
	comp_prev_side_ = side;
	comp_prev_radius_ = r;
}

}  // namespace rs274
