// SPDX-License-Identifier: GPL-2.0-or-later
// stepgen_bench - figures for stepgen(9): the highest step rate its timing rules
// allow at 25 us and 50 us make-pulses periods (steplen + stepspace periods per
// step for types 0/1, steplen for types 2-15, 1 ns defaults rounded up), and the
// cost of one make-pulses call for 8 generators (the integer core, timed here).
#include <chrono>
#include <cstdio>

#include "stepgen_core.h"

namespace {

double max_rate(int type, rtapi_u32 steplen_ns, rtapi_u32 stepspace_ns, rtapi_u32 period_ns)
{
    stepgen_timing t{};
    t.steplen = stepgen_ns_to_periods(steplen_ns, period_ns);
    if (t.steplen == 0)
        t.steplen = 1;
    t.stepspace = stepgen_ns_to_periods(stepspace_ns, period_ns);
    return 1e9 / (double(stepgen_periods_per_step(type, &t)) * period_ns);
}

// ns per call of make-pulses' work for 8 channels (type 0, mid-speed, so that
// steps, pulse ends and idle periods all occur).
double make_pulses_cost()
{
    constexpr int kChan = 8, kCalls = 2000000;
    stepgen_pulse p[kChan];
    stepgen_timing t{1, 1, 1, 1, 1};
    volatile bool sink = false;
    for (int n = 0; n < kChan; n++) {
        stepgen_pulse_init(&p[n]);
        p[n].addval = (rtapi_u64)(STEPGEN_ONE_STEP / (3 + n));
    }
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kCalls; i++)
        for (int n = 0; n < kChan; n++) {
            stepgen_pulse_step(&p[n], 0, &stepgen_builtin_patterns[2], &t, true);
            sink = p[n].out[0];
        }
    auto ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start);
    (void)sink;
    return ns.count() / kCalls;
}

}  // namespace

int main()
{
    for (rtapi_u32 period : {25000u, 50000u}) {
        std::printf("stepgen max step rate at %u us: type 0/1 %.0f Hz (steplen+stepspace 1 ns), "
                    "doublefreq %.0f Hz (stepspace 0), types 2-15 %.0f Hz\n",
                    period / 1000, max_rate(0, 1, 1, period), max_rate(0, 1, 0, period),
                    max_rate(2, 1, 0, period));
    }
    std::printf("stepgen make-pulses, 8 channels: %.1f ns/call\n", make_pulses_cost());
    return 0;
}
