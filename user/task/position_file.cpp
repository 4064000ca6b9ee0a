// SPDX-License-Identifier: GPL-2.0-or-later
// position_file.cpp - see position_file.hpp.
#include "position_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace hal::task {

Result<std::vector<double>> read_position_file(const std::string& path)
{
    std::vector<double> out;
    std::ifstream f(path);
    if (!f) {
        if (errno == ENOENT)
            return out;
        return Error{-errno, path + ": cannot read: " + std::strerror(errno)};
    }
    std::string line;
    for (int n = 1; std::getline(f, line); ++n) {
        size_t b = line.find_first_not_of(" \t\r");
        if (b == std::string::npos)
            continue;
        size_t e = line.find_last_not_of(" \t\r");
        std::string word = line.substr(b, e - b + 1);
        char* end = nullptr;
        errno = 0;
        double v = std::strtod(word.c_str(), &end);
        if (*end != '\0' || errno != 0 || !std::isfinite(v))
            return Error{-EINVAL, path + ":" + std::to_string(n) + ": '" + word.substr(0, 40) +
                                      "' is not a joint position"};
        out.push_back(v);
    }
    return out;
}

Result<void> write_position_file(const std::string& path, const std::vector<double>& positions)
{
    std::string tmp = path + ".new";
    FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f)
        return Error{-errno, tmp + ": cannot write: " + std::strerror(errno)};
    for (double p : positions)
        std::fprintf(f, "%.17f\n", p);
    bool good = std::fflush(f) == 0 && !std::ferror(f);
    int err = errno;
    good = std::fclose(f) == 0 && good;
    if (!good) {
        std::remove(tmp.c_str());
        return Error{-err, tmp + ": cannot write: " + std::strerror(err)};
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
        return Error{-errno, path + ": cannot rename " + tmp + ": " + std::strerror(errno)};
    return ok();
}

std::vector<double> motor_offsets_for(const std::vector<double>& positions)
{
    std::vector<double> out;
    for (double p : positions)
        out.push_back(-p);
    return out;
}

}  // namespace hal::task
