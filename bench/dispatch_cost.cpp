// SPDX-License-Identifier: GPL-2.0-or-later
// dispatch_cost - the thread dispatch figure of issue 20: the thread's Time (CPU
// clocks of one cycle, first function start to last function end) divided by the
// number of functions on it, sampled once per cycle for SECONDS after the thread's
// tmax was reset. Prints the median and the maximum of the samples, and tmax/N.
// Usage: dispatch_cost THREAD SECONDS
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

extern "C" {
#include "hal_query.h"
}

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: dispatch_cost THREAD SECONDS\n");
        return 2;
    }
    const char* name = argv[1];
    double seconds = std::atof(argv[2]);
    if (hal_attach() < 0)
        return 1;
    hal_thread_info t{};
    if (hal_find_thread(name, &t) < 0) {
        std::fprintf(stderr, "dispatch_cost: thread '%s' does not exist\n", name);
        return 1;
    }
    int functs = 0;
    hal_query_thread_functs(
        name, [](const char*, void* ctx) { ++*static_cast<int*>(ctx); return 0; }, &functs);
    std::string tmax_name = std::string(name) + ".tmax";
    hal_value zero{};
    zero.s = 0;
    hal_set_param_value(tmax_name.c_str(), &zero);
    std::vector<double> per_funct;
    auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    unsigned long long last = t.cycles;
    while (std::chrono::steady_clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::microseconds(t.period_ns / 2000 + 1));
        if (hal_find_thread(name, &t) < 0)
            break;
        if (t.cycles != last && t.time > 0)
            per_funct.push_back(double(t.time) / std::max(functs, 1));
        last = t.cycles;
    }
    hal_detach();
    if (per_funct.empty() || functs == 0) {
        std::fprintf(stderr, "dispatch_cost: thread '%s' did not run (%d functions)\n", name,
                     functs);
        return 1;
    }
    std::sort(per_funct.begin(), per_funct.end());
    double median = per_funct[per_funct.size() / 2];
    std::printf("%zu cycles sampled, %d functions: median %.1f, max %.1f clocks per function "
                "(thread tmax %.1f per function, %.2fx the median)\n",
                per_funct.size(), functs, median, per_funct.back(), double(t.tmax) / functs,
                double(t.tmax) / functs / median);
    return 0;
}
