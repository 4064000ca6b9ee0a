// SPDX-License-Identifier: GPL-2.0-or-later
// interp_bench [LINES] - RS274NGC interpreter throughput (issue 15): generates a program
// of LINES (default 1,000,000) short G1 moves in memory (nothing is written to disk),
// runs it through librs274 with the printing canon writing to a discarding stream, and
// prints blocks per second. Prints figures, never fails on them.
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <streambuf>
#include <string>

#include "rs274/interp.hpp"
#include "rs274/print_canon.hpp"

namespace {
class NullBuf : public std::streambuf {
protected:
	int overflow(int c) override { return c; }
	std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};
double seconds_since(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv)
{
	long lines = argc > 1 ? std::atol(argv[1]) : 1000000;
	std::string prog;
	prog.reserve((size_t)lines * 32);
	prog += "G21 G90 G94 F1000\n";
	char buf[96];
	for (long i = 0; i < lines; i++) {
		// a zig-zag of 0.1 mm steps: every line a real move, different numbers
		std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f Z%.3f\n", (i % 1000) * 0.1, (i / 1000) * 0.1,
		              (i % 7) * -0.01);
		prog += buf;
	}
	prog += "M2\n";

	NullBuf nb;
	std::ostream out(&nb);
	rs274::Config cfg;
	rs274::PrintCanon canon(out, cfg.axes);
	rs274::Interp interp(canon, cfg);
	if (!interp.init()) {
		std::fprintf(stderr, "interp_bench: %s\n", interp.error().to_string().c_str());
		return 1;
	}
	auto t0 = std::chrono::steady_clock::now();
	if (!interp.open_text("bench.ngc", prog)) {
		std::fprintf(stderr, "interp_bench: %s\n", interp.error().to_string().c_str());
		return 1;
	}
	double t_open = seconds_since(t0);
	auto t1 = std::chrono::steady_clock::now();
	std::clock_t c1 = std::clock();   // CPU time too: wall time means little on a loaded machine
	rs274::Status st = interp.run();
	double t_run = seconds_since(t1);
	double cpu_run = double(std::clock() - c1) / CLOCKS_PER_SEC;
	if (st != rs274::Status::END) {
		std::fprintf(stderr, "interp_bench: %s\n", interp.error().to_string().c_str());
		return 1;
	}
	long blocks = lines + 2;
	std::printf("interp: %ld G1 blocks: split into lines %.3f s, interpreted %.3f s = %.0f blocks/s "
	            "(%.0f incl. splitting); CPU %.3f s = %.0f blocks per CPU second\n",
	            lines, t_open, t_run, blocks / t_run, blocks / (t_run + t_open), cpu_run,
	            blocks / cpu_run);
	return 0;
}
