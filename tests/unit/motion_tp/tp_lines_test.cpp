// Single lines, G61.1/G61 stops, queue limits and argument checks.
#include "tp_sim.hpp"

TEST(TpLine, ReachesTargetWithinLimits)
{
	TpSim s;
	ASSERT_EQ(s.line(10, 5, -2, 80), 0);
	s.run();
	Vec9 p = s.pos();
	EXPECT_DOUBLE_EQ(p[0], 10);
	EXPECT_DOUBLE_EQ(p[1], 5);
	EXPECT_DOUBLE_EQ(p[2], -2);
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	// path speed never above F
	for (size_t k = 1; k < s.trace.size(); k++)
		EXPECT_LE(TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt), 80 * (1 + 1e-9));
	EXPECT_TRUE(tp_is_done(s.tp));
}

TEST(TpLine, CruisesAtFeedAndTakesTheTrapezoidTime)
{
	TpSim s;
	ASSERT_EQ(s.line(100, 0, 0, 50), 0);
	int n = s.run();
	// accel 0.05 s + cruise (100 - 2.5)/50 = 1.95 s + decel 0.05 s = 2.05 s
	EXPECT_NEAR(n * s.dt, 2.05, 0.005);
	double vmid = TpSim::path_speed(s.trace[1000], s.trace[999], s.dt);
	EXPECT_NEAR(vmid, 50, 1e-9);
}

TEST(TpLine, PerAxisLimitsOnDiagonalAndVlimit)
{
	TpSim s;
	tp_set_vlimit(s.tp, 30);
	ASSERT_EQ(s.line(50, 50, 0, 1000), 0);
	s.run();
	for (size_t k = 1; k < s.trace.size(); k++)
		EXPECT_LE(TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt), 30 * (1 + 1e-9));
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpLine, RotaryOnlyIgnoresVlimit)
{
	TpSim s;
	tp_set_vlimit(s.tp, 1);
	tp_pose p{};
	p.a = 90;
	tp_move m = s.feed(50);
	ASSERT_EQ(tp_add_line(s.tp, &p, &m), 0);
	s.run();
	EXPECT_DOUBLE_EQ(s.pos()[3], 90);
	double vmax = 0;
	for (size_t k = 1; k < s.trace.size(); k++)
		vmax = std::max(vmax, (s.trace[k][3] - s.trace[k - 1][3]) / s.dt);
	EXPECT_NEAR(vmax, 50, 1e-6);
}

static void square(TpSim &s, double side, double f)
{
	ASSERT_EQ(s.line(side, 0, 0, f, 1), 0);
	ASSERT_EQ(s.line(side, side, 0, f, 2), 0);
	ASSERT_EQ(s.line(0, side, 0, f, 3), 0);
	ASSERT_EQ(s.line(0, 0, 0, f, 4), 0);
}

// the cycle at which the trace sits exactly on pt, and the speeds around it
static void expect_stop_at(const TpSim &s, const Vec9 &pt)
{
	bool found = false;
	for (size_t k = 1; k + 1 < s.trace.size(); k++) {
		double d = seg_dist(s.trace[k], pt, pt);
		if (d < 1e-12) {
			found = true;
			double vin = TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt);
			double vout = TpSim::path_speed(s.trace[k + 1], s.trace[k], s.dt);
			EXPECT_LE(vin, s.amax * s.dt * (1 + 1e-9)) << "arriving at corner";
			EXPECT_LE(vout, s.amax * s.dt * (1 + 1e-9)) << "leaving corner";
			break;
		}
	}
	EXPECT_TRUE(found) << "never on corner " << pt[0] << "," << pt[1];
}

TEST(TpLine, G61StopsExactlyAtSquareCorners)
{
	TpSim s;
	ASSERT_EQ(tp_set_term_cond(s.tp, TP_TERM_EXACT, 0), 0);
	square(s, 10, 60);
	s.run();
	expect_stop_at(s, Vec9{10, 0, 0});
	expect_stop_at(s, Vec9{10, 10, 0});
	expect_stop_at(s, Vec9{0, 10, 0});
	EXPECT_LE(s.worst_vel_ratio(), 1 + 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	Vec9 p = s.pos();
	EXPECT_DOUBLE_EQ(p[0], 0);
	EXPECT_DOUBLE_EQ(p[1], 0);
}

TEST(TpLine, G611StopsAlsoOnCollinearJunctions)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_STOP, 0);
	s.line(5, 0, 0, 60);
	s.line(10, 0, 0, 60);
	s.run();
	expect_stop_at(s, Vec9{5, 0, 0});
}

TEST(TpLine, G61KeepsSpeedThroughCollinearJunction)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_EXACT, 0);
	s.line(5, 0, 0, 60);
	s.line(10, 0, 0, 60);
	s.run();
	// at x = 5 the speed is the feed
	for (size_t k = 1; k < s.trace.size(); k++)
		if (s.trace[k - 1][0] < 5 && s.trace[k][0] >= 5) {
			EXPECT_NEAR(TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt), 60, 1e-6);
		}
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpLine, RapidToFeedIsAlwaysAStop)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0);
	tp_pose p = pose(5, 0);
	tp_move m = s.feed(60);
	m.motion_type = TP_MOTION_TRAVERSE;
	ASSERT_EQ(tp_add_line(s.tp, &p, &m), 0);
	s.line(10, 0, 0, 60);
	s.run();
	expect_stop_at(s, Vec9{5, 0, 0});
}

TEST(TpLine, ReversalIsAStop)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.1);
	s.line(5, 0, 0, 60);
	s.line(2, 0, 0, 60);
	s.run();
	expect_stop_at(s, Vec9{5, 0, 0});
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpQueue, FullIsReported)
{
	TpSim s(10);
	int ok = 0, err = 0;
	for (int i = 1; i <= 20 && !err; i++) {
		err = s.line(i, 0, 0, 10, i);
		if (!err)
			ok++;
	}
	EXPECT_EQ(err, TP_ERR_QUEUE_FULL);
	EXPECT_EQ(ok, 9);
	EXPECT_TRUE(tp_is_queue_full(s.tp));
	EXPECT_TRUE(s.cycle().queue_full);
	EXPECT_STREQ(tp_strerror(TP_ERR_QUEUE_FULL), "motion queue full");
}

TEST(TpQueue, BadArgumentsAreRefusedAndChangeNothing)
{
	TpSim s;
	EXPECT_EQ(s.line(NAN, 0, 0, 10), TP_ERR_INVALID);
	EXPECT_EQ(s.line(1, 0, 0, 0), TP_ERR_INVALID);
	EXPECT_EQ(s.line(1, 0, 0, -3), TP_ERR_INVALID);
	EXPECT_EQ(tp_queue_depth(s.tp), 0);
	EXPECT_EQ(tp_set_cycle_time(s.tp, 0), TP_ERR_INVALID);
	EXPECT_EQ(tp_set_term_cond(s.tp, 7, 0), TP_ERR_INVALID);
	EXPECT_EQ(tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, -1), TP_ERR_INVALID);
	EXPECT_EQ(tp_set_axis_limits(s.tp, 9, 1, 1), TP_ERR_INVALID);
	EXPECT_EQ(tp_set_dout(s.tp, 64, 1, 1), TP_ERR_INVALID);
	EXPECT_EQ(tp_set_aout(s.tp, -1, 1, 1), TP_ERR_INVALID);
	EXPECT_EQ(tp_set_aout(s.tp, 0, 1, NAN), TP_ERR_INVALID);
	EXPECT_EQ(tp_set_max_feed_scale(s.tp, 0.5), TP_ERR_INVALID);
	EXPECT_EQ(tp_size(2), 0u);
	std::vector<double> small(8);
	EXPECT_EQ(tp_init(small.data(), small.size() * sizeof(double), 10), nullptr);
	// a zero-length move is accepted and dropped
	EXPECT_EQ(s.line(0, 0, 0, 10), 0);
	EXPECT_EQ(tp_queue_depth(s.tp), 0);
	// set_pos is refused while segments are queued
	s.line(1, 0, 0, 10);
	tp_pose p = pose(3, 3);
	EXPECT_EQ(tp_set_pos(s.tp, &p), TP_ERR_BUSY);
}

TEST(TpQueue, StatusWhileExecuting)
{
	TpSim s;
	s.line(10, 0, 0, 50, 7);
	s.line(10, 10, 0, 50, 8);
	const tp_outputs &o = s.cycle();
	EXPECT_EQ(o.exec_id, 7);
	EXPECT_EQ(o.motion_type, TP_MOTION_FEED);
	EXPECT_EQ(o.queue_depth, 2);
	EXPECT_EQ(o.active_depth, 1);
	EXPECT_NEAR(o.distance_to_go, 10 - s.pos()[0], 1e-12);
	EXPECT_FALSE(o.done);
	s.run();
	EXPECT_EQ(s.outs.back().exec_id, 0);
	EXPECT_TRUE(s.outs.back().done);
}
