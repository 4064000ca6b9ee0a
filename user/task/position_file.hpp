// SPDX-License-Identifier: GPL-2.0-or-later
// position_file.hpp - [TRAJ]POSITION_FILE (ini-and-launch.md): the joint positions,
// one `%.17f` per line in joint order, written when task exits and read when it
// starts, so a machine without homing finds its joints where they were.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"

namespace hal::task {

// The positions in the file; an empty list when it does not exist (first run). A
// line that is not a number is an error naming FILE:LINE.
Result<std::vector<double>> read_position_file(const std::string& path);

// Writes FILE.new and renames it to FILE, so a crash leaves the old file or the new.
Result<void> write_position_file(const std::string& path, const std::vector<double>& positions);

// The motor offsets that put joint j at positions[j] with its motor where it starts
// (motor-pos-fb 0): SET_JOINT_MOTOR_OFFSET -position (motion.md: pos-fb =
// motor-pos-fb - motor-offset).
std::vector<double> motor_offsets_for(const std::vector<double>& positions);

}  // namespace hal::task
