// SPDX-License-Identifier: GPL-2.0-or-later
// tp_bench: figures of motmod's trajectory planner (kernel/motion/tp/), on the C the
// module is built from, in this process. Prints figures, never fails.
//   1. planner cost per cycle (us, median and max) with a full queue (2000 segments,
//      look-ahead depth 50) of short G64 segments, and the cost of queueing one segment;
//   2. the shortest segment length that still reaches the programmed feed
//      (3 m/min = 50 mm/s, 1 ms cycle, 1000 mm/s^2), for collinear segments and for a
//      polyline approximating an R 50 mm arc (G64 P0.001).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

extern "C" {
#include "tp.h"
}

namespace {

using Clock = std::chrono::steady_clock;

struct Planner {
	std::vector<double> mem;
	struct tp *tp;
	explicit Planner(int queue, double acc)
	    : mem(tp_size(queue) / sizeof(double) + 1),
	      tp(tp_init(mem.data(), mem.size() * sizeof(double), queue))
	{
		tp_set_cycle_time(tp, 0.001);
		for (int i = 0; i < 9; i++)
			tp_set_axis_limits(tp, i, 200, acc);
	}
	int line(double x, double y, double f, int id)
	{
		tp_pose p{};
		p.x = x;
		p.y = y;
		tp_move m{};
		m.motion_type = TP_MOTION_FEED;
		m.vel = f;
		m.ini_maxvel = 200;
		m.acc = 1000;
		m.id = id;
		return tp_add_line(tp, &p, &m);
	}
};

double quantile(std::vector<double> v, double q)
{
	size_t k = std::min(v.size() - 1, (size_t)(q * v.size()));
	std::nth_element(v.begin(), v.begin() + k, v.end());
	return v[k];
}

double median(const std::vector<double> &v) { return quantile(v, 0.5); }

// point i of a polyline: collinear along x, or chords of an R 50 arc
void point(int kind, double len, int i, double *x, double *y)
{
	if (kind == 0) {
		*x = len * i;
		*y = 0;
		return;
	}
	double R = 50, a = len / R * i;
	*x = R * std::sin(a);
	*y = R - R * std::cos(a);
}

// peak path speed over a run of n segments of length len
double peak_speed(int kind, double len, int n)
{
	Planner p(TP_DEFAULT_QUEUE_SIZE, 1000);
	tp_set_term_cond(p.tp, TP_TERM_PARABOLIC, 0.001);
	tp_inputs in{};
	in.feed_scale = in.rapid_scale = 1;
	in.spindle_at_speed = 1;
	tp_outputs o{};
	double px = 0, py = 0, vmax = 0;
	int next = 1;
	for (int k = 0; k < 1000000; k++) {
		while (next <= n && !tp_is_queue_full(p.tp)) {
			double x, y;
			point(kind, len, next, &x, &y);
			p.line(x, y, 50, next++);
		}
		tp_run_cycle(p.tp, &in, &o);
		vmax = std::max(vmax, std::hypot(o.pos.x - px, o.pos.y - py) / 0.001);
		px = o.pos.x;
		py = o.pos.y;
		if (o.done && next > n)
			break;
	}
	return vmax;
}

}  // namespace

int main()
{
	// 1. cost per cycle with a full queue of 0.05 mm zig-zag-free arc chords
	Planner p(TP_DEFAULT_QUEUE_SIZE, 1000);
	tp_set_term_cond(p.tp, TP_TERM_PARABOLIC, 0.001);
	tp_inputs in{};
	in.feed_scale = in.rapid_scale = 1;
	in.spindle_at_speed = 1;
	tp_outputs o{};
	std::vector<double> cyc, add;
	int next = 1;
	for (int k = 0; k < 30000; k++) {
		while (!tp_is_queue_full(p.tp)) {
			double x, y;
			point(1, 0.05, next, &x, &y);
			auto t0 = Clock::now();
			p.line(x, y, 50, next++);
			add.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
		}
		auto t0 = Clock::now();
		tp_run_cycle(p.tp, &in, &o);
		cyc.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
	}
	std::printf("tp: cost per cycle, queue of %d segments of 0.05 mm (G64 P0.001, depth %d): "
		    "median %.3f us, 99.9%% %.3f us, max %.3f us (%zu cycles; max includes preemption)\n",
		    TP_DEFAULT_QUEUE_SIZE, TP_DEFAULT_OPT_DEPTH, median(cyc), quantile(cyc, 0.999),
		    *std::max_element(cyc.begin(), cyc.end()), cyc.size());
	std::printf("tp: cost of queueing one segment (junction, blend arc, look-ahead): "
		    "median %.3f us, 99.9%% %.3f us, max %.3f us (%zu segments)\n",
		    median(add), quantile(add, 0.999), *std::max_element(add.begin(), add.end()), add.size());

	// 2. shortest segment length that still reaches 50 mm/s
	const char *names[2] = {"collinear", "R 50 arc chords"};
	for (int kind = 0; kind < 2; kind++) {
		double lo = 0.0005, hi = 1.0;	// lo fails, hi reaches
		if (peak_speed(kind, hi, 20 / hi) < 49.95) {
			std::printf("tp: %s: feed not reached even at %.3f mm\n", names[kind], hi);
			continue;
		}
		for (int it = 0; it < 14; it++) {
			double mid = std::sqrt(lo * hi);
			if (peak_speed(kind, mid, (int)(20 / mid)) >= 49.95)
				hi = mid;
			else
				lo = mid;
		}
		std::printf("tp: shortest segment reaching 3 m/min at 1 ms, 1000 mm/s^2 (%s): %.4f mm"
			    " (0.05 mm: peak %.2f mm/s)\n", names[kind], hi,
			    peak_speed(kind, 0.05, 400));
	}
	return 0;
}
