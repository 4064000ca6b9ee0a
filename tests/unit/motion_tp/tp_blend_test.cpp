// G64 blending: tolerance band, limits, look-ahead through short segments.
#include "tp_sim.hpp"

// worst distance of the trace from the closed polyline pts
static double worst_dev(const TpSim &s, const std::vector<Vec9> &pts)
{
	double w = 0;
	for (const Vec9 &p : s.trace) {
		double d = 1e99;
		for (size_t i = 0; i + 1 < pts.size(); i++)
			d = std::min(d, seg_dist(p, pts[i], pts[i + 1]));
		w = std::max(w, d);
	}
	return w;
}

static std::vector<Vec9> square_pts(double side)
{
	return {Vec9{0, 0, 0}, Vec9{side, 0, 0}, Vec9{side, side, 0}, Vec9{0, side, 0}, Vec9{0, 0, 0}};
}

static void run_square(TpSim &s, double side, double f, int laps)
{
	for (int l = 0; l < laps; l++) {
		ASSERT_EQ(s.line(side, 0, 0, f, 1), 0);
		ASSERT_EQ(s.line(side, side, 0, f, 2), 0);
		ASSERT_EQ(s.line(0, side, 0, f, 3), 0);
		ASSERT_EQ(s.line(0, 0, 0, f, 4), 0);
	}
	s.run();
}

TEST(TpBlend, SquareG64P001StaysInBandAndLimits)
{
	TpSim s;
	ASSERT_EQ(tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.01), 0);
	run_square(s, 10, 60, 2);
	EXPECT_LE(worst_dev(s, square_pts(10)), 0.01 + 1e-9);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	// blended: the corners are passed without stopping (speed > 0 everywhere but the ends)
	double vmin = 1e9;
	for (size_t k = 200; k + 200 < s.trace.size(); k++)
		vmin = std::min(vmin, TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt));
	EXPECT_GT(vmin, 1.0);
	EXPECT_DOUBLE_EQ(s.pos()[0], 0);
	EXPECT_DOUBLE_EQ(s.pos()[1], 0);
}

TEST(TpBlend, SquareG64WithoutToleranceStaysWithinQuarterLength)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0);
	run_square(s, 10, 60, 1);
	EXPECT_LE(worst_dev(s, square_pts(10)), 2.5);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
}

TEST(TpBlend, BlendIsFasterThanExactStop)
{
	TpSim a, b;
	tp_set_term_cond(a.tp, TP_TERM_PARABOLIC, 0.05);
	tp_set_term_cond(b.tp, TP_TERM_EXACT, 0);
	run_square(a, 10, 60, 1);
	run_square(b, 10, 60, 1);
	EXPECT_LT(a.trace.size(), b.trace.size());
}

TEST(TpBlend, ParabolicFallbackStaysInBandAndLimits)
{
	TpSim s;
	tp_set_arc_blend(s.tp, 0, 1, 50, 4, 100, 0.1);	// arc blends off: 2.4-style parabolic
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.01);
	run_square(s, 10, 60, 1);
	EXPECT_LE(worst_dev(s, square_pts(10)), 0.01 + 1e-9);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpBlend, LookAheadKeepsFeedOverShortCollinearSegments)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.01);
	// 0.05 mm segments at 3000 mm/min = 50 mm/s, 1 ms cycle
	for (int i = 1; i <= 400; i++)
		ASSERT_EQ(s.line(0.05 * i, 0, 0, 50, i), 0);
	s.run();
	double vmax = 0;
	for (size_t k = 1; k < s.trace.size(); k++)
		vmax = std::max(vmax, TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt));
	EXPECT_NEAR(vmax, 50, 1e-6);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	EXPECT_DOUBLE_EQ(s.pos()[0], 20);
}

TEST(TpBlend, SlightKinksAreTangent)
{
	// a polyline approximating a large circle: tiny angle changes, blended at speed
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.001);
	const double R = 500;
	for (int i = 1; i <= 200; i++) {
		double a = i * 0.0005;
		ASSERT_EQ(s.line(R * std::sin(a), R - R * std::cos(a), 0, 40, i), 0);
	}
	s.run();
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	double vmid = TpSim::path_speed(s.trace[s.trace.size() / 2], s.trace[s.trace.size() / 2 - 1], s.dt);
	EXPECT_NEAR(vmid, 40, 1e-4);	// chord of a polyline corner
}
