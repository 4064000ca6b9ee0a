// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_misc.cpp - echo, help, status, source, quit/exit (halcmd(1)).
#include <cerrno>
#include <cstdio>

#include "commands.hpp"
#include "hal_query.h"
#include "realtime.hpp"
#include "session.hpp"

namespace hal::halcmd {

namespace {

// The layout of LinuxCNC's halcmd, which scripts parse.
void print_lock_status()
{
    int lock = hal_get_lock();
    std::printf("HAL locking status:\n  current lock value %d (%02x)\n", lock, lock);
    if (lock == HAL_LOCK_NONE)
        std::printf("  HAL_LOCK_NONE - nothing is locked\n");
    static const struct {
        int bit;
        const char* text;
    } bits[] = {
        {HAL_LOCK_LOAD, "HAL_LOCK_LOAD    - loading of new components is locked"},
        {HAL_LOCK_CONFIG, "HAL_LOCK_CONFIG  - link and addf is locked"},
        {HAL_LOCK_PARAMS, "HAL_LOCK_PARAMS  - setting params is locked"},
        {HAL_LOCK_RUN, "HAL_LOCK_RUN     - running/stopping HAL is locked"},
    };
    for (const auto& b : bits)
        if (lock & b.bit)
            std::printf("  %s\n", b.text);
}

// Freed records go back to one heap (hal_alloc.c), none is kept per kind for reuse:
// the "recycled" column LinuxCNC prints is always 0 here.
Result<void> print_mem_status()
{
    unsigned long used = 0, total = 0;
    hal_counts n{};
    int rc = hal_memory_usage(&used, &total);
    if (rc >= 0)
        rc = hal_object_counts(&n);
    if (rc < 0)
        return Error{rc, "status: cannot read HAL memory usage"};
    std::printf("HAL memory status\n  used/total shared memory:   %lu/%lu\n", used, total);
    std::printf("  active/recycled components: %d/0\n", n.comps);
    std::printf("  active/recycled pins:       %d/0\n", n.pins);
    std::printf("  active/recycled parameters: %d/0\n", n.params);
    std::printf("  active/recycled aliases:    %d/0\n", n.aliases);
    std::printf("  active/recycled signals:    %d/0\n", n.sigs);
    std::printf("  active/recycled functions:  %d/0\n", n.functs);
    std::printf("  active/recycled threads:    %d/0\n", n.threads);
    return ok();
}

}  // namespace

Result<void> cmd_echo(Session&, Args args)
{
    std::string line;
    for (const std::string& a : args)
        line += (line.empty() ? "" : " ") + a;
    std::printf("%s\n", line.c_str());
    return ok();
}

Result<void> cmd_help(Session&, Args args)
{
    if (!args.empty() && !find_command(args[0]))
        return Error{-EINVAL, "help: no command '" + args[0] + "'"};
    print_help(stdout, args.empty() ? "" : args[0]);
    return ok();
}

Result<void> cmd_status(Session&, Args args)
{
    std::string what = args.empty() ? "all" : args[0];
    if (what != "lock" && what != "mem" && what != "all")
        return Error{-EINVAL, "status: '" + what + "' is not one of lock, mem, all"};
    if (what != "mem")
        print_lock_status();
    if (what != "lock")
        return print_mem_status();
    return ok();
}

Result<void> cmd_debug(Session& s, Args args)
{
    if (args.empty()) {
        std::printf("RTAPI message level: %d\n", rtapi_get_msg_level());
        return ok();
    }
    const std::string& a = args[0];
    if (a.size() != 1 || a[0] < '0' || a[0] > '5')
        return Error{-EINVAL, "debug: '" + a + "' is not a message level (use 0 none, 1 errors, 2 warnings, "
                                                 "3 info, 4 debug or 5 all)"};
    int level = a[0] - '0';
    rtapi_set_msg_level(level);
    if (auto r = rt_set_msg_level(level); !r)
        return r;
    s.info("RTAPI message level set to " + a);
    return ok();
}

Result<void> cmd_setexact(Session& s, Args)
{
    return s.check(hal_set_exact_periods(), "setexact_for_test_suite_only");
}

Result<void> cmd_source(Session& s, Args args)
{
    return s.source(args[0]);
}

Result<void> cmd_quit(Session& s, Args)
{
    s.request_quit();
    return ok();
}

}  // namespace hal::halcmd
