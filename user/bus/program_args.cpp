// SPDX-License-Identifier: GPL-2.0-or-later
// program_args.cpp - the shared command line and stop signals of milltask, io and halui (program_args.hpp).
#include "bus/program_args.hpp"

#include <csignal>
#include <cstdio>

namespace hal::bus {

namespace {
volatile std::sig_atomic_t stop_requested = 0;
void on_stop_signal(int) { stop_requested = 1; }
}  // namespace

volatile std::sig_atomic_t* install_stop_signals()
{
    struct sigaction sa = {};
    sa.sa_handler = on_stop_signal;
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
    return &stop_requested;
}

int parse_program_args(const char* prog, int argc, char** argv, ProgramArgs& out)
{
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if ((a == "-ini" || a == "--ini") && i + 1 < argc) {
            out.ini_path = argv[++i];
        } else if ((a == "-bus" || a == "--bus") && i + 1 < argc) {
            out.bus_path = argv[++i];
        } else if (a == "-h" || a == "--help") {
            std::printf("usage: %s -ini FILE [-bus PATH]\n", prog);
            return 0;
        } else {
            std::fprintf(stderr, "%s: unknown argument '%s'\nusage: %s -ini FILE [-bus PATH]\n", prog,
                         a.c_str(), prog);
            return 2;
        }
    }
    if (out.ini_path.empty()) {
        std::fprintf(stderr, "%s: no INI file given\nusage: %s -ini FILE [-bus PATH]\n", prog, prog);
        return 2;
    }
    return -1;
}

}  // namespace hal::bus
