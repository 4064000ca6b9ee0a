// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_show.cpp - show and list (halcmd(1); layouts in RULINGS.md "halcmd output
// formats"). Each table's header is printed with the same format as its rows, so
// columns always line up. -s: no headers, owner names, one line per sig/thread.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "commands.hpp"
#include "hal_query.h"
#include "session.hpp"
#include "snapshot.hpp"
#include "values.hpp"

namespace hal::halcmd {

namespace {

enum class Item { comp, pin, param, sig, funct, thread, alias, all };

std::optional<Item> parse_item(const std::string& s)
{
    if (s == "comp" || s == "component")
        return Item::comp;
    if (s == "pin")
        return Item::pin;
    if (s == "param" || s == "parameter")
        return Item::param;
    if (s == "sig" || s == "signal")
        return Item::sig;
    if (s == "funct" || s == "function")
        return Item::funct;
    if (s == "thread")
        return Item::thread;
    if (s == "alias")
        return Item::alias;
    if (s == "all")
        return Item::all;
    return std::nullopt;
}

using Patterns = std::vector<std::string>;

constexpr const char* comp_fmt = "%5s  %-4s  %-32s  %5s  %s\n";
constexpr const char* pin_fmt = "%*s  %-5s %-4s %12s  %s%s\n";    // also params
// LinuxCNC's signal table: type in 5, value right-aligned in 12, linked pins indented 25.
constexpr const char* sig_fmt = "%-5s  %12s  %s";
constexpr int sig_indent = 25;
constexpr const char* funct_fmt = "%*s  %-16s  %-16s  %-3s  %5s  %s\n";
constexpr const char* thread_fmt = "%11s  %-3s  %-20s  ( %8s, %8s )\n";
constexpr int thread_indent = 18;

void heading(bool script, const char* title)
{
    if (!script)
        std::printf("%s\n", title);
}

void trailer(bool script)
{
    if (!script)
        std::printf("\n");
}

std::string owner_of(bool script, int id, const char* name)
{
    return script ? std::string(name) : std::to_string(id);
}

// Owner column width: ids right-aligned in 5; -s names left-aligned to the longest.
template <typename Info>
int owner_width(bool script, const std::vector<Info>& rows)
{
    if (!script)
        return 5;
    size_t w = 5;
    for (const Info& r : rows)
        w = std::max(w, std::strlen(r.owner));
    return -static_cast<int>(w);
}

void show_comps(const Snapshot& h, const Patterns& pats, bool script)
{
    heading(script, "Loaded HAL Components:");
    if (!script)
        std::printf(comp_fmt, "ID", "Type", "Name", "PID", "State");
    for (auto it = h.comps.rbegin(); it != h.comps.rend(); ++it) {   // newest first
        if (!name_matches(pats, it->name))
            continue;
        std::string pid = it->is_realtime ? "" : std::to_string(it->pid);
        std::printf(comp_fmt, std::to_string(it->id).c_str(), it->is_realtime ? "RT" : "User", it->name,
                    pid.c_str(), it->is_ready ? "ready" : "initializing");
    }
    trailer(script);
}

const char* link_arrow(hal_pin_dir_t dir)
{
    return dir == HAL_OUT ? "==>" : dir == HAL_IN ? "<==" : "<=>";
}

void show_pins(const Snapshot& h, const Patterns& pats, bool script)
{
    heading(script, "Component Pins:");
    if (!script)
        std::printf(pin_fmt, 5, "Owner", "Type", "Dir", "Value", "Name", "");
    int ow = owner_width(script, h.pins);
    for (const hal_pin_info& p : h.pins) {
        if (!name_matches(pats, p.name))
            continue;
        std::string link = p.signal[0] ? std::string(" ") + link_arrow(p.dir) + " " + p.signal : "";
        std::printf(pin_fmt, ow, owner_of(script, p.owner_id, p.owner).c_str(), type_name(p.type),
                    pin_dir_name(p.dir), format_value(p.type, p.value).c_str(), p.name, link.c_str());
    }
    trailer(script);
}

void show_params(const Snapshot& h, const Patterns& pats, bool script)
{
    heading(script, "Parameters:");
    if (!script)
        std::printf(pin_fmt, 5, "Owner", "Type", "Dir", "Value", "Name", "");
    int ow = owner_width(script, h.params);
    for (const hal_param_info& p : h.params) {
        if (!name_matches(pats, p.name))
            continue;
        std::printf(pin_fmt, ow, owner_of(script, p.owner_id, p.owner).c_str(), type_name(p.type),
                    param_dir_name(p.dir), format_value(p.type, p.value).c_str(), p.name, "");
    }
    trailer(script);
}

// Pins on a signal: the writer first, then bidirectional pins, then readers, each by name.
std::vector<const hal_pin_info*> pins_of(const Snapshot& h, const char* sig)
{
    std::vector<const hal_pin_info*> out;
    for (hal_pin_dir_t dir : {HAL_OUT, HAL_IO, HAL_IN})
        for (const hal_pin_info& p : h.pins)
            if (p.dir == dir && std::string_view(sig) == p.signal)
                out.push_back(&p);
    return out;
}

const char* sig_arrow(hal_pin_dir_t dir)
{
    return dir == HAL_OUT ? "<==" : dir == HAL_IN ? "==>" : "<=>";
}

void show_sigs(const Snapshot& h, const Patterns& pats, bool script)
{
    heading(script, "Signals:");
    if (!script) {
        std::printf("%-5s  %12s  %s", "Type", "Value", "Name");
        std::printf("     (linked to)\n");
    }
    for (const hal_sig_info& s : h.sigs) {
        if (!name_matches(pats, s.name))
            continue;
        std::printf(sig_fmt, type_name(s.type), format_value(s.type, s.value).c_str(), s.name);
        for (const hal_pin_info* p : pins_of(h, s.name)) {
            if (script)
                std::printf(" %s %s", sig_arrow(p->dir), p->name);
            else
                std::printf("\n%*s%s %s", sig_indent, "", sig_arrow(p->dir), p->name);
        }
        std::printf("\n");
    }
    trailer(script);
}

std::string hex(__u64 v)
{
    char buf[24];
    std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

void show_functs(const Snapshot& h, const Patterns& pats, bool script)
{
    heading(script, "Exported Functions:");
    if (!script)
        std::printf(funct_fmt, 5, "Owner", "CodeAddr", "Arg", "FP", "Users", "Name");
    int ow = owner_width(script, h.functs);
    for (const hal_funct_info& f : h.functs) {
        if (!name_matches(pats, f.name))
            continue;
        std::printf(funct_fmt, ow, owner_of(script, f.owner_id, f.owner).c_str(), hex(f.code_addr).c_str(),
                    hex(f.arg).c_str(), f.uses_fp ? "YES" : "NO", std::to_string(f.users).c_str(), f.name);
    }
    trailer(script);
}

void show_threads(const Snapshot& h, const Patterns& pats, bool script)
{
    heading(script, "Realtime Threads:");
    if (!script)
        std::printf(thread_fmt, "Period", "FP", "Name", "Time", "Max-Time");
    for (const ThreadEntry& t : h.threads) {
        if (!name_matches(pats, t.info.name))
            continue;
        const char* fp = t.info.uses_fp ? "YES" : "NO";
        if (script) {
            std::printf("%lld %s %s", t.info.period_ns, fp, t.info.name);
            for (const std::string& f : t.functs)
                std::printf(" %s", f.c_str());
            std::printf("\n");
            continue;
        }
        std::printf(thread_fmt, std::to_string(t.info.period_ns).c_str(), fp, t.info.name,
                    std::to_string(t.info.time).c_str(), std::to_string(t.info.tmax).c_str());
        if (t.info.overruns > 0)  // only then: the usual layout stays as scripts know it
            std::printf("%*smissed periods (overruns): %lld\n", thread_indent, "",
                        t.info.overruns);
        int n = 1;
        for (const std::string& f : t.functs)
            std::printf("%*s%2d %s\n", thread_indent, "", n++, f.c_str());
    }
    trailer(script);
}

void show_aliases(const Snapshot& h, const Patterns& pats, bool script)
{
    for (bool params : {false, true}) {
        heading(script, params ? "Parameter Aliases:" : "Pin Aliases:");
        if (!script)
            std::printf(" %-36s  %s\n", "Alias", "Original Name");
        for (const hal_alias_info& a : h.aliases)
            if (a.is_param == params && (name_matches(pats, a.alias) || name_matches(pats, a.target)))
                std::printf(" %-36s  %s\n", a.alias, a.target);
        trailer(script);
    }
}

void list_names(const Snapshot& h, Item item, const Patterns& pats)
{
    std::vector<std::string> names;
    auto add = [&](const char* n) {
        if (name_matches(pats, n))
            names.emplace_back(n);
    };
    switch (item) {
    case Item::comp:
        for (const auto& x : h.comps)
            add(x.name);
        std::sort(names.begin(), names.end());
        break;
    case Item::pin: for (const auto& x : h.pins) add(x.name); break;
    case Item::param: for (const auto& x : h.params) add(x.name); break;
    case Item::sig: for (const auto& x : h.sigs) add(x.name); break;
    case Item::funct: for (const auto& x : h.functs) add(x.name); break;
    case Item::thread: for (const auto& x : h.threads) add(x.info.name); break;
    case Item::alias: for (const auto& x : h.aliases) add(x.alias); break;
    case Item::all: break;
    }
    // LinuxCNC prints every name followed by one space; scripts split on it.
    std::string line;
    for (const std::string& n : names)
        line += n + " ";
    std::printf("%s\n", line.c_str());
}

// What show/list ITEM reads: signals are printed with the pins on them.
unsigned kinds_for(Item item)
{
    switch (item) {
    case Item::comp: return snap_comps;
    case Item::pin: return snap_pins;
    case Item::param: return snap_params;
    case Item::sig: return snap_sigs | snap_pins;
    case Item::funct: return snap_functs;
    case Item::thread: return snap_threads;
    case Item::alias: return snap_aliases;
    default: return snap_all;
    }
}

}  // namespace

Result<void> cmd_show(Session& s, Args args)
{
    Item item = Item::all;
    Patterns pats(args.begin(), args.end());
    if (!args.empty()) {
        if (auto i = parse_item(args[0])) {
            item = *i;
            pats.erase(pats.begin());
        }
    }
    remove_dead_user_components();   // a crashed userspace component is not shown as if alive
    bool all = item == Item::all;
    bool script = s.script_mode();
    // Unmatched names are dropped while reading, except where every row counts: the
    // pins of a signal, and -s, whose owner column is as wide as the longest owner.
    unsigned filtered = script || all || item == Item::sig ? 0u : kinds_for(item);
    Snapshot h = take_snapshot(kinds_for(item), filtered,
                               [&pats](std::string_view n) { return name_matches(pats, n); });
    if (all || item == Item::comp)
        show_comps(h, pats, script);
    if (all || item == Item::pin)
        show_pins(h, pats, script);
    if (all || item == Item::param)
        show_params(h, pats, script);
    if (all || item == Item::sig)
        show_sigs(h, pats, script);
    if (all || item == Item::funct)
        show_functs(h, pats, script);
    if (all || item == Item::thread)
        show_threads(h, pats, script);
    if (item == Item::alias)            // not part of "show all", as before aliases existed
        show_aliases(h, pats, script);
    return ok();
}

Result<void> cmd_list(Session&, Args args)
{
    auto item = parse_item(args[0]);
    if (!item || *item == Item::all)
        return Error{-EINVAL, "list: '" + args[0] + "' is not one of comp, pin, sig, param, funct, thread, alias"};
    Patterns pats(args.begin() + 1, args.end());
    list_names(take_snapshot(kinds_for(*item)), *item, pats);
    return ok();
}

}  // namespace hal::halcmd
