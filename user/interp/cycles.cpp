// SPDX-License-Identifier: GPL-2.0-or-later
// cycles.cpp - canned cycles G73, G74, G81-G89 (gcode.md 10) and G76 threading.
// The cycle works in plane coordinates: (p1, p2) the position in the plane, n the
// axis normal to it (Z in G17, Y in G18, X in G19).
#include <algorithm>
#include <cmath>

#include "impl.hpp"

namespace rs274 {

static const char axis_letters[] = "xyzabcuvw";

void Interp::Impl::do_cycle(Block& b, int code)
{
	if (comp != 400)
		fail("Cannot use canned cycles with cutter radius compensation on");
	if (feed_mode == FeedMode::INVERSE_TIME)
		fail("Cannot use inverse time feed with canned cycles");
	for (char c : {'a', 'b', 'c'})
		if (b.w(c))
			fail("Cannot put %s %c in canned cycle", c == 'a' ? "an" : "a", c);
	if (b.w('u') || b.w('v') || b.w('w'))
		fail("Cannot put a u, v or w in canned cycle");
	int a1, a2, an;
	plane_axes(a1, a2, an);
	const char* pname = plane == Plane::XY ? "xy" : plane == Plane::XZ ? "xz" : "yz";
	char ln = axis_letters[an], l1 = axis_letters[a1], l2 = axis_letters[a2];
	int reps = b.w('l') ? (int)b.v('l') : 1;
	if (reps == 0)
		fail("Cannot do zero repeats of cycle");
	if (reps > cfg.max_loop_iterations)
		fail("Too many repeats of cycle (limit %ld)", cfg.max_loop_iterations);
	Pos cur = program_pos();
	if (cycle_code != code) {
		cycle_code = code;
		cycle_old_z = cur[an];
		cycle_has_r = cycle_has_z = cycle_has_p = cycle_has_q = cycle_has_ijk = false;
	}
	if (b.w('r')) {
		cycle_r = b.v('r');
		cycle_has_r = true;
	}
	if (b.w(ln)) {
		cycle_z = b.v(ln);
		cycle_has_z = true;
	}
	if (b.w('p')) {
		if (b.v('p') < 0)
			fail("Negative dwell time in canned cycle");
		cycle_p = b.v('p');
		cycle_has_p = true;
	}
	if (b.w('q')) {
		if (b.v('q') <= 0)
			fail("Negative or zero q value used");
		cycle_q = b.v('q');
		cycle_has_q = true;
	}
	if (code == 870 && (b.w('i') || b.w('j') || b.w('k'))) {
		if (!b.w('i'))
			fail("I word missing with g87");
		if (!b.w('j'))
			fail("J word missing with g87");
		if (!b.w('k'))
			fail("K word missing with g87");
		cycle_i = b.v('i');
		cycle_j = b.v('j');
		cycle_k = b.v('k');
		cycle_has_ijk = true;
	}
	if (!cycle_has_z)
		fail("%c value unspecified in %s plane canned cycle", ln - 32, pname);
	if (!cycle_has_r)
		fail("R clearance plane unspecified in cycle");
	int codeno = code / 10;
	if ((code == 820 || code == 860 || code == 880 || code == 890) && !cycle_has_p)
		fail("Dwell time p word missing with g%d", codeno);
	if ((code == 730 || code == 830) && !cycle_has_q)
		fail("Q word missing with g%d", codeno);
	if (code == 870 && !cycle_has_ijk)
		fail("I word missing with g87");
	if (code == 840 && spindle_dir != 1)
		fail(spindle_dir == 0 ? "Spindle not turning clockwise in g84"
		                      : "Spindle turning counterclockwise in G84");
	if (code == 740 && spindle_dir != -1)
		fail("Spindle not turning counterclockwise in g74");
	if ((code == 860 || code == 870 || code == 880) && spindle_dir == 0)
		fail("Spindle not turning in g%d", codeno);

	double r = cycle_r, z = cycle_z;
	if (incremental) {
		r = cycle_r + cur[an];
		z = r + cycle_z;
	}
	if (r < z)
		fail("R less than %c in cycle in %s plane", ln, pname);
	double clear = retract_old_z ? std::max(cycle_old_z, r) : r;
	if ((code == 730 || code == 830) && (r - z) / cycle_q > cfg.max_loop_iterations)
		fail("Too many pecks: Q is too small for the depth (limit %ld)", cfg.max_loop_iterations);
	double delta = units == Units::INCH ? 0.010 : 0.254;
	MotionControl saved_mc = mc;
	if (mc != MotionControl::EXACT_PATH)
		canon.set_motion_control_mode(MotionControl::EXACT_PATH, 0);

	Pos p = cur;
	auto at = [&](double n) { Pos q = p; q[an] = n; return q; };
	if (p[an] < r)
		traverse(at(r));   // preliminary move up to the R plane
	for (int rep = 0; rep < reps; rep++) {
		if (incremental) {
			p[a1] += b.w(l1) ? b.v(l1) : 0;
			p[a2] += b.w(l2) ? b.v(l2) : 0;
		} else {
			if (b.w(l1))
				p[a1] = b.v(l1);
			if (b.w(l2))
				p[a2] = b.v(l2);
		}
		double cz = program_pos()[an];
		if (rep == 0 && cz > r) {
			traverse(at(cz));
			traverse(at(r));
		} else {
			traverse(at(clear));
			if (clear > r)
				traverse(at(r));
		}
		switch (code) {
		case 730:
		case 830: {
			double d = r - cycle_q;
			while (d > z) {
				feed_to(at(d));
				if (code == 830)
					traverse(at(r));
				traverse(at(d + delta));
				d -= cycle_q;
			}
			feed_to(at(z));
			traverse(at(clear));
			break;
		}
		case 810:
			feed_to(at(z));
			traverse(at(clear));
			break;
		case 820:
			feed_to(at(z));
			canon.dwell(cycle_p);
			traverse(at(clear));
			break;
		case 740:
		case 840: {
			canon.feed_override_enable(false);
			canon.speed_override_enable(0, false);
			feed_to(at(z));
			canon.stop_spindle_turning(0);
			if (code == 840)
				canon.start_spindle_counterclockwise(0);
			else
				canon.start_spindle_clockwise(0);
			if (cycle_has_p)
				canon.dwell(cycle_p);
			feed_to(at(clear));
			canon.stop_spindle_turning(0);
			if (code == 840)
				canon.start_spindle_clockwise(0);
			else
				canon.start_spindle_counterclockwise(0);
			canon.feed_override_enable(feed_override);
			canon.speed_override_enable(0, speed_override);
			break;
		}
		case 850:
			feed_to(at(z));
			feed_to(at(r));
			traverse(at(clear));
			break;
		case 860:
			feed_to(at(z));
			canon.dwell(cycle_p);
			canon.stop_spindle_turning(0);
			traverse(at(clear));
			spindle_dir == 1 ? canon.start_spindle_clockwise(0) : canon.start_spindle_counterclockwise(0);
			break;
		case 870: {
			// back bore: offset by I J, down past the part, centre, feed up to K and back
			Pos off = p;
			off[a1] += cycle_i;
			off[a2] += cycle_j;
			double k = incremental ? z + cycle_k : cycle_k;
			if (k <= z || k > r)
				fail("K in g87 must lie between the bottom (Z) and the R plane");
			auto off_at = [&](double n) { Pos q = off; q[an] = n; return q; };
			traverse(off_at(r));
			canon.stop_spindle_turning(0);
			traverse(off_at(z));
			traverse(at(z));
			spindle_dir == 1 ? canon.start_spindle_clockwise(0) : canon.start_spindle_counterclockwise(0);
			feed_to(at(k));
			feed_to(at(z));
			canon.stop_spindle_turning(0);
			traverse(off_at(z));
			traverse(off_at(clear));
			traverse(at(clear));
			spindle_dir == 1 ? canon.start_spindle_clockwise(0) : canon.start_spindle_counterclockwise(0);
			break;
		}
		case 880:
			feed_to(at(z));
			canon.dwell(cycle_p);
			canon.stop_spindle_turning(0);
			canon.program_stop();
			spindle_dir == 1 ? canon.start_spindle_clockwise(0) : canon.start_spindle_counterclockwise(0);
			break;
		case 890:
			feed_to(at(z));
			canon.dwell(cycle_p);
			feed_to(at(clear));
			break;
		default: break;
		}
	}
	if (saved_mc != MotionControl::EXACT_PATH)
		canon.set_motion_control_mode(saved_mc, p_tol * unit_factor(AX_X));
}

// G76 P(pitch) Z I J K [R Q H E L] (gcode.md 10): threading passes, each a
// spindle-synchronized feed along Z at the pass depth, from the drive line (the start
// point's X) towards the thread, with the compound angle shifting each pass's start.
void Interp::Impl::do_g76(const Block& b)
{
	if (plane != Plane::XZ)
		fail("G76 allowed only in the ZX plane");
	if (b.w('x') || b.w('y'))
		fail("X or Y words not allowed with G76");
	for (char c : {'a', 'b', 'c', 'u', 'v', 'w'})
		if (b.w(c))
			fail("Cannot move rotary axes with G76");
	if (comp != 400)
		fail("Cannot use G76 with cutter radius compensation on");
	for (char c : {'p', 'i', 'j', 'k'})
		if (!b.w(c))
			fail("%c word missing with G76", c - 32);
	if (!b.w('z'))
		fail("All axes missing with motion code");
	double pitch = b.v('p'), peak = b.v('i'), first = b.v('j'), full = b.v('k');
	if (pitch <= 0 || first <= 0 || full <= 0)
		fail("Negative or zero P, J or K value used with G76");
	double deg = b.w('r') ? b.v('r') : 1;
	if (deg < 1)
		fail("R value must be 1 or greater with G76");
	double angle = b.w('q') ? b.v('q') : 0;
	int spring = b.w('h') ? (int)std::lround(b.v('h')) : 0;
	if (spring < 0)
		fail("Negative H value used with G76");
	if (spring > 1000)
		fail("Too many spring passes with G76 (H > 1000)");
	int taper_ends = b.w('l') ? (int)b.v('l') : 0;
	if (taper_ends > 3)
		fail("L value must be 0..3 with G76");
	double taper = b.w('e') ? b.v('e') : 0;
	if (spindle_dir == 0)
		fail("Spindle not turning in G76");
	Pos start = program_pos();
	double zend = incremental ? start[AX_Z] + b.v('z') : b.v('z');
	double len = std::fabs(zend - start[AX_Z]);
	if (taper > len / 2)
		fail("E value in G76 is more than half the length of the drive line");
	double dir = peak < 0 ? -1 : 1;   // external threads cut towards -X
	double zdir = zend < start[AX_Z] ? -1 : 1;
	double xdrive = start[AX_X], xpeak = start[AX_X] + peak;
	double tan_a = std::tan(angle * M_PI / 180);
	double k = pitch * unit_factor(AX_Z);
	auto pass = [&](double depth) {
		double zs = start[AX_Z] - zdir * depth * tan_a;
		double xc = xpeak + dir * depth;
		Pos p = start;
		p[AX_Z] = zs;
		p[AX_X] = (taper_ends & 1) && taper > 0 ? xpeak : xc;
		traverse(p);
		canon.start_speed_feed_synch(0, k, false);
		if ((taper_ends & 1) && taper > 0) {
			p[AX_X] = xc;
			p[AX_Z] = zs + zdir * taper;
			feed_to(p);
		}
		p[AX_Z] = (taper_ends & 2) && taper > 0 ? zend - zdir * taper : zend;
		feed_to(p);
		if ((taper_ends & 2) && taper > 0) {
			p[AX_X] = xpeak;
			p[AX_Z] = zend;
			feed_to(p);
		}
		canon.stop_speed_feed_synch();
		p[AX_X] = xdrive;
		traverse(p);
		p[AX_Z] = zs;
		traverse(p);
	};
	for (int n = 1;; n++) {
		double depth = first * std::pow((double)n, 1.0 / deg);
		if (depth >= full)
			break;
		if (n >= 10000)
			fail("G76 would need more than 10000 passes: J is too small for K");
		pass(depth);
	}
	pass(full);
	for (int s = 0; s < spring; s++)
		pass(full);
	Pos p = start;
	traverse(p);
}

}  // namespace rs274
