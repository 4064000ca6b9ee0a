// Homing to an index pulse: switch + index (encoder zeroing or not), index only,
// absolute encoders, locking indexer.
#include <gtest/gtest.h>
#include "homing_sim.hpp"

using namespace homing_test;
using V = std::vector<int>;

TEST(HomingIndex, SwitchThenIndexEncoderResets)
{
	Sim sim(1);
	sim.place(0, 0);
	sim.sj(0).sw_lo = 50;
	sim.sj(0).sw_hi = 1e9;
	sim.sj(0).index_pos = 50.3;
	params(0, 1.5, 4, 5, 1, HOME_USE_INDEX);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{6, 7, 9, 10, 11, 12, 18, 20, 21, 0}));
	EXPECT_TRUE(sim.sj(0).index_enable_seen);
	EXPECT_FALSE(get_index_enable(0));
	EXPECT_TRUE(get_homed(0));
	// HOME_OFFSET 1.5 is the index: HOME 4 is 2.5 past it
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 4);
	EXPECT_NEAR(sim.sj(0).phys, 50.3 + 2.5, 1e-9);
	EXPECT_DOUBLE_EQ(sim.hj(0).motor_offset, -1.5);	// the encoder reads 0 at the index
	EXPECT_NEAR(sim.hj(0).pos_fb, 4, 1e-9);
}

TEST(HomingIndex, OppositeLatchThenIndex)
{
	Sim sim(1);
	sim.place(0, 0);
	sim.sj(0).sw_lo = 50;
	sim.sj(0).sw_hi = 1e9;
	sim.sj(0).index_pos = 49.6;	// met leaving the switch (moving negative)
	params(0, 0, -3, 5, -1, HOME_USE_INDEX);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{6, 7, 13, 14, 18, 20, 21, 0}));
	EXPECT_NEAR(sim.sj(0).phys, 49.6 - 3, 1e-9);
}

TEST(HomingIndex, IndexWithoutEncoderReset)
{
	Sim sim(1);
	sim.place(0, 0);
	sim.sj(0).sw_lo = 50;
	sim.sj(0).sw_hi = 1e9;
	sim.sj(0).index_pos = 50.3;
	sim.sj(0).encoder_resets = false;
	params(0, 1.5, 4, 5, 1, HOME_USE_INDEX | HOME_INDEX_NO_ENCODER_RESET);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_TRUE(get_homed(0));
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 4);
	// the index is seen in the period the encoder clears index-enable: within one
	// latch-velocity step (1 u/s x 1 ms)
	EXPECT_NEAR(sim.sj(0).phys, 50.3 + 2.5, 0.0015);
}

TEST(HomingIndex, IndexOnly)
{
	Sim sim(1);
	sim.place(0, 5);
	sim.sj(0).index_pos = 7;
	params(0, 10, 12, 0, 1, HOME_USE_INDEX);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{16, 18, 20, 21, 0}));
	EXPECT_TRUE(get_homed(0));
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 12);
	EXPECT_NEAR(sim.sj(0).phys, 7 + 2, 1e-9);
}

TEST(HomingIndex, IndexNeverComesEndsTheMove)
{
	Sim sim(1);
	sim.place(0, 5);
	sim.hj(0).min_limit = 0;
	sim.hj(0).max_limit = 1;
	params(0, 10, 12, 0, 1, HOME_USE_INDEX);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	ASSERT_EQ(Sim::errors.size(), 1u);
	EXPECT_EQ(Sim::errors[0], "j0 end of move in home state 18");
	EXPECT_FALSE(get_index_enable(0));	// dropped by the abort
	EXPECT_FALSE(get_homed(0));
}

TEST(HomingAbsolute, Type1AddsHomeOffsetThenFinalMove)
{
	Sim sim(1);
	sim.place(0, 3);	// the absolute encoder reads 3
	params(0, 5, 10, 0, 0, HOME_ABSOLUTE_ENCODER | HOME_NO_REHOME);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{20, 21, 0}));
	EXPECT_TRUE(get_homed(0));
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 10);
	EXPECT_NEAR(sim.sj(0).phys, 5, 1e-9);	// reading 3 became 8; 10 is 2 further
	// NO_REHOME: a homed joint is not homed again
	EXPECT_EQ(do_home_joint(0), 1);
	EXPECT_FALSE(get_homing_is_active());
}

TEST(HomingAbsolute, Type2NoFinalMove)
{
	Sim sim(1);
	sim.place(0, 3);
	params(0, 5, 10, 0, 0, HOME_ABSOLUTE_ENCODER | HOME_NO_REHOME | HOME_NO_FINAL_MOVE);
	ASSERT_EQ(do_home_joint(0), 0);
	sim.step();
	EXPECT_TRUE(get_homed(0));	// in the first period
	EXPECT_FALSE(get_homing(0));
	sim.run_until_idle();
	EXPECT_EQ(sim.sj(0).states, (V{0}));
	EXPECT_DOUBLE_EQ(sim.hj(0).pos_cmd, 8);
	EXPECT_NEAR(sim.sj(0).phys, 3, 1e-12);	// nothing moved
	EXPECT_DOUBLE_EQ(sim.hj(0).motor_offset, -5);
	EXPECT_EQ(sim.allhomed_events, 1);
}

TEST(HomingAbsolute, Type0IsOrdinaryHoming)
{
	Sim sim(1);
	sim.place(0, 3);
	params(0, 5, 10, 0, 0, 0);	// immediate: reading := HOME_OFFSET
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_NEAR(sim.sj(0).phys, 3 + 5, 1e-9);
	EXPECT_EQ(do_home_joint(0), 0);	// may home again
}

TEST(HomingLockingIndexer, UnlocksBeforeAndLocksAfter)
{
	Sim sim(1, 0, 1);
	sim.place(0, 3);
	sim.sj(0).unlock_delay = 20;
	params(0, 1, 2, 0, 0, HOME_UNLOCK_FIRST);
	EXPECT_TRUE(get_home_needs_unlock_first(0));
	ASSERT_EQ(do_home_joint(0), 0);
	sim.run_until_idle();
	EXPECT_TRUE(Sim::errors.empty());
	EXPECT_EQ(sim.sj(0).states, (V{3, 20, 21, 23, 0}));
	EXPECT_TRUE(get_homed(0));
	EXPECT_FALSE(homing_g.h[0].unlock);
	EXPECT_FALSE(homing_g.h[0].is_unlocked);
	EXPECT_NEAR(sim.sj(0).phys, 4, 1e-9);
}
