// Homing to a switch: search/latch sign combinations, switch already closed at start,
// final velocity, velocity clamp, limit and end-of-move aborts, the config errors.
#include <gtest/gtest.h>
#include "homing_sim.hpp"

using namespace homing_test;
using V = std::vector<int>;

namespace {

// Joint 0 at physical 0, switch closed from 50 upward.
Sim &switch_machine(Sim &sim)
{
	sim.place(0, 0);
	sim.sj(0).sw_lo = 50;
	sim.sj(0).sw_hi = 1e9;
	return sim;
}

}  // namespace

TEST(HomingSwitch, SameSignLatchBacksOffAndLatchesRisingEdge)
{
	Sim sim(1);
	switch_machine(sim);
	params(0, 52, 10, 5, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	EXPECT_TRUE(get_homing_is_active());
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty()) << Sim::errors[0];
	EXPECT_EQ(sim.sj(0).states, (V{6, 7, 9, 10, 11, 12, 20, 21, 0}));
	EXPECT_TRUE(get_homed(0));
	EXPECT_FALSE(get_homing(0));
	EXPECT_TRUE(get_allhomed());
	EXPECT_EQ(sim.allhomed_events, 1);
	// HOME_OFFSET 52 is the rising edge at 50; HOME 10 is then physical 8
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 10);
	EXPECT_NEAR(sim.sj(0).phys, 50 + 10 - 52, 0.002);
	EXPECT_NEAR(sim.hj(0).motor_offset, -2, 0.002);
	EXPECT_NEAR(sim.hj(0).pos_fb, 10, 1e-9);
	// the final move ran at MAX_VELOCITY (HOME_FINAL_VEL -1)
	EXPECT_NEAR(sim.sj(0).max_speed_final, 10, 1e-6);
}

TEST(HomingSwitch, OppositeSignLatchLeavesTheSwitch)
{
	Sim sim(1);
	switch_machine(sim);
	params(0, 0, 3, 5, -1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{6, 7, 13, 14, 20, 21, 0}));
	EXPECT_TRUE(get_homed(0));
	// falling edge while moving negative: the switch opens just below 50
	EXPECT_NEAR(sim.sj(0).phys, 50 + 3, 0.002);
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 3);
}

TEST(HomingSwitch, NegativeSearchDirection)
{
	Sim sim(1);
	sim.place(0, 20);
	sim.sj(0).sw_lo = -1e9;
	sim.sj(0).sw_hi = -5;	// closed at and below -5
	params(0, -1, 0, -4, -0.5);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{6, 7, 9, 10, 11, 12, 20, 21, 0}));
	EXPECT_NEAR(sim.sj(0).phys, -5 + 0 - (-1), 0.001);
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 0);
}

TEST(HomingSwitch, SwitchAlreadyClosedAtStartBacksOffFirst)
{
	Sim sim(1);
	switch_machine(sim);
	sim.place(0, 51);
	params(0, 52, 10, 5, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{4, 5, 6, 7, 9, 10, 11, 12, 20, 21, 0}));
	EXPECT_NEAR(sim.sj(0).phys, 8, 0.002);
	EXPECT_TRUE(get_homed(0));
}

TEST(HomingSwitch, FinalVelocityAndSearchVelocityClampedToMaxVelocity)
{
	Sim sim(1);
	switch_machine(sim);
	params(0, 52, 10, 50, 1, 0, HOME_SEQUENCE_NONE, 2.5);	// search 50 > MAX_VELOCITY 10
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(get_homed(0));
	EXPECT_DOUBLE_EQ(sim.sj(0).max_vel_lim, 10);
	EXPECT_NEAR(sim.sj(0).max_speed_final, 2.5, 1e-6);
	EXPECT_NEAR(sim.sj(0).phys, 8, 0.002);
}

TEST(HomingSwitch, FinalVelocityAboveMaxIsClamped)
{
	Sim sim(1);
	switch_machine(sim);
	params(0, 52, 10, 5, 1, 0, HOME_SEQUENCE_NONE, 40);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_NEAR(sim.sj(0).max_speed_final, 10, 1e-6);
}

TEST(HomingSwitch, LimitSwitchDuringSearchAborts)
{
	Sim sim(1);
	switch_machine(sim);
	sim.sj(0).pos_lim = 40;
	params(0, 52, 10, 5, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "j0 hit limit in home state 7");
	EXPECT_EQ(sim.sj(0).states, (V{6, 7, 0}));
	EXPECT_FALSE(get_homed(0));
	EXPECT_FALSE(get_homing(0));
	EXPECT_FALSE(sim.hj(0).free_tp_enable);
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingSwitch, IgnoreLimitsHomesOnASharedLimitSwitch)
{
	Sim sim(1);
	switch_machine(sim);
	sim.sj(0).pos_lim = 50;		// the limit switch is the home switch
	params(0, 52, 10, 5, 1, HOME_IGNORE_LIMITS);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_TRUE(get_homed(0));
	EXPECT_NEAR(sim.sj(0).phys, 8, 0.002);
}

TEST(HomingSwitch, MoveEndingWithoutSwitchAborts)
{
	Sim sim(1);
	sim.place(0, 0);	// no switch anywhere
	sim.hj(0).min_limit = 0;
	sim.hj(0).max_limit = 2;	// search move: pos_cmd + 2 * range = 4
	params(0, 0, 0, 5, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "j0 end of move in home state 7");
	EXPECT_NEAR(sim.sj(0).phys, 4, 1e-9);
	EXPECT_FALSE(get_homed(0));
}

TEST(HomingSwitch, NarrowSwitchInactiveBeforeBackoff)
{
	Sim sim(1);
	sim.place(0, 0);
	sim.sj(0).sw_lo = 50;
	sim.sj(0).sw_hi = 50.05;	// the search overshoots it (stopping distance 0.125)
	params(0, 0, 0, 5, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "Home switch inactive before start of backoff move");
	EXPECT_EQ(sim.sj(0).states, (V{6, 7, 9, 0}));
	EXPECT_FALSE(get_homed(0));
}

TEST(HomingSwitch, NarrowSwitchInactiveBeforeOppositeLatch)
{
	Sim sim(1);
	sim.place(0, 0);
	sim.sj(0).sw_lo = 50;
	sim.sj(0).sw_hi = 50.05;
	params(0, 0, 0, 5, -1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "Home switch inactive before start of latch move");
}

TEST(HomingSwitch, WideBackoffStillOnSwitchBeforeLatch)
{
	// The backoff stops as soon as the switch opens; a switch that closes again just
	// behind it (a second cam) is closed when the latch move would start.
	Sim sim(1);
	switch_machine(sim);
	params(0, 52, 10, 5, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.before_homing = [](Sim &) {
		if (get_home_state(0) == HOME_RISE_SEARCH_START)
			homing_g.h[0].home_sw = true;	// the second cam
	};
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "Home switch active before start of latch move");
	EXPECT_FALSE(get_homed(0));
}

TEST(HomingConfig, ImmediateHomeSetsHomeOffsetThenMovesToHome)
{
	Sim sim(1);
	sim.place(0, 3);
	params(0, 1, 2, 0, 0);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{20, 21, 0}));
	EXPECT_TRUE(get_homed(0));
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 2);
	EXPECT_NEAR(sim.sj(0).phys, 4, 1e-9);	// physical 3 became 1; 2 is one further
}

TEST(HomingConfig, LatchWithoutSearchOrIndexIsAnError)
{
	Sim sim(1);
	sim.place(0, 0);
	params(0, 0, 0, 0, 1);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0],
		  "invalid homing config: non-zero LATCH_VEL needs either SEARCH_VEL or USE_INDEX");
	EXPECT_FALSE(get_homed(0));
	EXPECT_FALSE(get_homing(0));
	EXPECT_EQ(get_home_state(0), HOME_IDLE);
}

TEST(HomingConfig, SearchWithoutLatchIsAnError)
{
	Sim sim(1);
	sim.place(0, 0);
	params(0, 0, 0, 5, 0);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "invalid homing config: non-zero SEARCH_VEL needs LATCH_VEL");
	EXPECT_FALSE(get_homed(0));
}

TEST(HomingConfig, HomeDelayIsATenthOfASecondAfterStopping)
{
	Sim sim(1);
	sim.place(0, 3);
	params(0, 1, 2, 0, 0);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	// FINAL_MOVE_START waits 100 ms = periods 0..99; the move starts in period 100
	EXPECT_EQ(sim.sj(0).first_final_wait, 100);
}
