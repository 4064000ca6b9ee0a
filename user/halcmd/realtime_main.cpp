// SPDX-License-Identifier: GPL-2.0-or-later
// realtime_main.cpp - realtime(1) as LinuxCNC scripts call it: "realtime start" brings
// up the realtime environment without loading a component (rtapi_app in the simulated
// flavor, rtapi.ko + hal_lib.ko in the kernel flavor), "stop" ends it like "halrun -U",
// "restart" is both, "status" prints whether it runs (exit 0) or not (exit 1).
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "realtime.hpp"
#include "teardown.hpp"

namespace {

using namespace hal::halcmd;

int usage(std::FILE* out)
{
    std::fputs("usage: realtime start|stop|restart|status\n"
               "  start    start the realtime environment (rtapi_app, or rtapi.ko and hal_lib.ko)\n"
               "  stop     stop threads, unload every component, end the realtime environment\n"
               "  restart  stop, then start\n"
               "  status   print whether it runs; exit status 0 if it does, 1 if not\n"
               "The flavor follows HAL_FLAVOR=kernel|sim (default: detected), the simulated\n"
               "instance RTAPI_INSTANCE.\n",
               out);
    return out == stdout ? 0 : 1;
}

int fail(const std::string& msg)
{
    std::fprintf(stderr, "realtime: %s\n", msg.c_str());
    return 1;
}

int start()
{
    if (rt_running())
        return 0;                        // already up: nothing to do, as LinuxCNC's script
    if (auto r = rt_start(); !r)
        return fail(r.error().message);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2)
        return usage(stderr);
    std::string cmd = argv[1];
    if (cmd == "-h" || cmd == "--help")
        return usage(stdout);
    try {
        if (auto r = select_flavor(""); !r)
            return fail(r.error().message);
        if (cmd == "start")
            return start();
        if (cmd == "stop")
            return force_exit("realtime");
        if (cmd == "restart") {
            force_exit("realtime");
            return start();
        }
        if (cmd == "status") {
            bool running = rt_running();
            std::printf("Realtime %s (%s flavor)\n", running ? "running" : "not running",
                        kernel_flavor() ? "kernel" : "simulated");
            return running ? 0 : 1;
        }
        fail("unknown command '" + cmd + "'");
        return usage(stderr);
    } catch (const std::exception& e) {
        return fail(std::string("internal error: ") + e.what());
    }
}
