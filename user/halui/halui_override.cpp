// SPDX-License-Identifier: GPL-2.0-or-later
// halui_override.cpp - override knob arithmetic (halui_override.hpp).
#include "halui_override.hpp"

#include <algorithm>
#include <cmath>

namespace hal::halui {

// Counts are an encoder's: they wrap around at the s32 limits, and a wrap is one step.
static double counts_delta(int32_t before, int32_t now)
{
    return static_cast<int32_t>(static_cast<uint32_t>(now) - static_cast<uint32_t>(before));
}

std::optional<double> OverrideKnob::update(const OverrideIn& in, double current, double now_s)
{
    if (!started_) {
        started_ = true;
        prev_ = in;
        return std::nullopt;
    }
    // a value sent recently and not yet reflected in the status is the better base
    if (sent_ && (now_s - sent_at_ > HOLD_S || std::fabs(current - *sent_) < 1e-9))
        sent_.reset();
    double value = sent_ ? *sent_ : current;
    bool changed = false;
    if (in.counts != prev_.counts) {
        if (in.count_enable) {
            if (in.direct_value)
                value = in.counts * in.scale;
            else
                value += counts_delta(prev_.counts, in.counts) * in.scale;
            changed = true;
        }
    }
    if (in.increase && !prev_.increase) {
        value += in.scale;
        changed = true;
    }
    if (in.decrease && !prev_.decrease) {
        value -= in.scale;
        changed = true;
    }
    if (has_reset_ && in.reset && !prev_.reset) {
        value = 1.0;
        changed = true;
    }
    prev_ = in;
    if (!changed || !std::isfinite(value))
        return std::nullopt;
    value = std::clamp(value, lo_, hi_);
    sent_ = value;
    sent_at_ = now_s;
    return value;
}

}  // namespace hal::halui
