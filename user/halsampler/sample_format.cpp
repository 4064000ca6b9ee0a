// SPDX-License-Identifier: GPL-2.0-or-later
// sample_format.cpp - format one sampler record as a line of halsampler output.
#include "sample_format.hpp"

#include <cinttypes>
#include <cstdio>

namespace hal {

std::string format_sample(std::string_view cfg, const hal_fifo_value* rec, bool tag)
{
    std::string line;
    char buf[400];  // "%f" of DBL_MAX has 316 characters

    if (tag) {
        std::snprintf(buf, sizeof(buf), "%" PRId32 " ",
                      static_cast<int32_t>(rec[HAL_FIFO_REC_SAMPLE].s));
        line += buf;
    }
    const hal_fifo_value* v = rec + HAL_FIFO_REC_HDR_WORDS;
    for (size_t m = 0; m < cfg.size(); m++) {
        switch (hal_fifo_type_of(cfg[m])) {
        case HAL_FIFO_FLOAT:
            std::snprintf(buf, sizeof(buf), "%f ", v[m].f);
            break;
        case HAL_FIFO_BIT:
            std::snprintf(buf, sizeof(buf), "%d ", v[m].u ? 1 : 0);
            break;
        case HAL_FIFO_S32:
            std::snprintf(buf, sizeof(buf), "%" PRId32 " ", static_cast<int32_t>(v[m].s));
            break;
        case HAL_FIFO_U32:
            std::snprintf(buf, sizeof(buf), "%" PRIu32 " ", static_cast<uint32_t>(v[m].u));
            break;
        case HAL_FIFO_S64:
            std::snprintf(buf, sizeof(buf), "%" PRId64 " ", static_cast<int64_t>(v[m].s));
            break;
        case HAL_FIFO_U64:
            std::snprintf(buf, sizeof(buf), "%" PRIu64 " ", static_cast<uint64_t>(v[m].u));
            break;
        default:
            std::snprintf(buf, sizeof(buf), "? ");
            break;
        }
        line += buf;
    }
    line += '\n';
    return line;
}

}  // namespace hal
