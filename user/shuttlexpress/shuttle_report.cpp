// SPDX-License-Identifier: GPL-2.0-or-later
// shuttle_report.cpp - see shuttle_report.hpp.
#include "shuttle_report.hpp"

namespace hal::shuttle {

Report decode_report(const uint8_t (&r)[report_size])
{
    Report rep{};
    rep.spring = static_cast<int8_t>(r[0]);
    if (rep.spring > 7)
        rep.spring = 7;
    if (rep.spring < -7)
        rep.spring = -7;
    rep.jog = r[1];
    for (int b = 0; b < 4; b++)
        rep.buttons[b] = (r[3] >> (4 + b)) & 1;
    rep.buttons[4] = r[4] & 1;
    return rep;
}

int32_t JogCounter::update(uint8_t raw)
{
    if (has_reference_)
        counts_ += static_cast<int8_t>(static_cast<uint8_t>(raw - last_));   // wraps: 255 -> 0 is +1
    has_reference_ = true;
    last_ = raw;
    return counts_;
}

}  // namespace hal::shuttle
