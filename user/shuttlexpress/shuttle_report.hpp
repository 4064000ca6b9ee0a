// SPDX-License-Identifier: GPL-2.0-or-later
// shuttle_report.hpp - the ShuttleXpress's 5-byte HID input report, decoded (pure):
//   byte 0  spring (outer) wheel, signed, -7 .. +7
//   byte 1  jog (inner) wheel, an 8-bit counter that wraps
//   byte 3  buttons 0..3 in bits 4..7;  byte 4  button 4 in bit 0
// and the jog count (shuttlexpress(1): the first report only sets the reference).
#pragma once

#include <cstddef>
#include <cstdint>

namespace hal::shuttle {

constexpr unsigned vendor_id = 0x0b33;
constexpr unsigned product_id = 0x0020;
constexpr size_t report_size = 5;
constexpr int button_count = 5;

struct Report {
    bool buttons[button_count];
    int spring;                  // -7 .. +7
    uint8_t jog;                 // raw counter
};

Report decode_report(const uint8_t (&r)[report_size]);

class JogCounter {
public:
    // Accumulated counts after this report's raw counter value.
    int32_t update(uint8_t raw);
    int32_t counts() const { return counts_; }

private:
    bool has_reference_ = false;
    uint8_t last_ = 0;
    int32_t counts_ = 0;
};

}  // namespace hal::shuttle
