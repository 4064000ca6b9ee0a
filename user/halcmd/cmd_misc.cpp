// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_misc.cpp - echo, help, status, source, quit/exit (halcmd(1)).
#include <cerrno>
#include <cstdio>

#include "commands.hpp"
#include "hal_query.h"
#include "session.hpp"

namespace hal::halcmd {

namespace {

void print_lock_status()
{
    int lock = hal_get_lock();
    std::printf("HAL locking status:\n  current lock value %d (0x%02x)\n", lock, lock);
    if (lock == HAL_LOCK_NONE)
        std::printf("  nothing is locked\n");
    static const struct {
        int bit;
        const char* text;
    } bits[] = {
        {HAL_LOCK_LOAD, "load: loading and unloading components is locked"},
        {HAL_LOCK_CONFIG, "config: signals, links and thread functions are locked"},
        {HAL_LOCK_PARAMS, "params: setting parameters, pins and signals is locked"},
        {HAL_LOCK_RUN, "run: starting and stopping threads is locked"},
    };
    for (const auto& b : bits)
        if (lock & b.bit)
            std::printf("  %s\n", b.text);
}

Result<void> print_mem_status()
{
    unsigned long used = 0, total = 0;
    int rc = hal_memory_usage(&used, &total);
    if (rc < 0)
        return Error{rc, "status: cannot read HAL memory usage"};
    std::printf("HAL memory status:\n  used/total shared memory: %lu/%lu\n", used, total);
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
