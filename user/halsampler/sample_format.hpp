// SPDX-License-Identifier: GPL-2.0-or-later
// sample_format.hpp - one FIFO record as halsampler prints it (RULINGS.md): each
// value followed by one space, floats "%f", bits 0/1, integers in decimal;
// with -t the sample number comes first.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "streamer_fifo.h"

namespace hal {

// Bytes one record can take at most: HAL_FIFO_MAX_PINS values of up to 316
// characters ("%f" of -DBL_MAX) plus a space, the tag, the newline.
inline constexpr std::size_t max_sample_line = HAL_FIFO_MAX_PINS * 318 + 16;

// Writes the line for one record (rec: HAL_FIFO_REC_HDR_WORDS + cfg.size() words)
// at 'out', which has room for max_sample_line bytes; returns the end. The same bytes
// as printf("%f ") etc., made by std::to_chars (issue 20: snprintf was most of
// halsampler's time).
char* format_sample_to(char* out, std::string_view cfg, const hal_fifo_value* rec, bool tag);

// The same line as a string (tests, single records).
std::string format_sample(std::string_view cfg, const hal_fifo_value* rec, bool tag);

}  // namespace hal
