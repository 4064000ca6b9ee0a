// SPDX-License-Identifier: GPL-2.0-or-later
// teardown.cpp - see teardown.hpp.
#include "teardown.hpp"

#include <cstdio>
#include <string>

#include "commands.hpp"
#include "hal/kmod.hpp"
#include "hal_query.h"
#include "realtime.hpp"

#if __has_include("rtapi_shmem_uspace.h")
#include "rtapi_shmem_uspace.h"
#else
extern "C" int rtapi_shmem_force_unlink_all(void);
#endif

namespace hal::halcmd {

namespace {

void complain(const char* prog, const std::string& msg)
{
    std::fflush(stdout);
    std::fprintf(stderr, "%s: %s\n", prog, msg.c_str());
}

}  // namespace

// Stop threads, unload userspace components and realtime modules.
// Returns false if something could not be undone (each problem printed once).
bool teardown_attached(const char* prog)
{
    bool ok = true;
    hal_set_lock(HAL_LOCK_NONE);                 // a locked HAL must not block its own teardown
    if (hal_threads_running())
        hal_stop_threads();
    if (auto r = unload_user_components(nullptr, "all"); !r) {
        complain(prog, r.error().message);
        ok = false;
    }
    if (rt_running()) {
        if (auto r = rt_unload("all"); !r) {
            complain(prog, r.error().message);
            ok = false;
        }
    }
    return ok;
}

// After the last user detached: stop rtapi_app and drop the segments (sim), or
// unload hal_lib and rtapi (kernel), so signals made by halcmd itself do not leak
// into the next session.
bool shutdown_realtime(const char* prog)
{
    bool ok = true;
    if (kernel_flavor() || rt_running()) {
        if (auto r = rt_shutdown(); !r) {
            complain(prog, r.error().message);
            ok = false;
        }
    }
    rtapi_shmem_force_unlink_all();
    return ok;
}

int force_exit(const char* prog)
{
    // kernel: attaching must not load hal_lib just to unload it again
    if ((!kernel_flavor() || hal::kmod::module_loaded("hal_lib")) && hal_attach() == 0) {
        hal_release_mutex();
        teardown_attached(prog);
        hal_detach();
    }
    shutdown_realtime(prog);
    return 0;
}

}  // namespace hal::halcmd
