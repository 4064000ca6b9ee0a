// tp_sim.hpp - drives the planner cycle by cycle and checks the per-axis limits on
// the commanded positions (velocity and acceleration by finite differences).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>
#include <gtest/gtest.h>
extern "C" {
#include "tp.h"
}

using Vec9 = std::array<double, 9>;

inline Vec9 vec(const tp_pose &p) { return {p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w}; }
inline tp_pose pose(double x, double y, double z = 0)
{
	tp_pose p{};
	p.x = x; p.y = y; p.z = z;
	return p;
}

struct TpSim {
	std::vector<double> mem;	// double-aligned
	struct tp *tp = nullptr;
	double dt = 0.001;
	double vmax = 100, amax = 1000;	// per axis, units/s, units/s^2
	tp_inputs in{};
	std::vector<Vec9> trace;	// commanded position after each cycle (trace[0] = start)
	std::vector<tp_outputs> outs;

	explicit TpSim(int queue = TP_DEFAULT_QUEUE_SIZE, double cycle = 0.001)
	    : mem(tp_size(queue) / sizeof(double) + 1), dt(cycle)
	{
		tp = tp_init(mem.data(), mem.size() * sizeof(double), queue);
		EXPECT_NE(tp, nullptr);
		tp_set_cycle_time(tp, dt);
		tp_set_amax(tp, 1e9);
		for (int i = 0; i < 9; i++)
			tp_set_axis_limits(tp, i, vmax, amax);
		in.feed_scale = 1;
		in.rapid_scale = 1;
		in.spindle_at_speed = 1;
		tp_pose p{};
		tp_get_pos(tp, &p);
		trace.push_back(vec(p));
	}
	tp_move feed(double f, int id = 1) const
	{
		tp_move m{};
		m.motion_type = TP_MOTION_FEED;
		m.vel = f;
		m.ini_maxvel = vmax;
		m.acc = amax;
		m.id = id;
		return m;
	}
	int line(double x, double y, double z, double f, int id = 1)
	{
		tp_pose p = pose(x, y, z);
		tp_move m = feed(f, id);
		return tp_add_line(tp, &p, &m);
	}
	const tp_outputs &cycle()
	{
		tp_outputs o{};
		EXPECT_EQ(tp_run_cycle(tp, &in, &o), 0);
		outs.push_back(o);
		trace.push_back(vec(o.pos));
		return outs.back();
	}
	// run until the queue is empty; returns cycles used
	int run(int max_cycles = 200000)
	{
		int n = 0;
		while (n < max_cycles) {
			cycle();
			n++;
			if (outs.back().done)
				break;
		}
		return n;
	}
	Vec9 pos() const { return trace.back(); }
	// worst per-axis |velocity| / limit and |acceleration| / limit over the trace
	double worst_vel_ratio(size_t from = 1) const
	{
		double w = 0;
		for (size_t k = from; k < trace.size(); k++)
			for (int i = 0; i < 9; i++)
				w = std::max(w, std::fabs(trace[k][i] - trace[k - 1][i]) / dt / vmax);
		return w;
	}
	double worst_acc_ratio(size_t from = 1) const
	{
		double w = 0;
		for (size_t k = std::max<size_t>(from, 1); k + 1 < trace.size(); k++)
			for (int i = 0; i < 9; i++)
				w = std::max(w, std::fabs(trace[k + 1][i] - 2 * trace[k][i] + trace[k - 1][i])
							 / (dt * dt) / amax);
		return w;
	}
	static double path_speed(const Vec9 &a, const Vec9 &b, double dt)
	{
		return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1])
				 + (a[2] - b[2]) * (a[2] - b[2])) / dt;
	}
};

// distance from point p to segment a-b in XYZ
inline double seg_dist(const Vec9 &p, const Vec9 &a, const Vec9 &b)
{
	double d[3], w[3], L2 = 0, t = 0;
	for (int i = 0; i < 3; i++) {
		d[i] = b[i] - a[i];
		w[i] = p[i] - a[i];
		L2 += d[i] * d[i];
		t += w[i] * d[i];
	}
	t = L2 > 0 ? std::clamp(t / L2, 0.0, 1.0) : 0;
	double s = 0;
	for (int i = 0; i < 3; i++) {
		double e = w[i] - t * d[i];
		s += e * e;
	}
	return std::sqrt(s);
}
