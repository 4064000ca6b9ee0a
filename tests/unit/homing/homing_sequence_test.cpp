// Home-All and home sequences: order, gaps, skipped joints, synchronized (negative)
// groups, shared switches.
#include <gtest/gtest.h>
#include "homing_sim.hpp"

using namespace homing_test;
using V = std::vector<int>;

namespace {

// n joints, joint j at 0 with a switch from 10 + j upward.
void switches(Sim &sim, int n)
{
	for (int j = 0; j < n; j++) {
		sim.place(j, 0);
		sim.sj(j).sw_lo = 10 + j;
		sim.sj(j).sw_hi = 1e9;
	}
}

}  // namespace

TEST(HomingSequence, HomeAllRunsSequencesInOrder)
{
	Sim sim(3);
	switches(sim, 3);
	params(0, 0, 1, 5, 1, 0, 2);
	params(1, 0, 1, 5, 1, 0, 1);
	params(2, 0, 1, 5, 1, 0, 1);
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	for (int j = 0; j < 3; j++) {
		EXPECT_TRUE(get_homed(j)) << j;
		EXPECT_NEAR(sim.sj(j).phys, 10 + j + 1, 0.002) << j;
	}
	// sequence 0 is empty (skipped), 1 = joints 1 and 2 together, then 2 = joint 0
	EXPECT_LT(sim.sj(1).finished_at, sim.sj(0).first_final_wait);
	EXPECT_GT(sim.sj(0).first_final_wait, sim.sj(2).finished_at);
	EXPECT_EQ(sim.allhomed_events, 1);
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingSequence, JointsOfOneSequenceStartTogether)
{
	Sim sim(2);
	switches(sim, 2);
	params(0, 0, 1, 5, 1, 0, 0);
	params(1, 0, 1, 5, 1, 0, 0);
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.step();
	EXPECT_EQ(get_home_state(0), HOME_INITIAL_SEARCH_START);
	EXPECT_EQ(get_home_state(1), HOME_INITIAL_SEARCH_START);
	sim.run_until_idle();
	EXPECT_TRUE(get_allhomed());
}

TEST(HomingSequence, GapEndsHomeAll)
{
	Sim sim(2);
	switches(sim, 2);
	params(0, 0, 1, 5, 1, 0, 0);
	params(1, 0, 1, 5, 1, 0, 2);	// no sequence 1
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(0));
	EXPECT_FALSE(get_homed(1));
	EXPECT_EQ(sim.sj(1).states, (V{0}));
	EXPECT_FALSE(get_homing_is_active());
	EXPECT_EQ(sim.allhomed_events, 0);
}

TEST(HomingSequence, JointWithoutSequenceIsNotInHomeAll)
{
	Sim sim(2);
	switches(sim, 2);
	params(0, 0, 1, 5, 1, 0, 1);
	params(1, 0, 1, 5, 1);		// HOME_SEQUENCE_NONE (999)
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(0));
	EXPECT_FALSE(get_homed(1));
	EXPECT_FALSE(get_allhomed());
	// ...but it homes by itself
	ASSERT_EQ(do_home_joint(1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(1));
	EXPECT_EQ(sim.allhomed_events, 1);
}

TEST(HomingSequence, InactiveJointsDoNotHomeAndDoNotCount)
{
	Sim sim(2);
	switches(sim, 2);
	sim.hj(1).active = false;
	params(0, 0, 1, 5, 1, 0, 0);
	params(1, 0, 1, 5, 1, 0, 0);
	EXPECT_EQ(do_home_joint(1), -EINVAL);
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(0));
	EXPECT_FALSE(get_homed(1));
	EXPECT_TRUE(get_allhomed());
}

TEST(HomingSequence, NoRehomeJointsAreSkippedByHomeAll)
{
	Sim sim(2);
	switches(sim, 2);
	sim.place(1, 3);
	params(0, 0, 1, 5, 1, 0, 0);
	params(1, 5, 10, 0, 0, HOME_ABSOLUTE_ENCODER | HOME_NO_REHOME | HOME_NO_FINAL_MOVE, 1);
	ASSERT_EQ(do_home_joint(1), 0);
	sim.step();
	ASSERT_TRUE(get_homed(1));
	double pos1 = sim.hj(1).pos_cmd;
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(0));
	EXPECT_TRUE(get_homed(1));
	EXPECT_DOUBLE_EQ(sim.hj(1).pos_cmd, pos1);	// not offset a second time
}

TEST(HomingSequence, SynchronizedGroupStartsFinalMoveTogether)
{
	Sim sim(3);
	switches(sim, 3);
	sim.sj(1).sw_lo = 30;	// joint 1 reaches its switch much later
	params(0, 0, 1, 5, 1, 0, -1);
	params(1, 0, 1, 5, 1, 0, 1);	// mixed signs: normalised to negative
	params(2, 0, 1, 5, 1, 0, 0);
	EXPECT_TRUE(get_home_is_synchronized(0));
	EXPECT_TRUE(get_home_is_synchronized(1));
	EXPECT_FALSE(get_home_is_synchronized(2));
	EXPECT_EQ(get_home_sequence(1), -1);
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_TRUE(get_allhomed());
	EXPECT_EQ(sim.sj(0).first_final_wait, sim.sj(1).first_final_wait);
	EXPECT_GT(sim.sj(0).first_final_wait, sim.sj(2).finished_at);
	EXPECT_NEAR(sim.sj(0).phys, 11, 0.002);
	EXPECT_NEAR(sim.sj(1).phys, 31, 0.002);
	// joint 0 waited at FINAL_MOVE_START
	EXPECT_EQ(sim.sj(0).states, (V{0, 6, 7, 9, 10, 11, 12, 20, 21, 0}));
}

TEST(HomingSequence, HomingOneJointOfASynchronizedGroupHomesTheGroup)
{
	Sim sim(3);
	switches(sim, 3);
	params(0, 0, 1, 5, 1, 0, -2);
	params(1, 0, 1, 5, 1, 0, -2);
	params(2, 0, 1, 5, 1, 0, 1);
	ASSERT_EQ(do_home_joint(1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(0));
	EXPECT_TRUE(get_homed(1));
	EXPECT_FALSE(get_homed(2));
	EXPECT_EQ(sim.sj(0).first_final_wait, sim.sj(1).first_final_wait);
}

TEST(HomingSequence, AbortOfASynchronizedJointAbortsItsGroup)
{
	Sim sim(2);
	switches(sim, 2);
	sim.sj(1).pos_lim = 5;		// joint 1 hits a limit before its switch
	params(0, 0, 1, 5, 1, 0, -1);
	params(1, 0, 1, 5, 1, 0, -1);
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "j1 hit limit in home state 7");
	EXPECT_FALSE(get_homed(0));
	EXPECT_FALSE(get_homed(1));
	EXPECT_LT(sim.sj(0).phys, 10);	// stopped before its switch
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingSequence, FailedJointStopsHomeAll)
{
	Sim sim(2);
	switches(sim, 2);
	sim.sj(0).pos_lim = 5;
	params(0, 0, 1, 5, 1, 0, 0);
	params(1, 0, 1, 5, 1, 0, 1);
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_FALSE(get_homed(0));
	EXPECT_EQ(sim.sj(1).states, (V{0}));
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingShared, SharedSwitchHomesOneAfterTheOther)
{
	// Two joints share one switch input (wired OR); each releases it before the next
	// starts, so HOME_IS_SHARED passes.
	Sim sim(2);
	switches(sim, 2);
	sim.sj(1).shared_with_prev = true;
	sim.sj(1).sw_lo = 20;
	params(0, 0, -5, 5, 1, HOME_IS_SHARED, 0);
	params(1, 0, -5, 5, 1, HOME_IS_SHARED, 1);
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty()) << Sim::errors[0];
	EXPECT_TRUE(get_allhomed());
	EXPECT_NEAR(sim.sj(0).phys, 5, 0.002);
	EXPECT_NEAR(sim.sj(1).phys, 15, 0.002);
}

TEST(HomingShared, SharedSwitchClosedRefusesToStart)
{
	Sim sim(2);
	switches(sim, 2);
	sim.sj(1).shared_with_prev = true;
	sim.place(0, 12);	// joint 0 holds the shared switch closed
	params(1, 0, 1, 5, 1, HOME_IS_SHARED);
	ASSERT_EQ(do_home_joint(1), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "Cannot home while shared home switch is closed");
	EXPECT_FALSE(get_homed(1));
	EXPECT_FALSE(get_homing(1));
	EXPECT_EQ(sim.sj(1).states, (V{0}));
	EXPECT_NEAR(sim.sj(1).phys, 0, 1e-12);
}
