// SPDX-License-Identifier: GPL-2.0-or-later
// python_path.cpp - see python_path.hpp.
#include "python_path.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#ifndef HAL_PYTHON_DIR
#define HAL_PYTHON_DIR "lib/python3/dist-packages"
#endif

namespace hal::halcmd {

namespace fs = std::filesystem;

void export_python_path()
{
    if (std::string(HAL_PYTHON_DIR).empty())
        return;                               // a build without the module
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec)
        return;
    fs::path dir = exe.parent_path().parent_path() / HAL_PYTHON_DIR;
    if (!fs::is_directory(dir, ec))
        return;
    std::string entry = dir.lexically_normal().string();
    const char* old = std::getenv("PYTHONPATH");
    std::string value = entry;
    if (old && *old) {
        // already first (a halcmd run by halrun, or by a script under halrun)
        std::string current(old);
        if (current == entry || current.rfind(entry + ":", 0) == 0)
            return;
        value += ":" + current;
    }
    setenv("PYTHONPATH", value.c_str(), 1);
}

}  // namespace hal::halcmd
