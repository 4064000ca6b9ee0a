// SPDX-License-Identifier: GPL-2.0-or-later
// overrun_watch.hpp - the realtime host's warning about missed periods: once a
// second it looks at every thread's overrun count (hal_thread_overruns) and prints
// one warning line per thread whose count grew (issue 19, item 3). The same counts
// are on each thread's <name>.overruns pin and in "halcmd show thread".
#pragma once

#include <chrono>
#include <map>
#include <string>

namespace hal {

// The warning for 'missed' more periods of thread 'name' within 'interval_ms'.
std::string overrun_warning(const std::string& name, long long period_ns,
                            unsigned long long missed, unsigned long long total,
                            int interval_ms);

class OverrunWatch {
public:
    using Clock = std::chrono::steady_clock;
    static constexpr int interval_ms = 1000;

    // Milliseconds until the next look (-1: no thread, nothing to watch).
    int ms_to_check(Clock::time_point now) const;
    // Look if it is time; prints through rtapi_print_msg(RTAPI_MSG_WARN).
    void check(Clock::time_point now);
    // For the unit tests: one look at given counts, returning the warnings.
    std::string update(const std::string& name, long long period_ns, unsigned long long total);

private:
    std::map<std::string, unsigned long long> last_;  // per thread, at the last look
    Clock::time_point next_{};
};

}  // namespace hal
