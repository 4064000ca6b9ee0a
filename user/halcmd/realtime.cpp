// SPDX-License-Identifier: GPL-2.0-or-later
// realtime.cpp - see realtime.hpp: one switch per call between the two flavors.
#include "realtime.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "hal/kmod.hpp"
#include "rtapi_client.hpp"
#include "snapshot.hpp"

namespace hal::halcmd {

Result<void> select_flavor(const std::string& forced)
{
    if (!forced.empty() && forced != "kernel" && forced != "sim")
        return Error{-EINVAL, "--flavor=" + forced + ": must be kernel or sim"};
    if (!forced.empty())
        setenv("HAL_FLAVOR", forced.c_str(), 1);
    auto choice = hal::kmod::detect_flavor();
    if (!choice)
        return choice.error();
    setenv("HAL_FLAVOR", hal::kmod::flavor_name(choice->flavor), 1);
    return ok();
}

bool kernel_flavor()
{
    const char* f = std::getenv("HAL_FLAVOR");
    return f && (std::strcmp(f, "kernel") == 0 || std::strcmp(f, "kmod") == 0);
}

Result<void> rt_prepare()
{
    if (!kernel_flavor())
        return ok();
    return hal::kmod::load_core();
}

Result<void> rt_load(const std::string& module, const std::vector<std::string>& args)
{
    if (kernel_flavor())
        return hal::kmod::load_module(module, args);
    return hal::rtapi_load(module, args);
}

Result<void> rt_unload(const std::string& module)
{
    if (!kernel_flavor())
        return hal::rtapi_unload(module);
    // A module whose function is on a thread holds a reference (kernel/rtapi/hal_lib_kmod.c):
    // take its functions off the threads first, as rtapi_app's unload does.
    if (hal::kmod::module_loaded("hal_lib") && hal_attach() == 0)
        hal_release_module(module == "all" ? "" : module.c_str());
    if (auto r = hal::kmod::unload_module(module); !r || module != "all")
        return r;
    // Threads outlive their module until the host goes (threads(9)); rtapi_app
    // deletes them on "unload all", hal_lib.ko when it is unloaded.
    if (!take_snapshot(snap_threads).threads.empty())
        return hal::kmod::reload_hal_lib();
    return ok();
}

Result<void> rt_set_msg_level(int level)
{
    if (!kernel_flavor())
        return hal::rtapi_set_msg_level(level);
    const char* path = "/sys/module/rtapi/parameters/msg_level";
    std::FILE* f = std::fopen(path, "w");
    if (!f) {
        if (errno == ENOENT)
            return ok();                 // rtapi.ko is not loaded
        return Error{-errno, std::string("debug: cannot write ") + path + ": " + std::strerror(errno)};
    }
    std::fprintf(f, "%d\n", level);
    if (std::fclose(f) != 0)
        return Error{-errno, std::string("debug: writing ") + path + ": " + std::strerror(errno)};
    return ok();
}

Result<void> rt_start()
{
    if (kernel_flavor())
        return hal::kmod::load_core();
    return hal::rtapi_start();
}

bool rt_running()
{
    if (kernel_flavor())
        return !hal::kmod::hal_modules().empty();
    return hal::rtapi_running();
}

Result<void> rt_check_host()
{
    if (kernel_flavor())
        return ok();  // the kernel is the host: it cannot die under the HAL
    // rtapi_app listens before it creates anything, and unlinks its socket only
    // after removing everything: realtime objects without a listener are orphans.
    // The usual case (a live host) costs one connect(); the objects are only
    // looked at, for the message, when the host is gone (issue 20: start-up time).
    if (hal::rtapi_running())
        return ok();
    Snapshot h = take_snapshot(snap_comps | snap_threads);
    std::string names;
    size_t n = 0;
    for (const hal_comp_info& c : h.comps) {
        if (!c.is_realtime)
            continue;
        if (n++ < 3)
            names += std::string(names.empty() ? "" : ", ") + c.name;
    }
    for (const ThreadEntry& t : h.threads) {
        if (n++ < 3)
            names += std::string(names.empty() ? "" : ", ") + t.info.name;
    }
    if (n == 0)
        return ok();
    const char* inst = std::getenv("RTAPI_INSTANCE");
    return Error{-EPIPE, "the realtime host (rtapi_app, RTAPI_INSTANCE=" +
                             std::string(inst ? inst : "0") + ") has died, leaving " +
                             std::to_string(n) + " realtime object" + (n == 1 ? "" : "s") +
                             " (" + names + (n > 3 ? ", ..." : "") +
                             ") that no longer run; clean up with 'halrun -U', then load again"};
}

Result<void> rt_shutdown()
{
    if (kernel_flavor())
        return hal::kmod::shutdown();
    return hal::rtapi_shutdown();
}

}  // namespace hal::halcmd
