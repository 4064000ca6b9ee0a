// SPDX-License-Identifier: GPL-2.0-or-later
// hm2_eth_rtt - reads halsampler lines of hm2_eth's three function times (the
// .time pins of read-request, read, write: CPU clocks, rtapi_get_clocks) and prints
// the per-cycle sum, the round trip of one servo cycle, as median and maximum in
// microseconds. The clock is calibrated against CLOCK_MONOTONIC here (the TSC on
// x86; elsewhere rtapi_get_clocks is nanoseconds).
// Usage: halsampler -n N | hm2_eth_rtt
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
static double clocks_per_us()
{
	auto t0 = std::chrono::steady_clock::now();
	unsigned long long c0 = __rdtsc();
	std::this_thread::sleep_for(std::chrono::milliseconds(200));
	unsigned long long c1 = __rdtsc();
	auto t1 = std::chrono::steady_clock::now();
	return (double)(c1 - c0) / std::chrono::duration<double, std::micro>(t1 - t0).count();
}
#else
static double clocks_per_us() { return 1000.0; }
#endif

int main()
{
	std::vector<double> cycle;
	long a, b, c;
	while (std::scanf("%ld %ld %ld", &a, &b, &c) == 3)
		cycle.push_back((double)(a + b + c));
	if (cycle.empty()) {
		std::fprintf(stderr, "hm2_eth_rtt: no samples\n");
		return 1;
	}
	double k = clocks_per_us();
	std::sort(cycle.begin(), cycle.end());
	std::printf("read-request + read + write: median %.1f us, max %.1f us over %zu cycles\n",
		    cycle[cycle.size() / 2] / k, cycle.back() / k, cycle.size());
	return 0;
}
