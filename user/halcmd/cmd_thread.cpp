// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_thread.cpp - addf, delf, start, stop, lock, unlock (halcmd(1), RULINGS.md lock
// levels). "lock X" adds level X to the current lock, "unlock X" removes it.
#include <cerrno>
#include <cstdlib>
#include <optional>

#include "commands.hpp"
#include "hal_query.h"
#include "session.hpp"

namespace hal::halcmd {

namespace {

struct LockLevel {
    const char* name;
    int bits;
};

const LockLevel lock_levels[] = {
    {"none", HAL_LOCK_NONE},     {"load", HAL_LOCK_LOAD}, {"config", HAL_LOCK_CONFIG},
    {"params", HAL_LOCK_PARAMS}, {"run", HAL_LOCK_RUN},   {"all", HAL_LOCK_ALL},
    {"tune", HAL_LOCK_LOAD | HAL_LOCK_CONFIG},   // LinuxCNC's HAL_LOCK_TUNE: params stay settable
};

std::optional<int> parse_lock_level(const std::string& name)
{
    for (const LockLevel& l : lock_levels)
        if (name == l.name)
            return l.bits;
    return std::nullopt;
}

Error bad_level(const char* cmd, const std::string& name)
{
    return Error{-EINVAL, std::string(cmd) + ": '" + name + "' is not a lock level (use none, load, config, tune, params, run or all)"};
}

}  // namespace

Result<void> require_unlocked(int lock_bits, std::string_view command)
{
    int lock = hal_get_lock();
    int held = lock < 0 ? 0 : lock & lock_bits;
    if (held == 0)
        return ok();
    // Worded like the HAL core's own lock refusals (hal_lock.c).
    for (const LockLevel& l : lock_levels)
        if (l.bits != HAL_LOCK_NONE && l.bits != HAL_LOCK_ALL && (held & l.bits) == l.bits)
            return Error{-EPERM, std::string("HAL is locked (") + l.name + "): cannot run '" + std::string(command) +
                                     "'; use 'unlock " + l.name + "' first"};
    return Error{-EPERM, "HAL is locked: cannot run '" + std::string(command) + "'"};
}

Result<void> cmd_addf(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "addf"); !r)
        return r;
    int position = -1;
    if (args.size() == 3) {
        char* end = nullptr;
        long p = std::strtol(args[2].c_str(), &end, 10);
        if (args[2].empty() || *end != '\0' || p == 0 || p < -1000000 || p > 1000000)
            return Error{-EINVAL, "addf: position '" + args[2] + "' is not a nonzero integer"};
        position = static_cast<int>(p);
    }
    int rc = hal_add_funct_to_thread(args[0].c_str(), args[1].c_str(), position);
    if (auto r = s.check(rc, "addf: adding function '" + args[0] + "' to thread '" + args[1] + "'"); !r)
        return r;
    s.info("Function '" + args[0] + "' added to thread '" + args[1] + "'");
    return ok();
}

Result<void> cmd_delf(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "delf"); !r)
        return r;
    int rc = hal_del_funct_from_thread(args[0].c_str(), args[1].c_str());
    if (auto r = s.check(rc, "delf: removing function '" + args[0] + "' from thread '" + args[1] + "'"); !r)
        return r;
    s.info("Function '" + args[0] + "' removed from thread '" + args[1] + "'");
    return ok();
}

Result<void> cmd_start(Session& s, Args)
{
    if (auto r = require_unlocked(HAL_LOCK_RUN, "start"); !r)
        return r;
    if (auto r = s.check(hal_start_threads(), "start: starting threads"); !r)
        return r;
    s.info("Realtime threads started");
    return ok();
}

Result<void> cmd_stop(Session& s, Args)
{
    if (auto r = require_unlocked(HAL_LOCK_RUN, "stop"); !r)
        return r;
    if (auto r = s.check(hal_stop_threads(), "stop: stopping threads"); !r)
        return r;
    s.info("Realtime threads stopped");
    return ok();
}

Result<void> cmd_lock(Session& s, Args args)
{
    std::string level = args.empty() ? "all" : args[0];
    auto bits = parse_lock_level(level);
    if (!bits)
        return bad_level("lock", level);
    int now = hal_get_lock();
    int want = *bits == HAL_LOCK_NONE ? HAL_LOCK_NONE : (now | *bits);
    if (auto r = s.check(hal_set_lock(static_cast<unsigned char>(want)), "lock: setting lock level"); !r)
        return r;
    s.info("HAL lock set to " + std::to_string(want));
    return ok();
}

Result<void> cmd_unlock(Session& s, Args args)
{
    std::string level = args.empty() ? "all" : args[0];
    auto bits = parse_lock_level(level);
    if (!bits)
        return bad_level("unlock", level);
    int want = hal_get_lock() & ~*bits;
    if (auto r = s.check(hal_set_lock(static_cast<unsigned char>(want)), "unlock: setting lock level"); !r)
        return r;
    s.info("HAL lock set to " + std::to_string(want));
    return ok();
}

}  // namespace hal::halcmd
