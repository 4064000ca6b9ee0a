// SPDX-License-Identifier: GPL-2.0-or-later
// plot_labels.hpp - what halplot asks the running HAL about sampler.N: a legend
// label per channel and the period of the thread that runs sampler.N.
#pragma once

#include <string>
#include <vector>

#include "hal/result.hpp"
#include "plot_script.hpp"

namespace hal {

struct SamplerContext {
    std::vector<PlotChannel> channels;
    long long period_ns = 0;
};

// Needs hal_attach() done. cfg: the FIFO's channel types.
Result<SamplerContext> sampler_context(int channel, const std::string& cfg);

}  // namespace hal
