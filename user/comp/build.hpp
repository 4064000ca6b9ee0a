// SPDX-License-Identifier: GPL-2.0-or-later
// build.hpp - what comp does with a file once it is read: write the C or the man page,
// compile a module (simulated flavor: NAME.so with the flags of hal_rt_module; kernel
// flavor: NAME.ko through kbuild) or a userspace program, install them.
#pragma once

#include <string>

#include "hal/result.hpp"
#include "options.hpp"

namespace hal::comp {

// Where things are, from the environment or compiled-in defaults.
struct Paths {
    std::vector<std::string> include_dirs;  // rtapi.h, hal.h, ...
    std::string rtlib_dir;                  // realtime modules
    std::string bin_dir;                    // userspace components
    std::string man9_dir;                   // man pages
    std::vector<std::string> ul_libs;       // static libraries a userspace component links
    std::string flavor;                     // "sim" or "kernel"
};

Paths find_paths();

// Process one input file according to the options (argv[0] names us in messages).
Result<void> process_file(const Options& opts, const std::string& file, const Paths& paths);

}  // namespace hal::comp
