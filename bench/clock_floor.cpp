// SPDX-License-Identifier: GPL-2.0-or-later
// clock_floor - what one read of the thread's clock (rtapi_get_clocks: the TSC on
// x86) costs back to back, in its own units: the floor of "clocks per function"
// when every function is timed (one read between two functions). Prints the
// median of 21 runs of 100,000 reads.
#include <algorithm>
#include <cstdio>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>

int main()
{
    std::vector<unsigned long long> sink(1024);
    std::vector<double> runs;
    for (int r = 0; r < 21; r++) {
        unsigned long long a = __rdtsc();
        for (int i = 0; i < 100000; i++)
            sink[i & 1023] = __rdtsc();
        unsigned long long b = __rdtsc();
        runs.push_back(double(b - a) / 100000);
    }
    std::sort(runs.begin(), runs.end());
    std::printf("%.1f\n", runs[runs.size() / 2] + double(sink[0] & 0) );
    return 0;
}
#else
int main()
{
    std::puts("n/a");
    return 0;
}
#endif
