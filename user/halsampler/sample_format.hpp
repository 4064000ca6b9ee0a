// SPDX-License-Identifier: GPL-2.0-or-later
// sample_format.hpp - one FIFO record as halsampler prints it (RULINGS.md): each
// value followed by one space, floats "%f", bits 0/1, integers in decimal;
// with -t the sample number comes first.
#pragma once

#include <string>
#include <string_view>

#include "streamer_fifo.h"

namespace hal {

// rec points at a whole record (HAL_FIFO_REC_HDR_WORDS + cfg.size() words).
std::string format_sample(std::string_view cfg, const hal_fifo_value* rec, bool tag);

}  // namespace hal
