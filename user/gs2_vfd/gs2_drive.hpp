// SPDX-License-Identifier: GPL-2.0-or-later
// gs2_drive.hpp - the GS2 drive's Modbus registers (GS2 user manual, "communication
// parameters": status monitor block at 0x2100, command registers at 0x091A) and the
// pure arithmetic of gs2_vfd(1): decoding a status block into pin values, turning a
// speed in RPM into a frequency command, the at-speed test. No I/O, unit-tested.
#pragma once

#include <cstdint>

namespace hal::gs2 {

// Status monitor block, read in one request of status_count registers.
constexpr int status_base = 0x2100;
enum StatusReg {
    st_status1 = 0,        // 0x2100 error code
    st_status2,            // 0x2101 drive status bits (run, direction, source of commands)
    st_freq_cmd,           // 0x2102 frequency command, 0.1 Hz
    st_freq_out,           // 0x2103 output frequency, 0.1 Hz
    st_current,            // 0x2104 output current, 0.1 A
    st_dc_bus,             // 0x2105 DC bus voltage, 0.1 V
    st_volts_out,          // 0x2106 output voltage, 0.1 V
    st_rpm,                // 0x2107 motor RPM
    st_scale_lo,           // 0x2108 scale frequency, low word
    st_scale_hi,           // 0x2109 scale frequency, high word
    st_power_factor,       // 0x210A power factor angle, 0.1 degree
    st_load,               // 0x210B load, 0.1 %
    st_firmware,           // 0x210C firmware revision
    status_count
};

// Command registers (written).
constexpr int reg_speed = 0x091A;      // frequency reference, 0.1 Hz
constexpr int reg_run = 0x091B;        // 0 stop, 1 run
constexpr int reg_direction = 0x091C;  // 0 forward, 1 reverse
constexpr int reg_fault_reset = 0x091E;// 1 resets a fault

struct Status {                        // what the output pins show
    int32_t status1, status2, firmware;
    double freq_cmd, freq_out, current, dc_bus, volts_out, rpm, scale_freq, power_factor, load;
    bool is_stopped;
};

Status decode_status(const uint16_t (&regs)[status_count]);

// Frequency reference for the drive, in 0.1 Hz: |rpm| scaled by the nameplate,
// clamped to the register; 0 when the nameplate is unusable.
uint16_t speed_to_register(double rpm, double nameplate_hz, double nameplate_rpm);

// Direction register from the spindle-fwd / spindle-rev pins (gs2_vfd(1)): reverse when
// spindle-rev is set, forward when spindle-fwd is set, reverse otherwise ("0 for REV").
int direction_register(bool fwd, bool rev);

// at-speed: the output frequency is within 'tolerance' (a fraction) of the command,
// and at least ack_delay poll cycles have passed since the command last changed.
bool at_speed(double freq_out, double freq_cmd, double tolerance, int cycles_since_change, int ack_delay);

}  // namespace hal::gs2
