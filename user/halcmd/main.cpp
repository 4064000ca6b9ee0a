// SPDX-License-Identifier: GPL-2.0-or-later
// main.cpp - halcmd: parse options, run the session, map failure to exit status 1.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "input_text.hpp"
#include "options.hpp"
#include "python_path.hpp"
#include "session.hpp"

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    auto opts = hal::halcmd::parse_halcmd_options(args);
    if (!opts) {
        std::fprintf(stderr, "halcmd: %s\n", hal::halcmd::printable(opts.error().message).c_str());
        return 1;
    }
    hal::halcmd::export_python_path();     // for loadusr'd Python components
    try {
        hal::halcmd::Session session(std::move(*opts));
        return session.run();
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "halcmd: internal error: %s\n", e.what());
        return 1;
    }
}
