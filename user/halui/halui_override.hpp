// SPDX-License-Identifier: GPL-2.0-or-later
// halui_override.hpp - one override knob (feed, rapid, spindle S, max velocity):
// the counts/count-enable/direct-value/scale/increase/decrease/reset pins turned into
// a new value, clamped (emcrsh-and-halui.md 3.2 "Counts rules"). HAL-free; time is
// an input so unit tests drive it.
#pragma once

#include <cstdint>
#include <optional>

namespace hal::halui {

// The IN pins of one knob as read this cycle.
struct OverrideIn {
    int32_t counts = 0;
    bool count_enable = true;   // default TRUE (seed halui(1))
    bool direct_value = false;
    double scale = 0.1;
    bool increase = false, decrease = false, reset = false;
};

class OverrideKnob {
public:
    // lo..hi: the clamp; has_reset: the knob has a reset pin (max-velocity has none).
    OverrideKnob(double lo, double hi, bool has_reset) : lo_(lo), hi_(hi), has_reset_(has_reset) {}

    // One cycle: 'current' is task's value (status), now_s a monotonic time. Returns
    // the value to send when the pins asked for a change. Counts moved while
    // count-enable is FALSE are absorbed. Until task reports a value just sent (or
    // HOLD_S passed), further steps build on the sent value, not the stale status.
    std::optional<double> update(const OverrideIn& in, double current, double now_s);

    static constexpr double HOLD_S = 0.5;

private:
    double lo_, hi_;
    bool has_reset_;
    bool started_ = false;      // the first cycle only records the pins
    OverrideIn prev_;
    std::optional<double> sent_;
    double sent_at_ = 0;
};

}  // namespace hal::halui
