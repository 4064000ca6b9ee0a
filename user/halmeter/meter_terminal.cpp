// SPDX-License-Identifier: GPL-2.0-or-later
// meter_terminal.cpp - halmeter's terminal mode; see meter_terminal.hpp.
#include "meter_terminal.hpp"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "meter_source.hpp"

namespace hal::meter {

namespace {

volatile sig_atomic_t stop_requested = 0;

void on_signal(int) { stop_requested = 1; }

}  // namespace

std::string terminal_update(const Item& item, const std::string& value, bool in_place)
{
    if (in_place)
        return "\r" + item.name + " = " + value + "\033[K";
    return value + "\n";
}

int run_terminal(const MeterOptions& o)
{
    struct sigaction sa = {};
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    bool in_place = !o.lines && isatty(STDOUT_FILENO);
    auto next = std::chrono::steady_clock::now();
    int status = 0;
    for (long n = 0; !stop_requested && (o.count == 0 || n < o.count); n++) {
        if (n > 0) {
            next += std::chrono::milliseconds(o.interval_ms);
            std::this_thread::sleep_until(next);
            if (stop_requested)
                break;
        }
        auto v = read_item(o.item);
        if (!v) {
            std::fprintf(stderr, "%shalmeter: %s\n", in_place ? "\n" : "", v.error().message.c_str());
            return 1;
        }
        std::fputs(terminal_update(o.item, *v, in_place).c_str(), stdout);
        std::fflush(stdout);
    }
    if (in_place)
        std::fputc('\n', stdout);
    return status;
}

}  // namespace hal::meter
