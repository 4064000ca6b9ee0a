/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sphereprobe.comp - sphereprobe(9): probe-out is TRUE while the probe position (in encoder
 * counts) is inside a hemisphere of radius r standing on z = cz, dome up. Integer only. */
component sphereprobe "Probe a pretend hemisphere";
pin in s32 px;
pin in s32 py;
pin in s32 pz "rawcounts position from software encoder";
pin in s32 cx;
pin in s32 cy;
pin in s32 cz "Center of sphere in counts";
pin in s32 r "Radius of hemisphere in counts";
pin out bit probe_out;
function _ nofp "update probe-out based on inputs";
author "Jeff Epler";
license "GPL";
;;
static rtapi_u64 dist(hal_s32_t a, hal_s32_t b)
{
	rtapi_s64 d = (rtapi_s64)a - b;

	return d < 0 ? -d : d;
}

FUNCTION(_)
{
	rtapi_u64 dx = dist(px, cx), dy = dist(py, cy), rr = r < 0 ? 0 : r;

	/* each distance is at most r here, so the squares (< 2^62 each) cannot overflow */
	if (pz < cz || dx > rr || dy > rr || dist(pz, cz) > rr) {
		probe_out = 0;
		return;
	}
	probe_out = dx * dx + dy * dy + dist(pz, cz) * dist(pz, cz) <= rr * rr;
}
