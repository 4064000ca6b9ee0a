/* SPDX-License-Identifier: GPL-2.0-or-later */
/* siggen_core.h - siggen(9) waveforms, HAL-free so unit tests drive it directly.
 * One phase accumulator per generator, in cycles (0 <= phase < 1); every output
 * is a function of the phase, so all six stay locked together:
 *   cosine  = cos(2 pi phase)        peaks (+) at phase 0
 *   sine    = sin(2 pi phase)        lags cosine by 90 degrees
 *   triangle  +1 at phase 0, -1 at 0.5 (peaks with cosine)
 *   sawtooth  -1 at phase 0 ramping to +1, drops when cosine peaks
 *   square    -1 for phase < 0.5, +1 after (positive while sine is negative)
 *   clock     TRUE while square is positive */
#ifndef SIGGEN_CORE_H
#define SIGGEN_CORE_H

#include "rtapi.h"
#include "rtapi_math.h"

struct siggen_state {
	double phase;		/* cycles, 0 <= phase < 1: private to the update function */
};

struct siggen_out {
	double sine, cosine, triangle, sawtooth, square;
	bool clock;
};

/* Advance by one period and compute the outputs. The frequency is clamped to
 * the Nyquist limit (half the sample rate), so one wrap per step suffices and
 * the waveforms cannot alias into nonsense; NaN counts as 0 Hz. */
static inline void siggen_step(struct siggen_state *s, double freq_hz, double amplitude,
			       double offset, long period_ns, struct siggen_out *o)
{
	double period_s = period_ns * 1e-9;
	double limit = period_s > 0.0 ? 0.5 / period_s : 0.0;
	double p, tri, saw, sq;

	if (freq_hz > limit)
		freq_hz = limit;
	else if (freq_hz < -limit)
		freq_hz = -limit;
	else if (freq_hz != freq_hz)
		freq_hz = 0.0;
	p = s->phase + freq_hz * period_s;
	if (p >= 1.0)
		p -= 1.0;
	else if (p < 0.0)
		p += 1.0;
	if (!(p >= 0.0 && p < 1.0))	/* rounding put us on 1.0, or a NaN crept in */
		p = 0.0;
	s->phase = p;

	if (p < 0.5) {
		tri = 1.0 - 4.0 * p;
		sq = -1.0;
	} else {
		tri = 4.0 * p - 3.0;
		sq = 1.0;
	}
	saw = 2.0 * p - 1.0;
	o->sine = sin(2.0 * M_PI * p) * amplitude + offset;
	o->cosine = cos(2.0 * M_PI * p) * amplitude + offset;
	o->triangle = tri * amplitude + offset;
	o->sawtooth = saw * amplitude + offset;
	o->square = sq * amplitude + offset;
	o->clock = sq > 0.0;
}

#endif /* SIGGEN_CORE_H */
