// Spindle-synchronized motion: G33 position sync, G95 velocity sync, rigid tap, at-speed.
#include "tp_sim.hpp"

TEST(TpSync, PositionSyncWaitsForIndexAndFollowsSpindle)
{
	TpSim s;
	const double K = 1.5, rps = 10;	// 15 units/s
	ASSERT_EQ(tp_set_spindle_sync(s.tp, 0, K, 0), 0);
	s.line(0, 0, -60, 60);
	s.in.spindle_speed = rps;
	double revs = 0;
	const tp_outputs &o1 = s.cycle();
	EXPECT_TRUE(o1.spindle_index_request);
	EXPECT_TRUE(o1.waiting_for_index);
	EXPECT_TRUE(o1.spindle_sync);
	EXPECT_EQ(o1.spindle_num, 0);
	EXPECT_FALSE(s.cycle().spindle_index_request);	// asked once
	s.in.spindle_index_enable = 1;	// motmod set the pin
	for (int i = 0; i < 5; i++) {
		revs += rps * s.dt;
		s.in.spindle_revs = revs;
		EXPECT_TRUE(s.cycle().waiting_for_index);
	}
	EXPECT_DOUBLE_EQ(s.pos()[2], 0);
	s.in.spindle_index_enable = 0;	// index found: encoder resets revs
	revs = 0;
	int n = 0;
	while (n < 20000) {
		revs += rps * s.dt;
		s.in.spindle_revs = revs;
		if (s.cycle().done)
			break;
		n++;
		// once locked: z = -(revs - offset) * K with a constant offset
	}
	EXPECT_DOUBLE_EQ(s.pos()[2], -60);
	// in the middle the axis moves exactly K per rev
	size_t k = s.trace.size() / 2;
	double v = (s.trace[k - 1][2] - s.trace[k][2]) / s.dt;
	EXPECT_NEAR(v, K * rps, 1e-6);
	// the spindle feeds through feed override 0 too (no pause for position sync)
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpSync, PositionSyncTracksSpindleSpeedChanges)
{
	TpSim s;
	const double K = 1.0;
	tp_set_spindle_sync(s.tp, 0, K, 0);
	s.line(0, 0, -200, 100);
	s.in.spindle_speed = 10;
	s.in.feed_scale = 0;	// ignored by position-synchronized moves
	s.cycle();
	s.in.spindle_index_enable = 1;
	s.cycle();
	s.in.spindle_index_enable = 0;
	double revs = 0;
	for (int i = 0; i < 1000; i++) {
		revs += s.in.spindle_speed * s.dt;
		s.in.spindle_revs = revs;
		s.cycle();
	}
	double lag = revs * K + s.pos()[2];	// spindle position minus axis position: constant
	s.in.spindle_speed = 20;
	for (int i = 0; i < 1000; i++) {
		revs += s.in.spindle_speed * s.dt;
		s.in.spindle_revs = revs;
		s.cycle();
	}
	EXPECT_NEAR(revs * K + s.pos()[2], lag, 1e-6);	// back in phase after the change
	size_t k = s.trace.size() - 1;
	EXPECT_NEAR((s.trace[k - 1][2] - s.trace[k][2]) / s.dt, 20, 1e-6);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpSync, VelocitySyncFeedPerRev)
{
	TpSim s;
	tp_set_spindle_sync(s.tp, 0, 0.1, 1);	// G95 0.1 per rev
	s.line(100, 0, 0, 50);
	s.in.spindle_speed = -20;	// direction does not matter
	for (int i = 0; i < 300; i++)
		s.cycle();
	size_t k = s.trace.size() - 1;
	EXPECT_NEAR((s.trace[k][0] - s.trace[k - 1][0]) / s.dt, 2.0, 1e-9);
	EXPECT_TRUE(s.outs.back().spindle_sync);
	tp_set_spindle_sync(s.tp, 0, 0, 0);	// off for following moves
	EXPECT_EQ(s.line(100, 10, 0, 50), 0);
}

TEST(TpSync, WaitsForAtSpeed)
{
	TpSim s;
	tp_pose p = pose(10, 0);
	tp_move m = s.feed(20);
	m.atspeed = 1;
	tp_add_line(s.tp, &p, &m);
	s.in.spindle_at_speed = 0;
	for (int i = 0; i < 10; i++)
		EXPECT_TRUE(s.cycle().waiting_for_atspeed);
	EXPECT_DOUBLE_EQ(s.pos()[0], 0);
	s.in.spindle_at_speed = 1;
	s.run();
	EXPECT_DOUBLE_EQ(s.pos()[0], 10);
}

TEST(TpSync, RigidTapGoesDownReversesAndReturns)
{
	TpSim s;
	const double K = 1.0;	// 1 unit per rev
	tp_set_spindle_sync(s.tp, 0, K, 0);
	tp_pose p = pose(0, 0, -10);
	tp_move m = s.feed(100);
	EXPECT_EQ(tp_add_rigid_tap(s.tp, &p, 0, &m), TP_ERR_INVALID);
	ASSERT_EQ(tp_add_rigid_tap(s.tp, &p, 1.0, &m), 0);
	// a simulated spindle: commanded 10 rev/s times the planner's scale, 100 rev/s^2
	double revs = 0, spd = 10, cmd = 10, zmin = 0;
	bool reversed = false;
	int n = 0;
	for (; n < 20000; n++) {
		s.in.spindle_revs = revs;
		s.in.spindle_speed = spd;
		const tp_outputs &o = s.cycle();
		zmin = std::min(zmin, o.pos.z);
		if (o.spindle_speed_scale < 0)
			reversed = true;
		if (o.done)
			break;
		double want = cmd * o.spindle_speed_scale;
		spd += std::clamp(want - spd, -100 * s.dt, 100 * s.dt);
		revs += spd * s.dt;
	}
	EXPECT_TRUE(reversed);
	EXPECT_LE(zmin, -10);		// reached depth (plus the spindle's stopping overshoot)
	EXPECT_GT(zmin, -10 - 0.6);	// 10^2 / (2 * 100) = 0.5 overshoot
	EXPECT_NEAR(s.pos()[2], 0, 1e-9);	// back on the start point
	EXPECT_EQ(s.outs.back().spindle_speed_scale, 1.0);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	tp_set_spindle_sync(s.tp, 0, 0, 0);
	EXPECT_EQ(tp_add_rigid_tap(s.tp, &p, 1.0, &m), TP_ERR_NO_SYNC);
}

TEST(TpSync, ChainOfSynchronizedSegmentsStaysInPhase)
{
	// G33 along z in two collinear pieces, blended: one index wait, one phase
	TpSim s;
	const double K = 2.0;
	tp_set_term_cond(s.tp, TP_TERM_PARABOLIC, 0.01);
	tp_set_spindle_sync(s.tp, 0, K, 0);
	s.line(0, 0, -30, 100, 1);
	s.line(0, 0, -60, 100, 2);
	s.in.spindle_speed = 10;
	int requests = 0;
	double revs = 0, lag = 0;
	bool locked = false;
	for (int n = 0; n < 20000; n++) {
		s.in.spindle_revs = revs;
		const tp_outputs &o = s.cycle();
		requests += o.spindle_index_request;
		if (o.spindle_index_request)
			s.in.spindle_index_enable = 1;
		else if (s.in.spindle_index_enable) {
			s.in.spindle_index_enable = 0;	// the index: revs restart at 0
			revs = 0;
			continue;
		}
		if (o.done)
			break;
		if (n > 300 && o.pos.z > -59) {
			double l = revs * K + o.pos.z;
			if (!locked) {
				lag = l;
				locked = true;
			}
			EXPECT_NEAR(l, lag, 1e-9) << "cycle " << n << " z " << o.pos.z;
		}
		revs += s.in.spindle_speed * s.dt;
	}
	EXPECT_EQ(requests, 1);
	EXPECT_DOUBLE_EQ(s.pos()[2], -60);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}
