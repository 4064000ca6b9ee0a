// Commands around homing: cancel, unhome (all, one, volatile, extra joints), refusals,
// the probe trip, parameter updates, bad joint numbers, setup errors.
#include <gtest/gtest.h>
#include "homing_sim.hpp"

using namespace homing_test;
using V = std::vector<int>;

namespace {

void switch_joint(Sim &sim, int j)
{
	sim.place(j, 0);
	sim.sj(j).sw_lo = 50;
	sim.sj(j).sw_hi = 1e9;
	params(j, 52, 10, 5, 1, HOME_USE_INDEX, j);
	sim.sj(j).index_pos = 50.3;
}

}  // namespace

TEST(HomingCommand, CancelMidSearch)
{
	Sim sim(1);
	switch_joint(sim, 0);
	ASSERT_EQ(do_home_joint(0), 0);
	while (get_home_state(0) != HOME_INITIAL_SEARCH_WAIT)
		sim.step();
	for (int i = 0; i < 100; i++)
		sim.step();
	do_cancel_homing(0);
	EXPECT_EQ(get_home_state(0), HOME_IDLE);
	EXPECT_FALSE(get_homing(0));
	EXPECT_FALSE(get_homed(0));
	EXPECT_FALSE(get_homing_is_active());
	EXPECT_FALSE(sim.hj(0).free_tp_enable);
	sim.run_until_idle();
	EXPECT_LT(sim.sj(0).phys, 50);	// stopped before the switch
	EXPECT_TRUE(Sim::errors.empty());
}

TEST(HomingCommand, CancelDuringIndexSearchDropsIndexEnable)
{
	Sim sim(1);
	switch_joint(sim, 0);
	sim.sj(0).index_pos = 60;
	ASSERT_EQ(do_home_joint(0), 0);
	while (get_home_state(0) != HOME_INDEX_SEARCH_WAIT)
		sim.step();
	sim.step();
	EXPECT_TRUE(get_index_enable(0));
	EXPECT_TRUE(get_homing_at_index_search_wait(0));
	do_cancel_homing(-1);
	EXPECT_FALSE(get_index_enable(0));
	EXPECT_FALSE(get_homing_at_index_search_wait(0));
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingCommand, CancelAllStopsHomeAll)
{
	Sim sim(2);
	switch_joint(sim, 0);
	switch_joint(sim, 1);
	ASSERT_EQ(do_home_joint(-1), 0);
	for (int i = 0; i < 500; i++)
		sim.step();
	do_cancel_homing(-1);
	sim.run_until_idle();
	EXPECT_FALSE(get_homed(0));
	EXPECT_FALSE(get_homed(1));
	EXPECT_EQ(sim.sj(1).states, (V{0}));	// sequence 1 never started
}

TEST(HomingCommand, RefusedWhileHoming)
{
	Sim sim(2);
	switch_joint(sim, 0);
	switch_joint(sim, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.step();
	EXPECT_EQ(do_home_joint(0), -EBUSY);
	EXPECT_EQ(do_home_joint(-1), -EBUSY);	// a participating joint is mid-homing
	EXPECT_EQ(set_unhomed(1, HOMING_MOTION_FREE), -EBUSY);
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "Cannot unhome while homing, joint 1");
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(0));
}

TEST(HomingCommand, BadJointNumbers)
{
	Sim sim(2);
	EXPECT_EQ(do_home_joint(2), -EINVAL);
	EXPECT_EQ(do_home_joint(-2), -EINVAL);
	EXPECT_EQ(set_unhomed(2, HOMING_MOTION_FREE), -EINVAL);
	EXPECT_EQ(set_unhomed(-3, HOMING_MOTION_FREE), -EINVAL);
	EXPECT_FALSE(get_homed(5));
	EXPECT_FALSE(get_homing(-1));
	EXPECT_EQ(get_home_sequence(9), HOME_SEQUENCE_NONE);
	EXPECT_EQ(get_home_sequence(0), HOME_SEQUENCE_NONE);
	do_cancel_homing(7);	// ignored
	set_joint_homing_params(3, 0, 0, 0, 0, 0, 0, 0, false);	// ignored
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingCommand, HomeAllWithNothingToHome)
{
	Sim sim(1);
	EXPECT_EQ(do_home_joint(-1), 1);	// joint 0 has no HOME_SEQUENCE
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingCommand, UnhomeOneAllAndVolatile)
{
	Sim sim(3);
	for (int j = 0; j < 3; j++) {
		sim.place(j, j);
		params(j, 0, 0, 0, 0, 0, 0, -1, j == 1);
	}
	EXPECT_TRUE(get_home_is_volatile(1));
	EXPECT_FALSE(get_home_is_volatile(0));
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	ASSERT_TRUE(get_allhomed());
	// machine off: task sends UNHOME -2 with motion disabled
	EXPECT_EQ(set_unhomed(-2, HOMING_MOTION_DISABLED), 0);
	EXPECT_TRUE(get_homed(0));
	EXPECT_FALSE(get_homed(1));
	EXPECT_TRUE(get_homed(2));
	EXPECT_EQ(do_unhome_joint(2), 0);
	EXPECT_FALSE(get_homed(2));
	EXPECT_EQ(do_unhome_joint(-1), 0);
	EXPECT_FALSE(get_homed(0));
	EXPECT_TRUE(Sim::errors.empty());
}

TEST(HomingCommand, UnhomeRefusedWhileMoving)
{
	Sim sim(1);
	sim.place(0, 0);
	params(0, 0, 0, 0, 0);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_TRUE(get_homed(0));
	sim.hj(0).free_tp_active = true;	// a jog
	EXPECT_EQ(do_unhome_joint(0), -EBUSY);
	EXPECT_EQ(do_unhome_joint(-1), -EBUSY);
	EXPECT_EQ(Sim::errors.back(), "Cannot unhome while moving, joint 0");
	EXPECT_TRUE(get_homed(0));
	// disabled: nothing moves, the stale flag does not matter
	EXPECT_EQ(set_unhomed(-1, HOMING_MOTION_DISABLED), 0);
	EXPECT_FALSE(get_homed(0));
}

TEST(HomingCommand, ExtraJointsUnhomeOnlyWhenDisabled)
{
	Sim sim(2, 1);
	for (int j = 0; j < 2; j++) {
		sim.place(j, 0);
		params(j, 0, 0, 0, 0, 0, 0);
	}
	ASSERT_EQ(do_home_joint(-1), 0);
	sim.run_until_idle();
	ASSERT_TRUE(get_allhomed());
	EXPECT_EQ(set_unhomed(1, HOMING_MOTION_FREE), -EBUSY);
	EXPECT_EQ(Sim::errors.back(), "Cannot unhome extra joint 1 unless motion is disabled");
	EXPECT_EQ(set_unhomed(-1, HOMING_MOTION_FREE), 0);
	EXPECT_FALSE(get_homed(0));
	EXPECT_TRUE(get_homed(1));	// skipped
	EXPECT_EQ(set_unhomed(1, HOMING_MOTION_DISABLED), 0);
	EXPECT_FALSE(get_homed(1));
}

TEST(HomingCommand, ProbeTripCancelsHoming)
{
	Sim sim(1);
	switch_joint(sim, 0);
	EXPECT_FALSE(homing_probe_trip(false));	// not homing: nothing
	ASSERT_EQ(do_home_joint(0), 0);
	for (int i = 0; i < 300; i++)
		sim.step();
	EXPECT_FALSE(homing_probe_trip(true));	// NO_PROBE_HOME_ERROR: the probe may be the switch
	EXPECT_TRUE(get_homing(0));
	EXPECT_TRUE(homing_probe_trip(false));
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "Probe tripped during homing motion.");
	EXPECT_FALSE(get_homing_is_active());
	EXPECT_FALSE(get_homed(0));
}

TEST(HomingCommand, NotInFreeStateNothingHappens)
{
	Sim sim(1);
	switch_joint(sim, 0);
	sim.free_state = false;	// motmod calls do_homing only in FREE
	ASSERT_EQ(do_home_joint(0), 0);
	for (int i = 0; i < 1000; i++)
		sim.step();
	EXPECT_EQ(get_home_state(0), HOME_START);
	EXPECT_NEAR(sim.sj(0).phys, 0, 1e-12);
	do_cancel_homing(-1);	// what motmod does on disable
	EXPECT_EQ(get_home_state(0), HOME_IDLE);
}

TEST(HomingCommand, ParamsIgnoredWhileHomingAndUpdatedWhenIdle)
{
	Sim sim(1);
	switch_joint(sim, 0);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.step();
	update_joint_homing_params(0, 0, 99, 3);	// ignored: homing
	EXPECT_EQ(get_home_sequence(0), 0);
	sim.run_until_idle();
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 10);
	update_joint_homing_params(0, 52, 20, 3);	// ini.0.home = 20
	EXPECT_EQ(get_home_sequence(0), 3);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 20);
	EXPECT_NEAR(sim.sj(0).phys, 50.3 + 20 - 52, 1e-9);
}

TEST(HomingCommand, SequenceSignRevertsWhenTheNegativeMemberChanges)
{
	Sim sim(2);
	params(0, 0, 0, 0, 0, 0, -1);
	params(1, 0, 0, 0, 0, 0, 1);
	EXPECT_EQ(get_home_sequence(1), -1);
	params(0, 0, 0, 0, 0, 0, 1);
	EXPECT_EQ(get_home_sequence(1), 1);
	EXPECT_FALSE(get_home_is_synchronized(0));
}

TEST(HomingSetup, RejectsBadArguments)
{
	struct homing_joint j[2] = {};
	EXPECT_EQ(homing_setup(0, 0, 0, j, nullptr), -EINVAL);
	EXPECT_EQ(homing_setup(HOMING_MAX_JOINTS + 1, 0, 0, j, nullptr), -EINVAL);
	EXPECT_EQ(homing_setup(2, 3, 0, j, nullptr), -EINVAL);
	EXPECT_EQ(homing_setup(2, -1, 0, j, nullptr), -EINVAL);
	EXPECT_EQ(homing_setup(2, 0, 0, nullptr, nullptr), -EINVAL);
	EXPECT_EQ(homing_setup(2, 0, 0, j, nullptr), 0);
}

TEST(HomingCommand, DeactivatedWhileHomingAborts)
{
	Sim sim(1);
	switch_joint(sim, 0);
	ASSERT_EQ(do_home_joint(0), 0);
	for (int i = 0; i < 300; i++)
		sim.step();
	ASSERT_TRUE(get_homing(0));
	sim.hj(0).active = false;
	sim.step();
	EXPECT_FALSE(get_homing(0));
	EXPECT_FALSE(get_homing_is_active());
	EXPECT_FALSE(sim.hj(0).free_tp_enable);
}
