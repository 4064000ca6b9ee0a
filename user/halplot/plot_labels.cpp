// SPDX-License-Identifier: GPL-2.0-or-later
// plot_labels.cpp - see plot_labels.hpp.
#include "plot_labels.hpp"

#include <utility>

extern "C" {
#include "hal.h"
#include "hal_query.h"
}

namespace hal {

namespace {

// The output pin that writes SIGNAL, or "" (a signal set with sets).
std::string writer_of(const std::string& signal)
{
    std::pair<const std::string*, std::string> ctx{&signal, {}};
    hal_query_pins(
        [](const hal_pin_info* p, void* c) {
            auto* x = static_cast<std::pair<const std::string*, std::string>*>(c);
            if (p->dir == HAL_OUT && *x->first == p->signal) {
                x->second = p->name;
                return 1;
            }
            return 0;
        },
        &ctx);
    return ctx.second;
}

// Period of the thread that runs FUNCT, or 0 when no thread does.
long long thread_period_of(const std::string& funct)
{
    std::vector<std::pair<std::string, long long>> threads;
    hal_query_threads(
        [](const hal_thread_info* t, void* c) {
            static_cast<std::vector<std::pair<std::string, long long>>*>(c)->emplace_back(t->name,
                                                                                          t->period_ns);
            return 0;
        },
        &threads);
    for (const auto& [name, period] : threads) {
        std::pair<const std::string*, bool> ctx{&funct, false};
        hal_query_thread_functs(
            name.c_str(),
            [](const char* f, void* c) {
                auto* x = static_cast<std::pair<const std::string*, bool>*>(c);
                x->second = x->second || *x->first == f;
                return x->second ? 1 : 0;
            },
            &ctx);
        if (ctx.second)
            return period;
    }
    return 0;
}

}  // namespace

Result<SamplerContext> sampler_context(int channel, const std::string& cfg)
{
    SamplerContext sc;
    std::string base = "sampler." + std::to_string(channel);
    sc.period_ns = thread_period_of(base);
    if (sc.period_ns <= 0)
        return Error{-1, base + " is not on a thread (addf " + base + " THREAD): no time axis"};
    for (size_t k = 0; k < cfg.size(); k++) {
        std::string pin = base + ".pin." + std::to_string(k);
        hal_pin_info info{};
        std::string label = pin;
        if (hal_find_pin(pin.c_str(), &info) == 0 && info.signal[0]) {
            std::string writer = writer_of(info.signal);
            label = writer.empty() ? std::string(info.signal) : writer;
        }
        char t = cfg[k];
        sc.channels.push_back({label, static_cast<char>(t >= 'A' && t <= 'Z' ? t - 'A' + 'a' : t)});
    }
    return sc;
}

}  // namespace hal
