// Arcs and helices: on the true circle, within velocity/acceleration limits, and
// tangent arc-line junctions keep speed.
#include "tp_sim.hpp"

static int arc(TpSim &s, double ex, double ey, double ez, double cx, double cy, int ccw, double f,
	       int turn = 0)
{
	tp_pose e = pose(ex, ey, ez);
	tp_cart c{cx, cy, 0}, n{0, 0, ccw ? 1.0 : -1.0};
	tp_move m = s.feed(f);
	m.motion_type = TP_MOTION_ARC;
	return tp_add_circle(s.tp, &e, &c, &n, turn, &m);
}

TEST(TpArc, HalfCircleOnTheCircleWithinLimits)
{
	TpSim s;
	tp_pose st = pose(10, 0);
	tp_set_pos(s.tp, &st);
	s.trace[0] = vec(st);
	ASSERT_EQ(arc(s, -10, 0, 0, 0, 0, 1, 80), 0);
	s.run();
	for (const Vec9 &p : s.trace) {
		EXPECT_NEAR(std::hypot(p[0], p[1]), 10, 1e-9);
		EXPECT_GE(p[1], -1e-12);	// ccw from +x to -x goes through +y
	}
	EXPECT_DOUBLE_EQ(s.pos()[0], -10);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpArc, SmallRadiusIsSpeedLimitedByNormalAcceleration)
{
	TpSim s;
	tp_pose st = pose(1, 0);
	tp_set_pos(s.tp, &st);
	s.trace[0] = vec(st);
	ASSERT_EQ(arc(s, 1, 0, 0, 0, 0, 0, 100), 0);	// full circle, cw
	s.run();
	double vmax = 0;
	for (size_t k = 1; k < s.trace.size(); k++)
		vmax = std::max(vmax, TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt));
	// v^2/r <= 0.866 a
	EXPECT_LE(vmax, std::sqrt(0.8660254 * s.amax * 1) * (1 + 1e-6));
	EXPECT_GT(vmax, 0.9 * std::sqrt(0.8660254 * s.amax * 1));
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	for (const Vec9 &p : s.trace)
		EXPECT_NEAR(std::hypot(p[0], p[1]), 1, 1e-9);
	// cw from +x: first moves toward -y
	EXPECT_LT(s.trace[5][1], 0);
}

TEST(TpArc, HelixAdvancesLinearlyAlongAxis)
{
	TpSim s;
	tp_pose st = pose(5, 0);
	tp_set_pos(s.tp, &st);
	s.trace[0] = vec(st);
	ASSERT_EQ(arc(s, 5, 0, -6, 0, 0, 1, 50, 2), 0);	// three turns down 6
	s.run();
	for (const Vec9 &p : s.trace) {
		EXPECT_NEAR(std::hypot(p[0], p[1]), 5, 1e-9);
		// z proportional to the unwrapped angle: check bound only
		EXPECT_LE(p[2], 1e-12);
		EXPECT_GE(p[2], -6 - 1e-12);
	}
	EXPECT_NEAR(s.pos()[2], -6, 1e-12);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	// path length 3 turns: t >= L / F
	double L = std::hypot(3 * 2 * M_PI * 5, 6.0);
	EXPECT_GE(s.trace.size() * s.dt, L / 50);
}

TEST(TpArc, TangentLineArcLineKeepsSpeed)
{
	// slot: line along +x, half circle ccw (r = 20), line back along -x; G61 (exact)
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_EXACT, 0);
	ASSERT_EQ(s.line(20, 0, 0, 50), 0);
	ASSERT_EQ(arc(s, 20, 40, 0, 20, 20, 1, 50), 0);
	ASSERT_EQ(s.line(0, 40, 0, 50), 0);
	s.run();
	// speed at both tangent junctions equals the feed (v^2/r = 125 < 0.866 a)
	int seen = 0;
	for (size_t k = 1; k < s.trace.size(); k++) {
		if ((s.trace[k - 1][0] < 20 && s.trace[k][0] >= 20 && s.trace[k][1] < 1)
		    || (s.trace[k - 1][0] > 20 && s.trace[k][0] <= 20 && s.trace[k][1] > 39)) {
			EXPECT_NEAR(TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt), 50, 1e-3);
			seen++;
		}
	}
	EXPECT_EQ(seen, 2);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
}

TEST(TpArc, ArcLineCornerBlendsWithinLimits)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.01);
	ASSERT_EQ(s.line(10, 0, 0, 50), 0);
	ASSERT_EQ(arc(s, 20, 0, 0, 15, 0, 0, 50), 0);	// cw half circle up and over: a corner at (10,0)
	ASSERT_EQ(s.line(20, -10, 0, 50), 0);
	s.run();
	EXPECT_NEAR(s.pos()[0], 20, 1e-12);
	EXPECT_NEAR(s.pos()[1], -10, 1e-12);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
}

TEST(TpArc, BadArcsAreRefused)
{
	TpSim s;
	tp_pose e = pose(1, 1);
	tp_cart c{0, 0, 0}, n0{0, 0, 0}, n{0, 0, 1};
	tp_move m = s.feed(10);
	EXPECT_EQ(tp_add_circle(s.tp, &e, &c, &n0, 0, &m), TP_ERR_INVALID);	// no normal
	EXPECT_EQ(tp_add_circle(s.tp, &e, &c, &n, 0, &m), TP_ERR_INVALID);	// start on the centre
	EXPECT_EQ(tp_queue_depth(s.tp), 0);
}
