// SPDX-License-Identifier: GPL-2.0-or-later
// module_dir.cpp - see module_dir.hpp.
#include "module_dir.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#ifndef HAL_INSTALL_RTLIB
#define HAL_INSTALL_RTLIB "/usr/lib/hal/rtlib"
#endif

namespace hal::halcmd {

namespace fs = std::filesystem;

std::string rtlib_dir()
{
    if (const char* env = std::getenv("HAL_RTLIB_DIR"))
        return env;
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path build = exe.parent_path().parent_path() / "rtlib";
        if (fs::is_directory(build, ec))
            return build.string();
    }
    return HAL_INSTALL_RTLIB;
}

std::vector<std::string> list_modules(const std::string& dir)
{
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        std::string ext = e.path().extension().string();
        if (ext == ".so" || ext == ".ko")
            out.push_back(e.path().stem().string());
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace hal::halcmd
