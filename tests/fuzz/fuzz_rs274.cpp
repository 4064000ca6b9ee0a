// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_rs274 - the RS274NGC interpreter (user/interp) on any bytes as a program and as
// an MDI line: no crash, no hang (loop and block limits), bounded memory (line length,
// expression depth, call depth, named-parameter count), no files written.
#include <cstdint>
#include <ostream>
#include <streambuf>
#include <string>

#include "rs274/interp.hpp"
#include "rs274/print_canon.hpp"

namespace {
// Discards what the printing canon writes (its formatting still runs).
class NullBuf : public std::streambuf {
protected:
	int overflow(int c) override { return c; }
	std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	std::string text(reinterpret_cast<const char*>(data), size);
	NullBuf buf;
	std::ostream out(&buf);
	rs274::Config cfg;
	cfg.axes = "XYZABC";
	cfg.file_output = false;
	cfg.max_loop_iterations = 2000;
	cfg.max_blocks = 20000;
	cfg.max_file_lines = 5000;
	rs274::PrintCanon canon(out, cfg.axes);
	rs274::Interp interp(canon, cfg);
	if (!interp.init())
		return 0;
	(void)interp.execute_mdi(text.substr(0, text.find('\n')));
	if (interp.open_text("fuzz.ngc", text))
		(void)interp.run();
	return 0;
}
