// SPDX-License-Identifier: GPL-2.0-or-later
// thread_cost - per-function cost of a running HAL thread: time the thread spent
// in its functions divided by (cycles x functions), measured over an interval.
// Usage: thread_cost THREAD SECONDS
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

extern "C" {
#include "hal_query.h"
}

namespace {

int count_functs(const char* thread)
{
    int n = 0;
    hal_query_thread_functs(
        thread, [](const char*, void* ctx) { ++*static_cast<int*>(ctx); return 0; }, &n);
    return n;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: thread_cost THREAD SECONDS\n");
        return 2;
    }
    const char* name = argv[1];
    double seconds = std::atof(argv[2]);
    if (hal_attach() < 0)
        return 1;
    hal_thread_info a{}, b{};
    if (hal_find_thread(name, &a) < 0) {
        std::fprintf(stderr, "thread_cost: thread '%s' does not exist\n", name);
        return 1;
    }
    int functs = count_functs(name);
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    hal_find_thread(name, &b);
    hal_detach();
    unsigned long long cycles = b.cycles - a.cycles;
    if (cycles == 0 || functs == 0) {
        std::fprintf(stderr, "thread_cost: thread '%s' ran %llu cycles with %d functions\n", name,
                     cycles, functs);
        return 1;
    }
    double per_funct = double(b.cpu_ns - a.cpu_ns) / (double(cycles) * functs);
    std::printf("%llu cycles, %d functions, %.1f ns per function call\n", cycles, functs,
                per_funct);
    return 0;
}
