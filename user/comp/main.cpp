// SPDX-License-Identifier: GPL-2.0-or-later
// main.cpp - comp(1) / halcompile: build, compile and install HAL components.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <span>

#include "build.hpp"
#include "options.hpp"

int main(int argc, char** argv)
{
    std::string prog = std::filesystem::path(argv[0]).filename().string();
    auto opts = hal::comp::parse_options(std::span(argv, argc));
    if (!opts) {
        std::fprintf(stderr, "%s: %s\n%s", prog.c_str(), opts.error().message.c_str(),
                     hal::comp::usage(prog).c_str());
        return 2;
    }
    if (opts->help) {
        std::fputs(hal::comp::usage(prog).c_str(), stdout);
        return 0;
    }
    try {
        hal::comp::Paths paths = hal::comp::find_paths();
        for (const auto& f : opts->files) {
            if (auto r = hal::comp::process_file(*opts, f, paths); !r) {
                std::fprintf(stderr, "%s\n", r.error().message.c_str());
                return 1;
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", prog.c_str(), e.what());
        return 1;
    }
    return 0;
}
