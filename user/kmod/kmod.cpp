// SPDX-License-Identifier: GPL-2.0-or-later
// kmod.cpp - flavor detection and module loading for the kernel flavor (kmod.hpp).
#include "hal/kmod.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

extern char** environ;

namespace hal::kmod {
namespace fs = std::filesystem;

#ifndef HAL_INSTALL_BINDIR
#define HAL_INSTALL_BINDIR "/usr/local/bin"
#endif
#ifndef HAL_KMOD_INSTALL_DIR
#define HAL_KMOD_INSTALL_DIR "/usr/local/lib/hal/modules"
#endif
#ifndef HAL_KMOD_INSTALL_SUBDIR
#define HAL_KMOD_INSTALL_SUBDIR ""
#endif

static std::string kernel_release()
{
    utsname u{};
    return uname(&u) == 0 ? u.release : "";
}

std::string helper_path()
{
    if (const char* env = std::getenv("EMC_MODULE_HELPER"); env && *env)
        return env;
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path beside = self.parent_path() / "emc_module_helper";
        if (fs::exists(beside, ec))
            return beside.string();
    }
    return std::string(HAL_INSTALL_BINDIR) + "/emc_module_helper";
}

Result<FlavorChoice> detect_flavor()
{
    if (const char* env = std::getenv("HAL_FLAVOR"); env && *env) {
        std::string f = env;
        if (f == "kernel" || f == "kmod")
            return FlavorChoice{Flavor::kmod, "HAL_FLAVOR=" + f};
        if (f == "sim" || f == "uspace")
            return FlavorChoice{Flavor::uspace, "HAL_FLAVOR=" + f};
        return Error{-EINVAL, "HAL_FLAVOR='" + f + "': must be kernel or sim"};
    }
    std::error_code ec;
    if (fs::exists("/proc/rtapi", ec))
        return FlavorChoice{Flavor::kmod, "rtapi.ko is loaded"};
    fs::path mods = fs::path(module_dir()) / "rtapi.ko";
    if (fs::exists(mods, ec) && access(helper_path().c_str(), X_OK) == 0)
        return FlavorChoice{Flavor::kmod, "modules installed for kernel " + kernel_release()};
    return FlavorChoice{Flavor::uspace, "no kernel modules for kernel " + kernel_release()};
}

const char* flavor_name(Flavor f)
{
    return f == Flavor::kmod ? "kernel" : "sim";
}

std::string module_dir()
{
    if (const char* env = std::getenv("HAL_KMOD_DIR"); env && *env)
        return env;
    return std::string(HAL_KMOD_INSTALL_DIR) + "/" + kernel_release() + HAL_KMOD_INSTALL_SUBDIR;
}

std::vector<std::string> loaded_modules()
{
    std::vector<std::string> names;
    std::ifstream in("/proc/modules");
    std::string line;
    while (std::getline(in, line))
        names.push_back(line.substr(0, line.find(' ')));
    return names;
}

bool module_loaded(const std::string& name)
{
    for (const auto& n : loaded_modules())
        if (n == name)
            return true;
    return false;
}

HelperRun run_helper(const std::vector<std::string>& argv)
{
    HelperRun r;
    std::string path = helper_path();
    std::vector<char*> cargv{path.data()};
    std::vector<std::string> copy = argv;
    for (auto& a : copy)
        cargv.push_back(a.data());
    cargv.push_back(nullptr);

    int pipefd[2];
    if (pipe2(pipefd, O_CLOEXEC) != 0) {
        r.err = std::string("pipe: ") + std::strerror(errno);
        return r;
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, pipefd[1], STDERR_FILENO);
    pid_t pid;
    int rc = posix_spawn(&pid, path.c_str(), &fa, nullptr, cargv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(pipefd[1]);
    if (rc != 0) {
        close(pipefd[0]);
        r.err = "cannot run " + path + ": " + std::strerror(rc);
        return r;
    }
    char buf[512];
    ssize_t n;
    while ((n = read(pipefd[0], buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR))
        if (n > 0)
            r.err.append(buf, static_cast<size_t>(n));
    close(pipefd[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

static Error helper_error(const std::string& what, const HelperRun& r)
{
    std::string first = r.err.substr(0, r.err.find('\n'));
    if (first.empty())
        first = "emc_module_helper exit status " + std::to_string(r.status);
    return Error{r.status == 2 ? -EPERM : -EIO, what + ": " + first};
}

std::vector<std::string> core_insert_argv(const std::string& core)
{
    std::vector<std::string> argv{"insert", core};
    if (const char* size = std::getenv("HAL_SIZE"); core == "hal_lib" && size && *size)
        argv.push_back(std::string("hal_size=") + size);
    return argv;
}

Result<void> load(const std::string& name, const std::vector<std::string>& args)
{
    for (const char* core : {"rtapi", "hal_lib"}) {
        if (name == core || module_loaded(core))
            continue;
        HelperRun r = run_helper(core_insert_argv(core));
        if (r.status != 0)
            return helper_error(std::string("loadrt ") + core, r);
    }
    std::vector<std::string> argv{"insert", name};
    argv.insert(argv.end(), args.begin(), args.end());
    HelperRun r = run_helper(argv);
    if (r.status != 0)
        return helper_error("loadrt " + name, r);
    return ok();
}

Result<void> unload(const std::string& name)
{
    HelperRun r = run_helper({"remove", name});
    if (r.status != 0)
        return helper_error("unloadrt " + name, r);
    return ok();
}

}  // namespace hal::kmod
