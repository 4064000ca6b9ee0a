// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_signal.cpp - newsig, delsig, linkps, linksp, linkpp, unlinkp, net (halcmd(1)).
// net checks every pin before changing anything and takes its links back if the core
// still refuses one, so a bad line leaves HAL as it was.
#include <cerrno>
#include <cstring>

#include "commands.hpp"
#include "hal_query.h"
#include "session.hpp"
#include "snapshot.hpp"
#include "values.hpp"

namespace hal::halcmd {

namespace {

Result<void> link_pin(Session& s, const std::string& pin, const std::string& sig)
{
    // linkps/linksp: "any previous link to pinname will be broken" (halcmd(1));
    // the HAL core refuses to relink, so unlink first when the signal differs.
    hal_pin_info p;
    hal_sig_info si;
    if (hal_find_pin(pin.c_str(), &p) == 0 && p.signal[0] != '\0' && sig != p.signal &&
        hal_find_sig(sig.c_str(), &si) == 0) {
        if (auto r = s.check(hal_unlink(pin.c_str()), "unlinking pin '" + pin + "'"); !r)
            return r;
    }
    if (auto r = s.check(hal_link(pin.c_str(), sig.c_str()), "linking pin '" + pin + "' to signal '" + sig + "'");
        !r)
        return r;
    s.info("Pin '" + pin + "' linked to signal '" + sig + "'");
    return ok();
}

// The pin that drives sig (error messages only, so a snapshot is fine).
std::string writer_of(const std::string& sig)
{
    for (const hal_pin_info& p : take_snapshot(snap_pins).pins)
        if (sig == p.signal && p.dir == HAL_OUT)
            return p.name;
    return "?";
}

// What net would do to one pin; an error names the pin and the reason.
Result<void> check_net_pin(const std::string& sig, const std::string& pin, hal_type_t type,
                           const std::string& writer, const hal_pin_info& p)
{
    if (p.type != type)
        return Error{-EINVAL, "net " + sig + ": pin '" + pin + "' is " + type_name(p.type) + ", but signal '" +
                                  sig + "' is " + type_name(type)};
    if (p.signal[0] != '\0' && sig != p.signal)
        return Error{-EBUSY, "net " + sig + ": pin '" + pin + "' is already linked to signal '" + p.signal + "'"};
    if (p.dir == HAL_OUT && !writer.empty() && writer != pin)
        return Error{-EBUSY, "net " + sig + ": pin '" + pin + "' would be a second writer of signal '" + sig +
                                 "', which '" + writer + "' already drives"};
    return ok();
}

// Take back what a failed net did: unlink the pins it linked (those still on 'sig')
// and delete the signal if the net created it (which also unlinks).
void undo_net(const std::string& sig, const std::vector<std::string>& linked, bool created)
{
    if (created) {
        hal_signal_delete(sig.c_str());
        return;
    }
    for (const std::string& pin : linked) {
        hal_pin_info p;
        if (hal_find_pin(pin.c_str(), &p) == 0 && sig == p.signal)
            hal_unlink(pin.c_str());
    }
}

}  // namespace

Result<void> cmd_newsig(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "newsig"); !r)
        return r;
    auto type = parse_type_name(args[1]);
    if (!type)
        return Error{-EINVAL, "newsig " + args[0] + ": '" + args[1] + "' is not a type (use bit, s32, u32, s64, u64 or float)"};
    if (auto r = s.check(hal_signal_new(args[0].c_str(), *type), "creating signal '" + args[0] + "'"); !r)
        return r;
    s.info("Signal '" + args[0] + "' created");
    return ok();
}

Result<void> cmd_delsig(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "delsig"); !r)
        return r;
    if (auto r = s.check(hal_signal_delete(args[0].c_str()), "deleting signal '" + args[0] + "'"); !r)
        return r;
    s.info("Signal '" + args[0] + "' deleted");
    return ok();
}

Result<void> cmd_linkps(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "linkps"); !r)
        return r;
    return link_pin(s, args[0], args[1]);
}

Result<void> cmd_linksp(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "linksp"); !r)
        return r;
    return link_pin(s, args[1], args[0]);
}

Result<void> cmd_linkpp(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "linkpp"); !r)
        return r;
    hal_pin_info p;
    if (hal_find_pin(args[0].c_str(), &p) != 0)
        return Error{-ENOENT, "linkpp: pin '" + args[0] + "' does not exist"};
    if (auto r = s.check(hal_signal_new(args[0].c_str(), p.type), "creating signal '" + args[0] + "'"); !r)
        return r;
    for (const std::string& pin : {args[0], args[1]}) {
        if (auto r = link_pin(s, pin, args[0]); !r) {
            hal_signal_delete(args[0].c_str());   // undo: also unlinks the first pin
            return r;
        }
    }
    return ok();
}

Result<void> cmd_unlinkp(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "unlinkp"); !r)
        return r;
    if (auto r = s.check(hal_unlink(args[0].c_str()), "unlinking pin '" + args[0] + "'"); !r)
        return r;
    s.info("Pin '" + args[0] + "' unlinked");
    return ok();
}

Result<void> cmd_net(Session& s, Args args)
{
    if (auto r = require_unlocked(HAL_LOCK_CONFIG, "net"); !r)
        return r;
    const std::string& sig = args[0];
    hal_sig_info si;
    bool exists = hal_find_sig(sig.c_str(), &si) == 0;
    std::vector<hal_pin_info> pins(args.size() - 1);
    for (size_t i = 1; i < args.size(); i++) {
        if (hal_find_pin(args[i].c_str(), &pins[i - 1]) != 0) {
            std::string what = "net " + sig + ": pin '" + args[i] + "' does not exist";
            hal_sig_info other;
            if (hal_find_sig(args[i].c_str(), &other) == 0)
                what += " ('" + args[i] + "' is a signal; net takes one signal, then pins)";
            return Error{-ENOENT, what};
        }
    }
    hal_type_t type = exists ? si.type : pins[0].type;
    std::string writer = exists && si.writers > 0 ? writer_of(sig) : "";
    for (size_t i = 0; i < pins.size(); i++) {
        if (auto r = check_net_pin(sig, args[i + 1], type, writer, pins[i]); !r)
            return r;
        if (pins[i].dir == HAL_OUT && writer.empty())
            writer = args[i + 1];
    }
    if (!exists) {
        if (auto r = s.check(hal_signal_new(sig.c_str(), type), "creating signal '" + sig + "'"); !r)
            return r;
        s.info("Signal '" + sig + "' created");
    }
    // All or nothing (issue 19, item 7): the core may still refuse a link that the
    // checks above passed (another process changed the HAL meanwhile, or a rule only
    // the core knows); then the links this net made are taken back.
    std::vector<std::string> linked;
    for (size_t i = 1; i < args.size(); i++) {
        if (sig == pins[i - 1].signal)
            continue;                     // already on this signal: nothing to do
        auto r = s.check(hal_link(args[i].c_str(), sig.c_str()),
                         "linking pin '" + args[i] + "' to signal '" + sig + "'");
        if (!r) {
            undo_net(sig, linked, !exists);
            return r;
        }
        linked.push_back(args[i]);
        s.info("Pin '" + args[i] + "' linked to signal '" + sig + "'");
    }
    return ok();
}

}  // namespace hal::halcmd
