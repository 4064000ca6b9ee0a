// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_alias.cpp - alias and unalias (LinuxCNC halcmd): a second name for a pin or a
// parameter. Both names then work in every command; save writes them back as
// "alias pin|param NAME ALIAS" lines (cmd_save.cpp).
#include <cerrno>
#include <string>

#include "commands.hpp"
#include "hal_query.h"
#include "session.hpp"

namespace hal::halcmd {

namespace {

// "pin" or "param"; anything else is refused with the accepted words.
Result<bool> is_param_kind(const char* cmd, const std::string& kind)
{
    if (kind == "pin")
        return false;
    if (kind == "param" || kind == "parameter")
        return true;
    return Error{-EINVAL, std::string(cmd) + ": '" + kind + "' is not 'pin' or 'param'"};
}

}  // namespace

Result<void> cmd_alias(Session& s, Args args)
{
    auto is_param = is_param_kind("alias", args[0]);
    if (!is_param)
        return is_param.error();
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "alias"); !r)
        return r;
    int rc = *is_param ? hal_param_alias(args[1].c_str(), args[2].c_str())
                       : hal_pin_alias(args[1].c_str(), args[2].c_str());
    if (auto r = s.check(rc, "alias " + args[1]); !r)
        return r;
    s.info(args[0] + " '" + args[1] + "' is also called '" + args[2] + "'");
    return ok();
}

Result<void> cmd_unalias(Session& s, Args args)
{
    auto is_param = is_param_kind("unalias", args[0]);
    if (!is_param)
        return is_param.error();
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "unalias"); !r)
        return r;
    int rc = *is_param ? hal_unalias_param(args[1].c_str()) : hal_unalias_pin(args[1].c_str());
    if (auto r = s.check(rc, "unalias " + args[1]); !r)
        return r;
    s.info("alias '" + args[1] + "' removed");
    return ok();
}

}  // namespace hal::halcmd
