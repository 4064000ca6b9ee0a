// homing_sim.cpp - the simulated machine of homing_sim.hpp.
#include "homing_sim.hpp"

namespace homing_test {

std::vector<std::string> Sim::errors;

static void collect(const char *msg)
{
	Sim::errors.emplace_back(msg);
}

void FreePlanner::run(double target, double max_vel, double acc, bool enable, double dt)
{
	double v_req = 0;

	if (enable) {
		double e = target - curr_pos, tiny = acc * dt * dt * 0.001;

		if (e > tiny)
			v_req = -acc * dt + std::sqrt(2 * acc * e + (acc * dt) * (acc * dt));
		else if (e < -tiny)
			v_req = acc * dt - std::sqrt(-2 * acc * e + (acc * dt) * (acc * dt));
		if (v_req > max_vel)
			v_req = max_vel;
		if (v_req < -max_vel)
			v_req = -max_vel;
		if (std::fabs(e) <= tiny && std::fabs(curr_vel) <= acc * dt) {
			curr_pos = target;
			curr_vel = 0;
			active = false;
			return;
		}
	}
	double dv = v_req - curr_vel;
	if (dv > acc * dt)
		dv = acc * dt;
	if (dv < -acc * dt)
		dv = -acc * dt;
	curr_vel += dv;
	curr_pos += curr_vel * dt;
	active = curr_vel != 0 || (enable && std::fabs(target - curr_pos) > acc * dt * dt * 0.001);
}

Sim::Sim(int n, int extra, unsigned unlock_mask) : n_(n), hj_(n), sj_(n)
{
	errors.clear();
	for (auto &h : hj_) {
		h = {};
		h.active = h.enabled = true;
		h.max_vel = 10;
		h.max_acc = max_acc;
		h.min_limit = -100;
		h.max_limit = 100;
	}
	homing_setup(n, extra, unlock_mask, hj_.data(), collect);
}

Sim::~Sim() = default;

void Sim::place(int j, double p)
{
	SimJoint &s = sj_[j];
	s.phys = p;
	s.enc_zero = 0;
	s.motor_pos_cmd = p;
	s.tp.curr_pos = p;
	s.tp.curr_vel = 0;
	hj_[j].pos_cmd = hj_[j].pos_fb = hj_[j].free_pos = hj_[j].free_pos_cmd = p;
	hj_[j].motor_offset = 0;
	hj_[j].motor_pos_fb = p;
}

bool Sim::step()
{
	bool ret = false;

	// the machine: servo follows the command, encoder, switches (threads before motion)
	for (int j = 0; j < n_; j++) {
		SimJoint &s = sj_[j];
		double prev = s.phys;
		s.phys = s.motor_pos_cmd + s.enc_zero;
		struct homing_priv &h = homing_g.h[j];
		if (h.index_enable && ((prev < s.index_pos) != (s.phys < s.index_pos))) {
			if (s.encoder_resets)
				s.enc_zero = s.index_pos;
			h.index_enable = false;	// the encoder clears index-enable
		}
		hj_[j].motor_pos_fb = s.phys - s.enc_zero;
		bool sw = s.phys >= s.sw_lo && s.phys <= s.sw_hi;
		if (s.shared_with_prev && j > 0)
			sw = sw || homing_g.h[j - 1].home_sw;
		h.home_sw = sw;
		hj_[j].on_pos_limit = s.phys >= s.pos_lim;
		hj_[j].on_neg_limit = s.phys <= s.neg_lim;
		if (h.unlock != h.is_unlocked) {
			if (++s.unlock_count >= s.unlock_delay) {
				h.is_unlocked = h.unlock;
				s.unlock_count = 0;
			}
		}
	}
	// motmod's process_inputs: pos_fb, hiding the encoder jump at the index
	for (int j = 0; j < n_; j++) {
		struct homing_joint &hj = hj_[j];
		hj.pos_fb = hj.motor_pos_fb - (hj.backlash_filt + hj.motor_offset);
		if (get_homing_at_index_search_wait(j) && !get_index_enable(j))
			hj.pos_fb = hj.pos_cmd;
		hj.free_pos = sj_[j].tp.curr_pos;
		hj.free_tp_active = sj_[j].tp.active;
	}
	if (before_homing)
		before_homing(*this);
	if (free_state) {
		ret = do_homing((long)(dt * 1e9 + 0.5));
		if (ret)
			allhomed_events++;
	}
	// get_pos_cmds (FREE): the free planner, then output_to_hal
	for (int j = 0; j < n_; j++) {
		struct homing_joint &hj = hj_[j];
		SimJoint &s = sj_[j];
		s.tp.curr_pos = hj.free_pos;
		double before = s.tp.curr_pos;
		s.tp.run(hj.free_pos_cmd, hj.free_vel_lim, max_acc, hj.free_tp_enable, dt);
		hj.pos_cmd = s.tp.curr_pos;
		s.motor_pos_cmd = hj.pos_cmd + hj.motor_offset;
		if (hj.free_vel_lim > s.max_vel_lim)
			s.max_vel_lim = hj.free_vel_lim;
		int st = get_home_state(j);
		if (st == HOME_FINAL_MOVE_WAIT) {
			if (s.first_final_wait < 0)
				s.first_final_wait = t_;
			double v = std::fabs(s.tp.curr_pos - before) / dt;
			if (v > s.max_speed_final)
				s.max_speed_final = v;
		}
		if (s.states.empty() || s.states.back() != st)
			s.states.push_back(st);
		if (get_index_enable(j))
			s.index_enable_seen = true;
		if (s.was_homing && !get_homing(j))
			s.finished_at = t_;
		s.was_homing = get_homing(j);
	}
	t_++;
	return ret;
}

long Sim::run_until_idle(long max_periods)
{
	long start = t_;
	do {
		step();
	} while (get_homing_is_active() && t_ - start < max_periods);
	// let the planners settle (a stop decelerates after homing ended)
	for (int i = 0; i < 200; i++)
		step();
	return t_ - start;
}

void params(int j, double offset, double home, double search, double latch, int flags, int seq,
	    double final_vel, bool vol)
{
	set_joint_homing_params(j, offset, home, final_vel, search, latch, flags, seq, vol);
}

}  // namespace homing_test
