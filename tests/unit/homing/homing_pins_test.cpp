// homing_pins_test.cpp - homing_init() in a real HAL (this process is the realtime
// host): the pins of homing.h with their EMC2 aliases, the unlock pins only for joints
// in unlock_joints_mask, and the per-period copies to and from the pins.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

extern "C" {
#include "hal.h"
#include "homing_priv.h"
}

namespace {

struct Peer {			// the test's side of the wires, in hal_malloc() memory
	hal_bit_t *sw, *idx_out, *homing, *homed, *unlock, *is_unlocked;
	hal_s32_t *state;
};

class HomingPins : public ::testing::Test {
protected:
	void SetUp() override
	{
		motmod_ = hal_init("motmodtest");
		ASSERT_GT(motmod_, 0);
		peer_comp_ = hal_init("peer");
		ASSERT_GT(peer_comp_, 0);
		p_ = static_cast<Peer *>(hal_malloc(sizeof(Peer)));
		ASSERT_NE(p_, nullptr);
	}
	void TearDown() override
	{
		for (const auto &s : sigs_)
			hal_signal_delete(s.c_str());
		hal_exit(peer_comp_);
		hal_exit(motmod_);
	}
	// wire pin (by any of its names) to a new signal, return 0 or -errno
	int wire(const std::string &pin, const std::string &sig, hal_type_t t = HAL_BIT)
	{
		if (hal_signal_new(sig.c_str(), t) == 0)
			sigs_.push_back(sig);
		return hal_link(pin.c_str(), sig.c_str());
	}
	int motmod_ = 0, peer_comp_ = 0;
	Peer *p_ = nullptr;
	std::vector<std::string> sigs_;
	struct homing_joint joints_[3] = {};
};

TEST_F(HomingPins, PinsAliasesAndCopies)
{
	ASSERT_EQ(homing_init(motmod_, 3, 0, 0x4, joints_, nullptr), 0);
	ASSERT_EQ(hal_pin_bit_newf(HAL_OUT, &p_->sw, peer_comp_, "peer.sw"), 0);
	ASSERT_EQ(hal_pin_bit_newf(HAL_IN, &p_->homing, peer_comp_, "peer.homing"), 0);
	ASSERT_EQ(hal_pin_bit_newf(HAL_IN, &p_->homed, peer_comp_, "peer.homed"), 0);
	ASSERT_EQ(hal_pin_bit_newf(HAL_IO, &p_->idx_out, peer_comp_, "peer.index"), 0);
	ASSERT_EQ(hal_pin_bit_newf(HAL_IN, &p_->unlock, peer_comp_, "peer.unlock"), 0);
	ASSERT_EQ(hal_pin_bit_newf(HAL_OUT, &p_->is_unlocked, peer_comp_, "peer.is-unlocked"), 0);
	ASSERT_EQ(hal_pin_s32_newf(HAL_IN, &p_->state, peer_comp_, "peer.state"), 0);

	// EMC2 names reach the same pins
	ASSERT_EQ(wire("axis.1.home-sw-in", "sw"), 0);
	ASSERT_EQ(hal_link("peer.sw", "sw"), 0);
	ASSERT_EQ(wire("joint.1.homing", "homing"), 0);
	ASSERT_EQ(hal_link("peer.homing", "homing"), 0);
	ASSERT_EQ(wire("axis.1.homed", "homed"), 0);
	ASSERT_EQ(hal_link("peer.homed", "homed"), 0);
	ASSERT_EQ(wire("axis.1.index-enable", "idx"), 0);
	ASSERT_EQ(hal_link("peer.index", "idx"), 0);
	ASSERT_EQ(wire("axis.1.home-state", "state", HAL_S32), 0);
	ASSERT_EQ(hal_link("peer.state", "state"), 0);
	ASSERT_EQ(wire("joint.2.unlock", "unlock"), 0);
	ASSERT_EQ(hal_link("peer.unlock", "unlock"), 0);
	ASSERT_EQ(wire("axis.2.is-unlocked", "isun"), 0);
	ASSERT_EQ(hal_link("peer.is-unlocked", "isun"), 0);
	// every joint has the homing pins; only joint 2 (mask 0x4) the unlock pins
	for (const char *n : {"joint.0.home-sw-in", "joint.0.index-enable", "joint.0.homing",
			      "joint.0.homed", "axis.0.home-state", "joint.2.home-state"})
		EXPECT_EQ(wire(n, std::string("s-") + n, strstr(n, "state") ? HAL_S32 : HAL_BIT), 0) << n;
	EXPECT_NE(wire("joint.0.unlock", "u0"), 0);
	EXPECT_NE(wire("axis.1.is-unlocked", "u1"), 0);

	*p_->sw = true;
	*p_->is_unlocked = true;
	read_homing_in_pins();
	EXPECT_TRUE(homing_g.h[1].home_sw);
	EXPECT_FALSE(homing_g.h[0].home_sw);
	EXPECT_TRUE(homing_g.h[2].is_unlocked);

	homing_g.h[1].homing = true;
	homing_g.h[1].index_enable = true;
	homing_g.h[1].state = HOME_INDEX_SEARCH_WAIT;
	homing_g.h[2].unlock = true;
	write_homing_out_pins();
	EXPECT_TRUE(*p_->homing);
	EXPECT_FALSE(*p_->homed);
	EXPECT_TRUE(*p_->idx_out);
	EXPECT_EQ(*p_->state, HOME_INDEX_SEARCH_WAIT);
	EXPECT_TRUE(*p_->unlock);
	// the encoder clears index-enable: homing reads it back
	*p_->idx_out = false;
	read_homing_in_pins();
	EXPECT_FALSE(get_index_enable(1));
}

TEST_F(HomingPins, BadArgumentsCreateNothing)
{
	EXPECT_EQ(homing_init(motmod_, 0, 0, 0, joints_, nullptr), -EINVAL);
	EXPECT_EQ(homing_init(motmod_, 3, 4, 0, joints_, nullptr), -EINVAL);
	EXPECT_NE(wire("joint.0.homed", "x"), 0);
	read_homing_in_pins();	// no pins: nothing happens
	write_homing_out_pins();
}

TEST_F(HomingPins, SecondInitFailsOnTheNameClash)
{
	ASSERT_EQ(homing_init(motmod_, 1, 0, 0, joints_, nullptr), 0);
	EXPECT_NE(homing_init(peer_comp_, 1, 0, 0, joints_, nullptr), 0);
}

}  // namespace

int main(int argc, char **argv)
{
	::testing::InitGoogleTest(&argc, argv);
	std::string inst = "unit-homing-" + std::to_string(getpid());
	setenv("RTAPI_INSTANCE", inst.c_str(), 1);
	return RUN_ALL_TESTS();
}
