// SPDX-License-Identifier: GPL-2.0-or-later
// G5 / G5.1 splines and G5.2/G5.3 NURBS (gcode.md 8): converted to STRAIGHT_FEED
// segments. The tests evaluate the true curve independently (Bernstein polynomials,
// Cox-de Boor basis functions), sample it densely and check that every sample lies
// within the tolerance of the emitted path and every path vertex lies on the curve.
#include <cmath>
#include <cstdio>
#include <functional>

#include "interp_test_util.hpp"

using interp_test::expect_error;
using interp_test::Prog;

namespace {

struct Pt {
	double x, y;
};

// The start point and every STRAIGHT_FEED end point in the XY plane.
std::vector<Pt> path(const Prog& r, Pt start)
{
	std::vector<Pt> v{start};
	for (const auto& m : r.calls({"STRAIGHT_FEED"})) {
		Pt p{};
		double z;
		EXPECT_EQ(std::sscanf(m.c_str(), "STRAIGHT_FEED(%lf, %lf, %lf)", &p.x, &p.y, &z), 3) << m;
		v.push_back(p);
	}
	return v;
}

double dist_to_path(Pt p, const std::vector<Pt>& poly)
{
	double best = 1e300;
	for (size_t i = 0; i + 1 < poly.size(); i++) {
		Pt a = poly[i], b = poly[i + 1];
		double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
		double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
		t = std::min(1.0, std::max(0.0, t));
		best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
	}
	return best;
}

// Checks the path against curve(t), t in [0, 1]; the printed values have 4 decimals.
void check_within(const std::vector<Pt>& poly, const std::function<Pt(double)>& curve, double tol)
{
	const double print = 1e-4;
	ASSERT_GE(poly.size(), 3u);
	Pt end = curve(1);
	EXPECT_NEAR(poly.back().x, end.x, print);
	EXPECT_NEAR(poly.back().y, end.y, print);
	for (int i = 0; i <= 4000; i++) {
		Pt c = curve(i / 4000.0);
		EXPECT_LE(dist_to_path(c, poly), tol + print) << "curve point " << i;
	}
	std::vector<Pt> dense;
	for (int i = 0; i <= 20000; i++)
		dense.push_back(curve(i / 20000.0));
	for (const Pt& v : poly)
		EXPECT_LE(dist_to_path(v, dense), 2 * print) << "vertex " << v.x << "," << v.y;
}

Pt bezier(const std::vector<Pt>& cp, double t)
{
	size_t n = cp.size() - 1;
	Pt r{0, 0};
	for (size_t i = 0; i <= n; i++) {
		double b = std::tgamma(n + 1.0) / (std::tgamma(i + 1.0) * std::tgamma(n - i + 1.0)) *
		           std::pow(t, (double)i) * std::pow(1 - t, (double)(n - i));
		r.x += b * cp[i].x;
		r.y += b * cp[i].y;
	}
	return r;
}

// Cox-de Boor basis N(i, k) (order k) on knots u.
double basis(int i, int k, double t, const std::vector<double>& u)
{
	if (k == 1) {
		if (t == 1.0)   // the last non-empty span is closed at 1
			return u[i] < 1.0 && u[i + 1] == 1.0 ? 1 : 0;
		return u[i] <= t && t < u[i + 1] ? 1 : 0;
	}
	double a = u[i + k - 1] > u[i] ? (t - u[i]) / (u[i + k - 1] - u[i]) * basis(i, k - 1, t, u) : 0;
	double b = u[i + k] > u[i + 1] ? (u[i + k] - t) / (u[i + k] - u[i + 1]) * basis(i + 1, k - 1, t, u) : 0;
	return a + b;
}

Pt nurbs(const std::vector<Pt>& cp, const std::vector<double>& w, int k, double t)
{
	int n = (int)cp.size();
	std::vector<double> u(k, 0.0);
	for (int i = 1; i <= n - k; i++)
		u.push_back((double)i / (n - k + 1));
	u.insert(u.end(), k, 1.0);
	double sx = 0, sy = 0, sw = 0;
	for (int i = 0; i < n; i++) {
		double b = basis(i, k, t, u) * w[i];
		sx += b * cp[i].x;
		sy += b * cp[i].y;
		sw += b;
	}
	return {sx / sw, sy / sw};
}

}  // namespace

TEST(InterpSplines, CubicWithinG64Tolerance)
{
	Prog r("G64 P0.01\nG0 X1 Y2\nG5 X11 Y2 I2 J5 P-2 Q5 F100\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	auto poly = path(r, {1, 2});
	check_within(poly, [](double t) { return bezier({{1, 2}, {3, 7}, {9, 7}, {11, 2}}, t); }, 0.01);
	// max|B''| = 6 * |(1,2) - 2(3,7) + (9,7)| = 6 * |(4,-5)| = 38.42 -> 22 segments:
	// ceil(sqrt(38.42 / (8 * 0.01))) = ceil(21.9)
	EXPECT_EQ(poly.size(), 23u);
}

TEST(InterpSplines, CubicContinuesTangentAndDefaultTolerance)
{
	// G61: no G64 tolerance, 0.0254 mm. The second G5 omits I J: its first control
	// point mirrors the last P Q: (10,0) - (-2,3) = (12,-3).
	Prog r("G61\nG5 X10 Y0 I0 J3 P-2 Q3 F100\nG5 X20 Y0 P0 Q-3\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	auto poly = path(r, {0, 0});
	size_t split = 0;
	for (size_t i = 0; i < poly.size(); i++)
		if (std::fabs(poly[i].x - 10) < 1e-9 && std::fabs(poly[i].y) < 1e-9)
			split = i;
	ASSERT_GT(split, 0u);
	std::vector<Pt> a(poly.begin(), poly.begin() + split + 1), b(poly.begin() + split, poly.end());
	check_within(a, [](double t) { return bezier({{0, 0}, {0, 3}, {8, 3}, {10, 0}}, t); }, 0.0254);
	check_within(b, [](double t) { return bezier({{10, 0}, {12, -3}, {20, -3}, {20, 0}}, t); }, 0.0254);
}

TEST(InterpSplines, Quadratic)
{
	Prog r("G20 G64 P0.001\nG5.1 X4 Y0 I2 J3 F10\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	auto poly = path(r, {0, 0});
	for (auto& p : poly) {   // printed in machine units (mm)
		p.x /= 25.4;
		p.y /= 25.4;
	}
	check_within(poly, [](double t) { return bezier({{0, 0}, {2, 3}, {4, 0}}, t); }, 0.001 + 1e-4 / 25.4);
}

TEST(InterpSplines, NurbsFromTheCurrentPoint)
{
	Prog r("G64 P0.005\nG0 X0 Y0\nF10\nG5.2 X0 Y1 P1 L3\nX2 Y2 P1\nX2 Y0 P1\nX0 Y0 P2\nG5.3\nG0 X5\nM2\n");
	ASSERT_TRUE(r.ok()) << r.error();
	auto poly = path(r, {0, 0});
	std::vector<Pt> cp = {{0, 0}, {0, 1}, {2, 2}, {2, 0}, {0, 0}};
	std::vector<double> w = {1, 1, 1, 1, 2};
	check_within(poly, [&](double t) { return nurbs(cp, w, 3, t); }, 0.005);
	// after G5.3 the program continues from the last control point
	EXPECT_EQ(r.moves().back(), "STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000)");
	// order 4, weights 1, G91 control points
	Prog q("G64 P0.002 F10\nG91 G5.2 L4\nX1 Y2\nX2 Y0\nX1 Y-2\nX1 Y1\nG5.3\nM2\n");
	ASSERT_TRUE(q.ok()) << q.error();
	std::vector<Pt> cq = {{0, 0}, {1, 2}, {3, 2}, {4, 0}, {5, 1}};
	check_within(path(q, {0, 0}), [&](double t) { return nurbs(cq, {1, 1, 1, 1, 1}, 4, t); }, 0.002);
}

TEST(InterpSplines, Errors)
{
	expect_error("G18 G5 X1 I1 J1 P1 Q1 F1", "G5 is only allowed in the XY plane (G17)");
	expect_error("G5 X1 Y1 I1 J1 P1 F1", "G5 requires both P and Q");
	expect_error("G5 X1 Y1 I1 P1 Q1 F1", "G5 requires both I and J, or neither right after a G5");
	expect_error("G5 X1 Y1 P1 Q1 F1", "G5 requires both I and J, or neither right after a G5");
	expect_error("G1 X1 F1\nG5 X2 Y1 P1 Q1", "G5 requires both I and J, or neither right after a G5", 2);
	expect_error("G5 X1 Y1 Z1 I1 J1 P1 Q1 F1", "G5 allows only X and Y axis words");
	expect_error("G5 X1 Y1 I1 J1 P1 Q1", "Cannot make a spline with zero feed rate");
	expect_error("G41.1 D1 F1\nG5 X1 Y1 I1 J1 P1 Q1", "Cannot convert spline with cutter radius compensation", 2);
	expect_error("G5.1 X1 Y1 I0 F1", "G5.1 requires an I or J that is not zero");
	expect_error("G5.1 X1 Y1 I1 J1 P1 F1", "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 M62 M63 M64 M65 M66 M98 or user M code to use it");
	expect_error("G5 F1", "All axes missing with motion code");
	expect_error("G5.3", "G5.3 without an open G5.2 block");
	expect_error("F1 G5.2\nX1 Y1\nG5.3", "NURBS with order 3 needs at least 3 control points (it has 2)", 3);
	expect_error("F1 G5.2\nX1 Y1\nM3\nG5.3", "Only X Y P control point lines and G5.3 may follow G5.2", 3);
	expect_error("F1 G5.2\nX1 Y1\nG1 X2\nG5.3", "Only X Y P control point lines and G5.3 may follow G5.2", 3);
	expect_error("F1 G5.2\nX1 Y1 Z1\nG5.3", "Only X Y P control point lines and G5.3 may follow G5.2", 2);
	expect_error("F1 G5.2\no1 if [1]\no1 endif", "Only X Y P control point lines and G5.3 may follow G5.2", 2);
	expect_error("F1 G5.2\nX1 Y1 P0\nG5.3", "NURBS weight P must be greater than zero", 2);
	expect_error("F1 G5.2 L1\nX1 Y1\nG5.3", "NURBS order L must be an integer from 2 to 10");
	expect_error("G93 G5.2 X1 Y1 F1", "G5.2 is not allowed in inverse time feed mode (G93)");
}
