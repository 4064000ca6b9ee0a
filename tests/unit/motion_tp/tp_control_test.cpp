// Overrides, pause/resume, abort, step, probe, synchronized outputs.
#include "tp_sim.hpp"

static double speed_at(const TpSim &s, size_t k) { return TpSim::path_speed(s.trace[k], s.trace[k - 1], s.dt); }

TEST(TpControl, FeedOverrideScalesVelocity)
{
	TpSim s;
	tp_set_max_feed_scale(s.tp, 2.0);
	s.line(100, 0, 0, 40);
	s.in.feed_scale = 0.5;
	for (int i = 0; i < 500; i++)
		s.cycle();
	EXPECT_NEAR(speed_at(s, s.trace.size() - 1), 20, 1e-9);
	s.in.feed_scale = 1.5;
	for (int i = 0; i < 500; i++)
		s.cycle();
	EXPECT_NEAR(speed_at(s, s.trace.size() - 1), 60, 1e-9);
	s.in.feed_scale = 3.0;	// above max feed scale: capped at 2 x F
	for (int i = 0; i < 500; i++)
		s.cycle();
	EXPECT_NEAR(speed_at(s, s.trace.size() - 1), 80, 1e-9);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpControl, RapidOverrideOnlyForTraverses)
{
	TpSim s;
	tp_pose p = pose(100, 0);
	tp_move m = s.feed(60);
	m.motion_type = TP_MOTION_TRAVERSE;
	tp_add_line(s.tp, &p, &m);
	s.in.feed_scale = 0.1;
	s.in.rapid_scale = 0.5;
	for (int i = 0; i < 300; i++)
		s.cycle();
	EXPECT_NEAR(speed_at(s, s.trace.size() - 1), 30, 1e-9);
	EXPECT_EQ(s.outs.back().motion_type, TP_MOTION_TRAVERSE);
}

TEST(TpControl, PauseDeceleratesWithinStoppingDistanceAndResumeFinishes)
{
	TpSim s;
	s.line(100, 0, 0, 50);
	for (int i = 0; i < 500; i++)
		s.cycle();
	double x0 = s.pos()[0];
	tp_pause(s.tp);
	int n = 0;
	while (!s.cycle().paused && n < 1000)
		n++;
	double stop = s.pos()[0] - x0;
	// v^2 / 2a = 1.25, plus at most one cycle of travel
	EXPECT_LE(stop, 1.25 + 50 * s.dt + 1e-9);
	EXPECT_GE(stop, 1.25 - 50 * s.dt);
	EXPECT_NEAR(n * s.dt, 0.05, 0.003);
	for (int i = 0; i < 100; i++)
		EXPECT_EQ(s.cycle().pos.x, s.pos()[0]);	// stays paused
	EXPECT_TRUE(tp_is_paused(s.tp));
	tp_resume(s.tp);
	s.run();
	EXPECT_DOUBLE_EQ(s.pos()[0], 100);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpControl, AbortStopsThenClearsQueue)
{
	TpSim s;
	s.line(100, 0, 0, 50, 1);
	s.line(100, 100, 0, 50, 2);
	for (int i = 0; i < 500; i++)
		s.cycle();
	tp_abort(s.tp);
	EXPECT_EQ(tp_add_line(s.tp, nullptr, nullptr), TP_ERR_ABORTING);
	s.run(2000);
	EXPECT_TRUE(s.outs.back().done);
	EXPECT_EQ(tp_queue_depth(s.tp), 0);
	EXPECT_LT(s.pos()[0], 100);
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
	// the planner is usable again from where it stopped
	double x = s.pos()[0];
	ASSERT_EQ(s.line(x, 10, 0, 50, 3), 0);
	s.run();
	EXPECT_DOUBLE_EQ(s.pos()[1], 10);
	EXPECT_DOUBLE_EQ(s.pos()[0], x);
}

TEST(TpControl, StepRunsOneSegment)
{
	TpSim s;
	tp_set_term_cond(s.tp, TP_TERM_EXACT, 0);
	s.line(10, 0, 0, 50, 1);
	s.line(10, 10, 0, 50, 2);
	s.line(0, 10, 0, 50, 3);
	tp_pause(s.tp);
	s.cycle();
	ASSERT_EQ(tp_step(s.tp), 0);
	for (int i = 0; i < 3000; i++)
		s.cycle();
	EXPECT_DOUBLE_EQ(s.pos()[0], 10);
	EXPECT_NEAR(s.pos()[1], 0, 1e-9);
	EXPECT_TRUE(s.outs.back().paused);
	ASSERT_EQ(tp_step(s.tp), 0);
	for (int i = 0; i < 3000; i++)
		s.cycle();
	EXPECT_DOUBLE_EQ(s.pos()[1], 10);
	EXPECT_DOUBLE_EQ(s.pos()[0], 10);
	tp_resume(s.tp);
	s.run();
	EXPECT_DOUBLE_EQ(s.pos()[0], 0);
}

TEST(TpControl, StepWhileMovingIsRefused)
{
	TpSim s;
	s.line(10, 0, 0, 50);
	s.cycle();
	s.cycle();
	EXPECT_EQ(tp_step(s.tp), TP_ERR_BUSY);
}

TEST(TpProbe, StopsOnTripAndReportsPosition)
{
	TpSim s;
	tp_pose p = pose(0, 0, -20);
	tp_move m = s.feed(20);
	m.motion_type = TP_MOTION_PROBING;
	ASSERT_EQ(tp_add_line(s.tp, &p, &m), 0);
	s.line(5, 5, 5, 20);	// must be flushed by the trip
	int k = 0;
	for (; k < 400; k++)
		EXPECT_TRUE(s.cycle().probing);
	double z_trip = s.pos()[2];
	s.in.probe_input = 1;
	const tp_outputs &o = s.cycle();
	EXPECT_TRUE(o.probe_tripped);
	EXPECT_DOUBLE_EQ(o.probed_pos.z, z_trip);
	s.in.probe_input = 0;
	s.run();
	EXPECT_TRUE(s.outs.back().done);
	EXPECT_LT(s.pos()[2], z_trip);	// decelerated beyond the trip point
	EXPECT_GT(s.pos()[2], z_trip - 20 * 20 / (2 * s.amax) - 20 * s.dt);
	EXPECT_DOUBLE_EQ(s.pos()[0], 0);	// the following move was flushed
	EXPECT_LE(s.worst_acc_ratio(), 1 + 1e-6);
}

TEST(TpProbe, ContactLossAndNoContact)
{
	TpSim s;
	tp_pose p = pose(0, 0, -1);
	tp_move m = s.feed(20);
	m.motion_type = TP_MOTION_PROBING;
	m.probe_type = TP_PROBE_LOSS;
	s.in.probe_input = 1;	// in contact: G38.4 trips when it goes to 0
	ASSERT_EQ(tp_add_line(s.tp, &p, &m), 0);
	s.run();
	bool no_contact = false;
	for (const tp_outputs &o : s.outs)
		no_contact |= o.probe_no_contact;
	EXPECT_TRUE(no_contact);
	EXPECT_DOUBLE_EQ(s.pos()[2], -1);
	ASSERT_EQ(tp_add_line(s.tp, &p, &m), 0);	// zero length: dropped
	p.z = 0;
	ASSERT_EQ(tp_add_line(s.tp, &p, &m), 0);
	for (int i = 0; i < 10; i++)
		s.cycle();
	s.in.probe_input = 0;
	EXPECT_TRUE(s.cycle().probe_tripped);
}

TEST(TpSyncIo, DoutAndAoutChangeAtSegmentStart)
{
	TpSim s;
	s.line(5, 0, 0, 50, 1);
	ASSERT_EQ(tp_set_dout(s.tp, 3, 1, 1), 0);
	ASSERT_EQ(tp_set_aout(s.tp, 2, 4.5, 4.5), 0);
	s.line(5, 5, 0, 50, 2);
	s.run();
	int at = -1;
	for (size_t k = 0; k < s.outs.size(); k++) {
		if (s.outs[k].dout_mask) {
			EXPECT_EQ(at, -1) << "emitted once";
			at = (int)k;
			EXPECT_EQ(s.outs[k].dout_mask, 1ull << 3);
			EXPECT_EQ(s.outs[k].dout_value, 1ull << 3);
			ASSERT_EQ(s.outs[k].aout_count, 1);
			EXPECT_EQ(s.outs[k].aout[0].index, 2);
			EXPECT_DOUBLE_EQ(s.outs[k].aout[0].value, 4.5);
			EXPECT_EQ(s.outs[k].exec_id, 2);
		}
	}
	ASSERT_GT(at, 0);
	// the cycle before was still on the first segment, at its end
	EXPECT_DOUBLE_EQ(s.trace[at][0], 5);	// trace[at] = position after cycle at-1
	EXPECT_DOUBLE_EQ(s.trace[at][1], 0);
	EXPECT_GT(s.trace[at + 1][1], 0);	// and the second segment moves in the same cycle
}

// SET_DOUT/SET_AOUT with an end value that differs: the start value when the segment
// starts moving, the end value in the period it reaches its end (a next segment's
// start values in that period would come after); an unchanged end is not emitted.
TEST(TpSyncIo, EndValuesAtSegmentEnd)
{
	TpSim s;
	s.line(5, 0, 0, 50, 1);
	ASSERT_EQ(tp_set_dout(s.tp, 1, 1, 0), 0);	// on for the segment, off after it
	ASSERT_EQ(tp_set_dout(s.tp, 2, 1, 1), 0);	// on, nothing at the end
	ASSERT_EQ(tp_set_aout(s.tp, 0, 2.5, -1.0), 0);
	s.line(5, 5, 0, 50, 2);
	s.line(0, 5, 0, 50, 3);
	s.run();
	int start = -1, end = -1;
	for (size_t k = 0; k < s.outs.size(); k++) {
		const tp_outputs& o = s.outs[k];
		if (!o.dout_mask)
			continue;
		if (start < 0) {
			start = (int)k;
			EXPECT_EQ(o.dout_mask, (1ull << 1) | (1ull << 2));
			EXPECT_EQ(o.dout_value, (1ull << 1) | (1ull << 2));
			ASSERT_EQ(o.aout_count, 1);
			EXPECT_DOUBLE_EQ(o.aout[0].value, 2.5);
			EXPECT_EQ(o.exec_id, 2);
		} else {
			EXPECT_EQ(end, -1) << "the end values are emitted once";
			end = (int)k;
			EXPECT_EQ(o.dout_mask, 1ull << 1);
			EXPECT_EQ(o.dout_value, 0u);
			ASSERT_EQ(o.aout_count, 1);
			EXPECT_EQ(o.aout[0].index, 0);
			EXPECT_DOUBLE_EQ(o.aout[0].value, -1.0);
		}
	}
	ASSERT_GT(start, 0);
	ASSERT_GT(end, start);
	EXPECT_LT(s.trace[end][1], 5);		// still moving before that period
	EXPECT_DOUBLE_EQ(s.trace[end + 1][0], 5);	// which ends at its end, (5, 5)
	EXPECT_DOUBLE_EQ(s.trace[end + 1][1], 5);
}
