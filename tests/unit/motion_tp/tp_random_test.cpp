// Random programs (fixed seeds): every mode keeps the per-axis limits, ends on the
// programmed end point, and G64 P stays inside its band around the programmed path.
#include <random>
#include "tp_sim.hpp"

struct Prog {
	std::vector<Vec9> pts;
};

static Prog random_polyline(unsigned seed, int n, double span, double min_len)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(-span, span);
	Prog p;
	p.pts.push_back(Vec9{});
	while ((int)p.pts.size() <= n) {
		Vec9 q = p.pts.back();
		q[0] += u(rng);
		q[1] += u(rng);
		q[2] += 0.3 * u(rng);
		double d = std::hypot(q[0] - p.pts.back()[0], q[1] - p.pts.back()[1], q[2] - p.pts.back()[2]);
		if (d >= min_len)
			p.pts.push_back(q);
	}
	return p;
}

static double worst_dev(const TpSim &s, const Prog &p)
{
	double w = 0;
	for (const Vec9 &x : s.trace) {
		double d = 1e99;
		for (size_t i = 0; i + 1 < p.pts.size(); i++)
			d = std::min(d, seg_dist(x, p.pts[i], p.pts[i + 1]));
		w = std::max(w, d);
	}
	return w;
}

class TpRandom : public ::testing::TestWithParam<std::tuple<int, unsigned>> {};

TEST_P(TpRandom, LimitsEndPointAndBand)
{
	int mode = std::get<0>(GetParam());
	unsigned seed = std::get<1>(GetParam());
	TpSim s;
	double tol = 0.02;
	if (mode == 0)
		tp_set_term_cond(s.tp, TP_TERM_STOP, 0);
	else if (mode == 1)
		tp_set_term_cond(s.tp, TP_TERM_EXACT, 0);
	else if (mode == 2)
		tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, tol);
	else if (mode == 3) {
		tp_set_arc_blend(s.tp, 0, 1, 50, 4, 100, 0.1);
		tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, tol);
	} else if (mode == 4) {	// G64 without P: arcs bounded by a quarter of the lengths
		tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0);
	} else {		// G64 without P, parabolic
		tp_set_arc_blend(s.tp, 0, 1, 50, 4, 100, 0.1);
		tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0);
	}
	Prog p = random_polyline(seed, 40, seed % 2 ? 5.0 : 0.5, 0.05);
	for (size_t i = 1; i < p.pts.size(); i++) {
		tp_pose e = pose(p.pts[i][0], p.pts[i][1], p.pts[i][2]);
		tp_move m = s.feed(40 + 10 * (i % 3), (int)i);
		ASSERT_EQ(tp_add_line(s.tp, &e, &m), 0);
	}
	s.run(400000);
	ASSERT_TRUE(s.outs.back().done);
	for (int i = 0; i < 3; i++)
		EXPECT_NEAR(s.pos()[i], p.pts.back()[i], 1e-9);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	if (mode == 2 || mode == 3)
		EXPECT_LE(worst_dev(s, p), tol + 1e-9);
	else if (mode >= 4)
		EXPECT_LE(worst_dev(s, p), 0.25 * (seed % 2 ? 5.0 : 0.5) * 1.8);	// quarter of the longest
	else
		EXPECT_LE(worst_dev(s, p), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Modes, TpRandom,
			 ::testing::Combine(::testing::Values(0, 1, 2, 3, 4, 5), ::testing::Values(1u, 2u, 3u, 4u)));

TEST(TpRandomOverride, ChangingFeedOverrideKeepsLimits)
{
	TpSim s;
	tp_set_max_feed_scale(s.tp, 2.0);
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.01);
	Prog p = random_polyline(7, 60, 2.0, 0.05);
	for (size_t i = 1; i < p.pts.size(); i++) {
		tp_pose e = pose(p.pts[i][0], p.pts[i][1], p.pts[i][2]);
		tp_move m = s.feed(30, (int)i);
		ASSERT_EQ(tp_add_line(s.tp, &e, &m), 0);
	}
	std::mt19937 rng(9);
	std::uniform_real_distribution<double> u(0.0, 2.0);
	for (int k = 0; k < 400000; k++) {
		if (k % 97 == 0)
			s.in.feed_scale = u(rng);
		if (s.cycle().done)
			break;
	}
	ASSERT_TRUE(s.outs.back().done);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(worst_dev(s, p), 0.01 + 1e-9);
}

// Segments arrive while the planner runs (the interpreter streaming behind motion),
// with pauses and resumes: limits hold and the path ends on the last point.
TEST(TpRandomStream, StreamingWithPausesKeepsLimitsAndBand)
{
	for (int mode = 0; mode < 3; mode++) {
		TpSim s;
		tp_set_arc_blend(s.tp, mode != 2, 1, 50, 4, 100, 0.1);
		tp_set_term_cond(s.tp, mode == 0 ? TP_TERM_EXACT : TP_TERM_PARABOLIC, 0.01);
		Prog p = random_polyline(11 + mode, 80, 1.0, 0.02);
		const int period = mode == 1 ? 41 : 7;	// mode 1: starved queue
		size_t next = 1;
		std::mt19937 rng(5);
		for (int k = 0; k < 400000; k++) {
			if (next < p.pts.size() && k % period == 0) {
				tp_pose e = pose(p.pts[next][0], p.pts[next][1], p.pts[next][2]);
				tp_move m = s.feed(40, (int)next);
				ASSERT_EQ(tp_add_line(s.tp, &e, &m), 0);
				next++;
			}
			if (k % 331 == 100)
				tp_pause(s.tp);
			if (k % 331 == 200)
				tp_resume(s.tp);
			if (s.cycle().done && next >= p.pts.size())
				break;
		}
		ASSERT_TRUE(s.outs.back().done) << "mode " << mode;
		for (int i = 0; i < 3; i++)
			EXPECT_NEAR(s.pos()[i], p.pts.back()[i], 1e-9) << "mode " << mode;
		EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9) << "mode " << mode;
		EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6) << "mode " << mode;
		EXPECT_LE(worst_dev(s, p), 0.01 + 1e-9) << "mode " << mode;
	}
}

// Lines and tangent / non-tangent arcs mixed, G64 P: limits and end point.
TEST(TpRandomArcs, LinesAndArcsKeepLimits)
{
	for (unsigned seed = 1; seed <= 4; seed++) {
		TpSim s;
		tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.01);
		std::mt19937 rng(seed);
		std::uniform_real_distribution<double> u(-3, 3);
		double x = 0, y = 0;
		for (int i = 0; i < 30; i++) {
			double nx = x + u(rng), ny = y + u(rng);
			if (i % 2) {
				// arc to (nx, ny) around the midpoint shifted sideways
				double cx = 0.5 * (x + nx) + 0.3 * (ny - y), cy = 0.5 * (y + ny) - 0.3 * (nx - x);
				// end on the same radius: project the end onto the start circle
				double r = std::hypot(x - cx, y - cy), a = std::atan2(ny - cy, nx - cx);
				nx = cx + r * std::cos(a);
				ny = cy + r * std::sin(a);
				tp_pose e = pose(nx, ny, 0);
				tp_cart c{cx, cy, 0}, n{0, 0, (i % 4 == 1) ? 1.0 : -1.0};
				tp_move m = s.feed(40, i);
				m.motion_type = TP_MOTION_ARC;
				ASSERT_EQ(tp_add_circle(s.tp, &e, &c, &n, 0, &m), 0);
			} else {
				ASSERT_EQ(s.line(nx, ny, 0, 40, i), 0);
			}
			x = nx;
			y = ny;
		}
		s.run(400000);
		ASSERT_TRUE(s.outs.back().done);
		EXPECT_NEAR(s.pos()[0], x, 1e-9);
		EXPECT_NEAR(s.pos()[1], y, 1e-9);
		EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9) << "seed " << seed;
		EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6) << "seed " << seed;
	}
}
