// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_drive.cpp - register decoding and speed arithmetic; see gs2_drive.hpp.
#include "gs2_drive.hpp"

#include <cmath>

namespace hal::gs2 {

Status decode_status(const uint16_t (&r)[status_count])
{
    Status s{};
    s.status1 = r[st_status1];
    s.status2 = r[st_status2];
    s.firmware = r[st_firmware];
    s.freq_cmd = r[st_freq_cmd] / 10.0;   // 0.1 units; "/ 10" gives the nearest double (230.1, not 230.10000000000002)
    s.freq_out = r[st_freq_out] / 10.0;
    s.current = r[st_current] / 10.0;
    s.dc_bus = r[st_dc_bus] / 10.0;
    s.volts_out = r[st_volts_out] / 10.0;
    s.rpm = r[st_rpm];
    s.scale_freq = static_cast<double>((static_cast<uint32_t>(r[st_scale_hi]) << 16) | r[st_scale_lo]);
    s.power_factor = r[st_power_factor] / 10.0;
    s.load = r[st_load] / 10.0;
    s.is_stopped = r[st_freq_out] == 0;
    return s;
}

uint16_t speed_to_register(double rpm, double nameplate_hz, double nameplate_rpm)
{
    if (!(nameplate_rpm > 0) || !(nameplate_hz > 0) || !std::isfinite(rpm))
        return 0;
    double tenths = std::fabs(rpm) * nameplate_hz / nameplate_rpm * 10.0;
    if (tenths > 65535.0)
        return 65535;
    return static_cast<uint16_t>(std::lround(tenths));
}

int direction_register(bool fwd, bool rev)
{
    if (rev)
        return 1;
    return fwd ? 0 : 1;
}

bool at_speed(double freq_out, double freq_cmd, double tolerance, int cycles_since_change, int ack_delay)
{
    if (cycles_since_change < ack_delay)
        return false;
    if (freq_cmd == 0)
        return freq_out == 0;
    return std::fabs(freq_out - freq_cmd) <= std::fabs(tolerance * freq_cmd);
}

}  // namespace hal::gs2
