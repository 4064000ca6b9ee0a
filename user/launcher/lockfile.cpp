// SPDX-License-Identifier: GPL-2.0-or-later
// lockfile.cpp - see lockfile.hpp.
#include "lockfile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace hal::launcher {

std::string lock_path(const std::string& prog)
{
    if (const char* env = std::getenv("EMC_LOCK_FILE"); env && *env)
        return env;
    std::string p = "/tmp/" + std::string(prog == "linuxcnc" ? "linuxcnc" : "emc") + ".lock";
    const char* flavor = std::getenv("HAL_FLAVOR");
    const char* inst = std::getenv("RTAPI_INSTANCE");
    bool kernel = flavor && std::strcmp(flavor, "kernel") == 0;
    if (!kernel && inst && *inst && std::strcmp(inst, "0") != 0)
        p += "." + std::string(inst);
    return p;
}

pid_t lock_owner(const std::string& path)
{
    std::ifstream in(path);
    long pid = 0;
    if (!(in >> pid) || pid <= 0 || pid > INT_MAX)
        return 0;
    return static_cast<pid_t>(pid);
}

bool is_launcher(pid_t pid)
{
    char self[PATH_MAX], other[PATH_MAX];
    ssize_t a = readlink("/proc/self/exe", self, sizeof self - 1);
    ssize_t b = readlink(("/proc/" + std::to_string(pid) + "/exe").c_str(), other, sizeof other - 1);
    if (b < 0)
        return errno == EACCES && kill(pid, 0) == 0;   // someone else's: do not guess it is stale
    if (a < 0)
        return false;
    return std::string(self, static_cast<size_t>(a)) == std::string(other, static_cast<size_t>(b));
}

Result<void> lock_create(const std::string& path)
{
    int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
        return Error{-errno, "cannot create lock file " + path + ": " + std::strerror(errno)};
    std::string text = std::to_string(getpid()) + "\n";
    bool ok = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    close(fd);
    if (!ok) {
        unlink(path.c_str());
        return Error{-EIO, "cannot write lock file " + path};
    }
    return hal::ok();
}

void lock_remove(const std::string& path)
{
    unlink(path.c_str());
}

}  // namespace hal::launcher
