// SPDX-License-Identifier: GPL-2.0-or-later
// check.cpp - block-level checks made before anything executes (gcode.md 15): which
// motion the block runs, axis-word users, and words no code on the line uses.
#include <cmath>

#include "impl.hpp"

namespace rs274 {

static bool is_cycle(int c) { return c == 730 || c == 740 || (c >= 810 && c <= 890); }
static bool one_of(int v, std::initializer_list<int> l)
{
	for (int x : l)
		if (v == x)
			return true;
	return false;
}

void Interp::Impl::check_block(Block& b)
{
	int g0 = b.gmode[0], g1 = b.gmode[1], g8 = b.gmode[8];
	bool axes = b.any_axis();
	bool g0_axis_user = one_of(g0, {100, 280, 300, 520, 920});
	bool tl_axis_user = g8 == 431 || (g8 == 432 && axes);
	if (g1 != -1 && (g0_axis_user || tl_axis_user))
		fail("Cannot use two g codes that both use axis values");
	if (g1 == 800 && axes)
		fail("Cannot use axis values with g80");
	if (g1 != -1) {
		b.motion = g1;
	} else if (axes && !g0_axis_user && !tl_axis_user) {
		if (motion == 800)
			fail("Cannot use axis values without a g code that uses them");
		b.motion = motion;
	} else if (g0 == 530 && !g0_axis_user) {
		b.motion = motion;
	}
	if (b.motion == 800)
		b.motion = -1;
	int mo = b.motion;
	if (mo != -1 && !axes && !one_of(mo, {0, 10, 20, 30, 52}))
		fail("All axes missing with motion code");
	if ((g0 == 520 || g0 == 920) && !axes)
		fail("All axes missing with g52 or g92");
	if (g0 == 40 && (mo == 20 || mo == 30))
		fail("G4 not allowed with G2 or G3 because they both use P");

	int m5 = b.mmode[5], m7 = b.mmode[7], m9 = b.mmode[9];
	bool user_m = b.mmode[10] != -1;
	if (b.w('d') && !one_of(b.gmode[7], {410, 411, 420, 421}) && b.gmode[14] != 960)
		fail("D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it");
	if (b.w('h') && !one_of(g8, {430, 432}) && mo != 760)
		fail("H word with no G43 or G76 to use it");
	if (b.w('i') && !one_of(mo, {20, 30, 50, 51, 331, 760, 870}) && g0 != 100)
		fail("I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it");
	if (b.w('j') && !one_of(mo, {20, 30, 50, 51, 760, 870}) && g0 != 100)
		fail("J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it");
	if (b.w('k') && !one_of(mo, {20, 30, 330, 331, 760, 870}))
		fail("K word with no G2, G3, G33, G33.1, G76, or G87 to use it");
	if (b.w('l') && g0 != 100 && !one_of(b.gmode[7], {411, 421}) && !is_cycle(mo) && m5 != 66 &&
	    mo != 760 && mo != 52 && b.mmode[4] != 98)
		fail("L word with no G10, cutter compensation, canned cycle, digital/analog input, M98 or NURBS code");
	if (b.w('p') && !one_of(g0, {40, 100}) && !one_of(mo, {20, 30, 50, 52, 740, 760, 820, 840, 860, 880, 890}) &&
	    b.gmode[13] != 640 && !one_of(m9, {50, 51, 52, 53}) && !one_of(m5, {62, 63, 64, 65, 66}) &&
	    !user_m && m7 != 19 && b.mmode[4] != 98)
		fail("P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 M62 M63 M64 M65 M66 M98 or user M code to use it");
	if (b.w('q') && g0 != 100 && b.gmode[13] != 640 && !one_of(mo, {50, 730, 760, 830}) && m7 != 19 &&
	    !one_of(m5, {66, 67, 68}) && !user_m && b.mmode[6] != 61)
		fail("Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, M68 or user M code that uses it");
	if (b.w('r') && !one_of(mo, {20, 30, 760}) && !is_cycle(mo) && g0 != 100 && m7 != 19)
		fail("R word with no g code that uses it");
	if (b.w('e') && mo != 760 && !one_of(m5, {66, 67, 68}))
		fail("E word with no G70, G76, M66, M67 or M68 to use it");
	if (b.w('$') && !one_of(m7, {3, 4, 5, 19}) && m9 != 51 && !one_of(mo, {330, 331, 760, 740, 840}) &&
	    b.gmode[5] != 950 && b.gmode[14] == -1 && !b.w('s'))
		fail("$ (spindle selection) word with no M3, M4, M5, M19, M51, G33, G33.1, G76, G95, G96 or G97 to use it");
	if (b.w('p') && (mo == 20 || mo == 30 || m7 == 19)) {
		double p = b.v('p');
		if (std::fabs(p - std::nearbyint(p)) > 0.0001)
			fail("P value not an integer with M19 G2 or G3");
		if ((mo == 20 || mo == 30) && p < 1)
			fail("P value should be 1 or greater with G2 or G3");
		if (m7 == 19 && (p < 0 || p > 2))
			fail("P value must be 0,1,or 2 with M19");
	}
	if (m7 == 19 && b.w('r') && (b.v('r') < 0 || b.v('r') > 360))
		fail("R value must be within 0..360 with M19");
}

}  // namespace rs274
