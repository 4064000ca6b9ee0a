// homing_sim.hpp - a simulated machine for the homing state machine: per joint a free
// planner (motion.md 12), a servo that follows motor-pos-cmd exactly, an encoder
// (optionally zeroing at the index while index-enable is set), a home switch, an index
// pulse and limit switches, all at physical positions. Time is the step count.
#pragma once
#include <cmath>
#include <functional>
#include <string>
#include <vector>

extern "C" {
#include "homing_priv.h"
}

namespace homing_test {

struct FreePlanner {		// simple_tp, as motmod runs it in FREE state
	double curr_pos = 0, curr_vel = 0;
	bool active = false;
	void run(double target, double max_vel, double max_acc, bool enable, double dt);
};

struct SimJoint {
	// machine (physical positions)
	double phys = 0;		// where the carriage is
	double enc_zero = 0;		// physical position the encoder reads as 0
	double motor_pos_cmd = 0;	// last output of "motmod"
	// home switch: TRUE while sw_lo <= phys <= sw_hi
	double sw_lo = 1e9, sw_hi = 1e9;
	bool shared_with_prev = false;	// switch input = OR with the previous joint's switch
	// index pulse at index_pos (crossing clears index-enable)
	double index_pos = 1e9;
	bool encoder_resets = true;	// encoder zeroes its count at the index
	bool absolute = false;		// absolute encoder: starts at phys (enc_zero 0)
	double pos_lim = 1e9, neg_lim = -1e9;	// physical limit-switch positions
	int unlock_delay = 0;		// periods from unlock to is-unlocked (and back)
	int unlock_count = 0;
	FreePlanner tp;
	// observations
	std::vector<int> states;	// home-state at the end of each period, repeats merged
	long first_final_wait = -1;	// period the final move (state 21) was first seen
	long finished_at = -1;		// period homing ended (homing went FALSE)
	double max_speed_final = 0;	// fastest |vel| seen during FINAL_MOVE_WAIT
	double max_vel_lim = 0;		// largest free_vel_lim homing asked for
	bool index_enable_seen = false;	// index-enable TRUE at some point
	bool was_homing = false;
};

class Sim {
public:
	explicit Sim(int n, int extra = 0, unsigned unlock_mask = 0);
	~Sim();
	struct homing_joint &hj(int j) { return hj_[j]; }
	SimJoint &sj(int j) { return sj_[j]; }
	// Place joint j physically at p with pos_cmd = pos_fb = p (motor offset 0).
	void place(int j, double p);
	// One servo period in the order of motion-controller. Returns do_homing()'s value.
	bool step();
	// Step until no joint homes and no sequence runs (or max periods). Returns periods.
	long run_until_idle(long max_periods = 200000);
	long now() const { return t_; }
	int allhomed_events = 0;		// periods in which do_homing() returned true
	static std::vector<std::string> errors;	// every report, in order
	double dt = 0.001;
	double max_acc = 100;
	bool free_state = true;			// do_homing only runs in FREE
	std::function<void(Sim &)> before_homing;	// hook run just before do_homing
private:
	int n_;
	long t_ = 0;
	std::vector<struct homing_joint> hj_;
	std::vector<SimJoint> sj_;
};

// joint params with the usual defaults: HOME_SEQUENCE none, final vel from max
void params(int j, double offset, double home, double search, double latch, int flags = 0,
	    int seq = HOME_SEQUENCE_NONE, double final_vel = -1, bool vol = false);

}  // namespace homing_test
