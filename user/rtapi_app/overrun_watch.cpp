// SPDX-License-Identifier: GPL-2.0-or-later
// overrun_watch.cpp - see overrun_watch.hpp.
#include "overrun_watch.hpp"

#include <algorithm>

#include "hal_host.h"
#include "rtapi.h"

namespace hal {

std::string overrun_warning(const std::string& name, long long period_ns,
                            unsigned long long missed, unsigned long long total,
                            int interval_ms)
{
    return "rtapi_app: thread '" + name + "' (period " + std::to_string(period_ns) +
           " ns) missed " + std::to_string(missed) + " period" + (missed == 1 ? "" : "s") +
           " in the last " + std::to_string(interval_ms) + " ms (" + std::to_string(total) +
           " since it started; pin " + name + ".overruns): it cannot keep up, use a longer "
           "period or fewer functions";
}

int OverrunWatch::ms_to_check(Clock::time_point now) const
{
    if (hal_thread_count() == 0)
        return -1;
    auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(next_ - now).count();
    return static_cast<int>(std::clamp<long long>(ms, 0, interval_ms));
}

std::string OverrunWatch::update(const std::string& name, long long period_ns,
                                 unsigned long long total)
{
    auto it = last_.find(name);
    unsigned long long before = it == last_.end() ? 0 : it->second;
    last_.insert_or_assign(name, total);
    if (total <= before)  // also a thread deleted and made again under the same name
        return "";
    return overrun_warning(name, period_ns, total - before, total, interval_ms);
}

void OverrunWatch::check(Clock::time_point now)
{
    if (now < next_)
        return;
    next_ = now + std::chrono::milliseconds(interval_ms);
    hal_thread_overruns(
        [](const char* name, long long period_ns, unsigned long long overruns, void* ctx) {
            auto* self = static_cast<OverrunWatch*>(ctx);
            std::string w = self->update(name, period_ns, overruns);
            if (!w.empty())
                rtapi_print_msg(RTAPI_MSG_WARN, "%s\n", w.c_str());
        },
        this);
}

}  // namespace hal
