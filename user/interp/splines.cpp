// SPDX-License-Identifier: GPL-2.0-or-later
// splines.cpp - G5 cubic and G5.1 quadratic splines, G5.2/G5.3 NURBS blocks (gcode.md
// 8), XY plane only. Canon has no spline call: each curve is converted here into
// STRAIGHT_FEED segments whose distance from the true curve is at most the path
// tolerance: the G64 P value when one is set, otherwise 0.001 in / 0.0254 mm (canon's
// default blending tolerance), in program units.
//   G5 / G5.1: Bezier curves (start, start + IJ, [end + PQ,] end); a uniform split in n
//     parts has a chord error of at most max|B''| / (8 n^2), so n follows from the
//     tolerance.
//   NURBS: clamped uniform knots, the current point is the first control point; each
//     knot span is split in halves until every chord lies within the tolerance of the
//     curve at its quarter points.
#include <cmath>

#include "impl.hpp"

namespace rs274 {

namespace {

constexpr long MAX_SPLINE_SEGMENTS = 10000;     // per G5/G5.1 curve and per NURBS span
constexpr size_t MAX_NURBS_POINTS = 10000;      // control points of one G5.2 block
constexpr long MAX_NURBS_EVALS = 2000000;        // curve evaluations converting one block

struct P2 {
	double x, y;
};
P2 lerp(P2 a, P2 b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }

// Distance from point p to the segment a-b.
double seg_dist(P2 p, P2 a, P2 b)
{
	double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
	double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

}  // namespace

double Interp::Impl::spline_tolerance() const
{
	if (mc == MotionControl::CONTINUOUS && p_tol > 0)
		return p_tol;
	return units == Units::INCH ? 0.001 : 0.0254;
}

void Interp::Impl::spline_checks(const Block& b, const char* what)
{
	if (plane != Plane::XY)
		fail("%s is only allowed in the XY plane (G17)", what);
	if (comp != 400)
		fail("Cannot convert spline with cutter radius compensation");
	for (char l : {'z', 'a', 'b', 'c', 'u', 'v', 'w'})
		if (b.w(l))
			fail("%s allows only X and Y axis words", what);
	if (feed_mode == FeedMode::INVERSE_TIME)
		fail("%s is not allowed in inverse time feed mode (G93)", what);
	if (feed == 0)
		fail("Cannot make a spline with zero feed rate");
}

void Interp::Impl::do_spline(const Block& b, int code, const Pos& end)
{
	const char* what = code == 50 ? "G5" : "G5.1";
	spline_checks(b, what);
	Pos start = program_pos();
	P2 s{start[AX_X], start[AX_Y]}, e{end[AX_X], end[AX_Y]};
	std::vector<P2> cp;
	if (code == 50) {
		if (b.w('i') != b.w('j'))
			fail("G5 requires both I and J, or neither right after a G5");
		if (!b.w('p') || !b.w('q'))
			fail("G5 requires both P and Q");
		P2 c1;
		if (b.w('i')) {
			c1 = {s.x + b.v('i'), s.y + b.v('j')};
		} else {
			if (!g5_continues)
				fail("G5 requires both I and J, or neither right after a G5");
			c1 = {s.x - g5_last_pq[0], s.y - g5_last_pq[1]};   // tangent to the last G5
		}
		cp = {s, c1, {e.x + b.v('p'), e.y + b.v('q')}, e};
	} else {
		double i = b.w('i') ? b.v('i') : 0, j = b.w('j') ? b.v('j') : 0;
		if (i == 0 && j == 0)
			fail("G5.1 requires an I or J that is not zero");
		cp = {s, {s.x + i, s.y + j}, e};
	}
	// max |B''|: 6 (cubic) or 2 (quadratic) times the largest second difference
	double m = 0;
	for (size_t k = 0; k + 2 < cp.size(); k++)
		m = std::max(m, std::hypot(cp[k].x - 2 * cp[k + 1].x + cp[k + 2].x, cp[k].y - 2 * cp[k + 1].y + cp[k + 2].y));
	m *= cp.size() == 4 ? 6 : 2;
	double n_real = std::ceil(std::sqrt(m / (8 * spline_tolerance())));
	long n = !(n_real >= 1) ? 1 : n_real > MAX_SPLINE_SEGMENTS ? MAX_SPLINE_SEGMENTS : (long)n_real;
	for (long k = 1; k <= n; k++) {
		double t = (double)k / n;
		std::vector<P2> q = cp;   // de Casteljau
		for (size_t lvl = q.size() - 1; lvl > 0; lvl--)
			for (size_t i = 0; i < lvl; i++)
				q[i] = lerp(q[i], q[i + 1], t);
		Pos p = end;
		if (k < n) {
			p[AX_X] = q[0].x;
			p[AX_Y] = q[0].y;
		}
		feed_to(p);
	}
	g5_continues = code == 50;
	if (code == 50) {
		g5_last_pq[0] = b.v('p');
		g5_last_pq[1] = b.v('q');
	}
}

// G5.2 (opens a block, its X Y are a control point) and the X Y [P] lines after it.
void Interp::Impl::nurbs_point(const Block& b, const Pos& end)
{
	if (b.gmode[1] == 52) {
		if (nurbs_open)
			fail("G5.2 inside an open G5.2 block (end it with G5.3)");
		spline_checks(b, "G5.2");
		int order = 3;
		if (b.w('l')) {
			double l = b.v('l');
			if (l < 2 || l > 10 || std::fabs(l - std::nearbyint(l)) > 0.0001)
				fail("NURBS order L must be an integer from 2 to 10");
			order = (int)std::nearbyint(l);
		}
		Pos s = program_pos();
		nurbs_open = true;
		nurbs_order = order;
		nurbs_cp.clear();
		nurbs_cp.push_back({s[AX_X], s[AX_Y], 1});
		nurbs_pos = s;
		if (!b.w('x') && !b.w('y'))
			return;
	} else {
		spline_checks(b, "G5.2");
	}
	double w = b.w('p') ? b.v('p') : 1;
	if (!(w > 0))
		fail("NURBS weight P must be greater than zero");
	if (nurbs_cp.size() >= MAX_NURBS_POINTS)
		fail("Too many NURBS control points (more than %zu)", MAX_NURBS_POINTS);
	nurbs_cp.push_back({end[AX_X], end[AX_Y], w});
	nurbs_pos = end;
}

// A point of the NURBS curve at parameter u (de Boor on weighted points).
static P2 nurbs_eval(const std::vector<std::array<double, 3>>& cp, const std::vector<double>& knots, int order,
                     double u)
{
	int p = order - 1, n = (int)cp.size();
	int span = p;
	while (span < n - 1 && u >= knots[span + 1])
		span++;
	std::array<double, 3> d[10];
	for (int j = 0; j <= p; j++) {
		const auto& c = cp[span - p + j];
		d[j] = {c[0] * c[2], c[1] * c[2], c[2]};
	}
	for (int r = 1; r <= p; r++)
		for (int j = p; j >= r; j--) {
			int i = span - p + j;
			double den = knots[i + p - r + 1] - knots[i];
			double a = den > 0 ? (u - knots[i]) / den : 0;
			for (int k = 0; k < 3; k++)
				d[j][k] = (1 - a) * d[j - 1][k] + a * d[j][k];
		}
	return {d[p][0] / d[p][2], d[p][1] / d[p][2]};
}

// G5.3: the curve through the collected control points, as lines.
void Interp::Impl::nurbs_end()
{
	if (!nurbs_open)
		fail("G5.3 without an open G5.2 block");
	nurbs_open = false;
	motion = 800;
	const auto& cp = nurbs_cp;
	int k = nurbs_order, n = (int)cp.size();
	if (n < k)
		fail("NURBS with order %d needs at least %d control points (it has %d)", k, k, n);
	// clamped uniform knot vector: k zeros, n - k interior values, k ones
	std::vector<double> knots;
	for (int i = 0; i < k; i++)
		knots.push_back(0);
	for (int i = 1; i <= n - k; i++)
		knots.push_back((double)i / (n - k + 1));
	for (int i = 0; i < k; i++)
		knots.push_back(1);
	double tol = spline_tolerance();
	Pos p = nurbs_pos;
	long evals = 0;
	auto at = [&](double u) {
		if (++evals > MAX_NURBS_EVALS)
			fail("NURBS curve too complex to convert within the tolerance");
		return nurbs_eval(cp, knots, k, u);
	};
	for (int s = k - 1; s < n; s++) {
		double u0 = knots[s], u1 = knots[s + 1];
		if (u1 <= u0)
			continue;
		long segs = 1;
		for (; segs < MAX_SPLINE_SEGMENTS; segs *= 2) {
			bool ok = true;
			for (long i = 0; i < segs && ok; i++) {
				double a = u0 + (u1 - u0) * i / segs, b = u0 + (u1 - u0) * (i + 1) / segs;
				P2 pa = at(a), pb = at(b);
				for (double f : {0.25, 0.5, 0.75})
					ok = ok && seg_dist(at(a + (b - a) * f), pa, pb) <= tol;
			}
			if (ok)
				break;
		}
		for (long i = 1; i <= segs; i++) {
			double u = u0 + (u1 - u0) * i / segs;
			P2 q = s == n - 1 && i == segs ? P2{cp.back()[0], cp.back()[1]} : at(u);
			p[AX_X] = q.x;
			p[AX_Y] = q.y;
			feed_to(p);
		}
	}
	nurbs_cp.clear();
}

}  // namespace rs274
