// SPDX-License-Identifier: GPL-2.0-or-later
// cmd_save.cpp - save (halcmd(1) "save", RULINGS.md "save"): HAL commands that rebuild
// the current HAL when fed to "halcmd -f". Plain "save" prints what halcmd(1) and
// LinuxCNC print: components, aliases, unlinked signals, nets, parameter values,
// thread functions. "save all" adds unconnected input pin values and values of
// undriven signals, so that its output rebuilds the HAL exactly.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <set>
#include <string>

#include "commands.hpp"
#include "hal_query.h"
#include "session.hpp"
#include "snapshot.hpp"
#include "values.hpp"

namespace hal::halcmd {

namespace {

std::string hex8(__u32 v)
{
    char buf[16];
    std::snprintf(buf, sizeof(buf), "%08X", v);
    return buf;
}

struct FileClose {
    void operator()(std::FILE* f) const noexcept
    {
        if (f)
            std::fclose(f);
    }
};
using File = std::unique_ptr<std::FILE, FileClose>;

// One module per line, in load order; arguments as given to loadrt.
void save_comps(std::FILE* out, const Snapshot& h)
{
    std::fprintf(out, "# components\n");
    std::set<std::string> done;
    for (const hal_comp_info& c : h.comps) {
        if (!c.is_realtime)
            continue;                     // userspace programs cannot be restarted from here
        std::string module = c.module[0] ? c.module : c.name;
        if (!done.insert(module).second)
            continue;
        if (c.args[0])
            std::fprintf(out, "loadrt %s %s\n", module.c_str(), c.args);
        else
            std::fprintf(out, "loadrt %s\n", module.c_str());
    }
}

// "alias pin|param NAME ALIAS" lines; LinuxCNC's section titles.
void save_aliases(std::FILE* out, const Snapshot& h)
{
    for (bool params : {false, true}) {
        std::fprintf(out, params ? "# param aliases\n" : "# pin aliases\n");
        for (const hal_alias_info& a : h.aliases)
            if (a.is_param == params)
                std::fprintf(out, "alias %s %s %s\n", params ? "param" : "pin", a.target, a.alias);
    }
}

bool is_unlinked(const hal_sig_info& s)
{
    return s.readers + s.writers + s.bidirs == 0;
}

void save_sigs(std::FILE* out, const Snapshot& h, bool unlinked_only)
{
    std::fprintf(out, "# signals\n");
    for (const hal_sig_info& s : h.sigs)
        if (!unlinked_only || is_unlinked(s))
            std::fprintf(out, "newsig %s %s\n", s.name, type_name(s.type));
}

const char* pin_arrow(hal_pin_dir_t dir)     // seen from the pin: linkps PIN => SIG
{
    return dir == HAL_OUT ? "=>" : dir == HAL_IN ? "<=" : "<=>";
}

const char* sig_arrow(hal_pin_dir_t dir)     // seen from the signal: linksp SIG => PIN
{
    return dir == HAL_OUT ? "<=" : dir == HAL_IN ? "=>" : "<=>";
}

void save_links(std::FILE* out, const Snapshot& h, bool arrows)
{
    std::fprintf(out, "# links\n");
    for (const hal_pin_info& p : h.pins) {
        if (!p.signal[0])
            continue;
        if (arrows)
            std::fprintf(out, "linkps %s %s %s\n", p.name, pin_arrow(p.dir), p.signal);
        else
            std::fprintf(out, "linkps %s %s\n", p.name, p.signal);
    }
}

// Pins of a signal: writer, then bidirectional pins, then readers (each by name).
std::vector<const hal_pin_info*> pins_of(const Snapshot& h, const char* sig)
{
    std::vector<const hal_pin_info*> out;
    for (hal_pin_dir_t dir : {HAL_OUT, HAL_IO, HAL_IN})
        for (const hal_pin_info& p : h.pins)
            if (p.dir == dir && std::strcmp(sig, p.signal) == 0)
                out.push_back(&p);
    return out;
}

void save_nets(std::FILE* out, const Snapshot& h, bool arrows)
{
    std::fprintf(out, "# nets\n");
    for (const hal_sig_info& s : h.sigs) {
        std::fprintf(out, "newsig %s %s\n", s.name, type_name(s.type));
        for (const hal_pin_info* p : pins_of(h, s.name)) {
            if (arrows)
                std::fprintf(out, "linksp %s %s %s\n", s.name, sig_arrow(p->dir), p->name);
            else
                std::fprintf(out, "linksp %s %s\n", s.name, p->name);
        }
    }
}

// "net SIG WRITER => READERS": one line per linked signal.
void save_netl(std::FILE* out, const Snapshot& h, bool arrows)
{
    std::fprintf(out, "# nets\n");
    for (const hal_sig_info& s : h.sigs) {
        auto pins = pins_of(h, s.name);
        if (pins.empty())
            continue;
        std::string line = std::string("net ") + s.name;
        bool readers_started = false;
        for (const hal_pin_info* p : pins) {
            if (arrows && p->dir == HAL_IO)
                line += " <=>";
            if (arrows && p->dir == HAL_IN && !readers_started)
                line += " =>";
            readers_started = readers_started || p->dir == HAL_IN;
            line += std::string(" ") + p->name;
        }
        std::fprintf(out, "%s\n", line.c_str());
    }
}

// LinuxCNC's layout: the value right-aligned in 12 columns, u32 as 0x%08X.
std::string saved_value(hal_type_t type, const hal_value& v)
{
    char buf[48];
    if (type == HAL_U32)
        std::snprintf(buf, sizeof(buf), "%12s", ("0x" + hex8(v.u)).c_str());
    else
        std::snprintf(buf, sizeof(buf), "%12s", format_value(type, v).c_str());
    return buf;
}

void save_params(std::FILE* out, const Snapshot& h)
{
    std::fprintf(out, "# parameter values\n");
    for (const hal_param_info& p : h.params)
        if (p.dir == HAL_RW)
            std::fprintf(out, "setp %s %s\n", p.name, saved_value(p.type, p.value).c_str());
}

void save_unconnected(std::FILE* out, const Snapshot& h)
{
    std::fprintf(out, "# unconnected pin values\n");
    for (const hal_pin_info& p : h.pins)
        if (p.dir != HAL_OUT && !p.signal[0])
            std::fprintf(out, "setp %s %s\n", p.name, saved_value(p.type, p.value).c_str());
}

bool is_zero(const hal_sig_info& s)
{
    switch (s.type) {
    case HAL_BIT: return !s.value.b;
    case HAL_S32: return s.value.s == 0;
    case HAL_U32: return s.value.u == 0;
    case HAL_S64: return s.value.ls == 0;
    case HAL_U64: return s.value.lu == 0;
    default: return s.value.f == 0.0;
    }
}

// Signals nobody drives hold what "sets" gave them; a new signal starts at zero.
void save_sig_values(std::FILE* out, const Snapshot& h)
{
    std::fprintf(out, "# signal values\n");
    for (const hal_sig_info& s : h.sigs)
        if (s.writers == 0 && !is_zero(s))
            std::fprintf(out, "sets %s %s\n", s.name, saved_value(s.type, s.value).c_str());
}

void save_threads(std::FILE* out, const Snapshot& h)
{
    std::fprintf(out, "# realtime thread/function links\n");
    for (const ThreadEntry& t : h.threads)
        for (const std::string& f : t.functs)
            std::fprintf(out, "addf %s %s\n", f.c_str(), t.info.name);
}

void save_item(std::FILE* out, const Snapshot& h, const std::string& item)
{
    if (item == "" || item == "all") {
        save_comps(out, h);
        save_aliases(out, h);
        save_sigs(out, h, true);
        save_netl(out, h, true);
        save_params(out, h);
        if (item == "all") {
            save_unconnected(out, h);
            save_sig_values(out, h);
        }
        save_threads(out, h);
    } else if (item == "alias") {
        save_aliases(out, h);
    } else if (item == "comp") {
        save_comps(out, h);
    } else if (item == "sig" || item == "sigu") {
        save_sigs(out, h, item == "sigu");
    } else if (item == "link" || item == "linka") {
        save_links(out, h, item == "linka");
    } else if (item == "net" || item == "neta") {
        save_nets(out, h, item == "neta");
    } else if (item == "netl" || item == "netla") {
        save_netl(out, h, item == "netla");
    } else if (item == "param") {
        save_params(out, h);
    } else if (item == "unconnected") {
        save_unconnected(out, h);
    } else if (item == "thread") {
        save_threads(out, h);
    }
}

}  // namespace

Result<void> cmd_save(Session&, Args args)
{
    std::string item = args.empty() ? "" : args[0];
    static const std::set<std::string> items = {"", "all", "comp", "alias", "sig", "sigu", "link", "linka", "net", "neta",
                                                "netl", "netla", "param", "unconnected", "thread"};
    if (!items.contains(item))
        return Error{-EINVAL, "save: '" + item +
                                  "' is not one of comp, alias, sig, sigu, link, linka, net, neta, netl, netla, param, "
                                  "unconnected, thread, all"};
    File file;
    std::FILE* out = stdout;
    if (args.size() == 2) {
        file.reset(std::fopen(args[1].c_str(), "w"));
        if (!file)
            return Error{-errno, "save: cannot write '" + args[1] + "': " + std::strerror(errno)};
        out = file.get();
    }
    Snapshot h = take_snapshot();
    save_item(out, h, item);
    if (file && std::fflush(file.get()) != 0)
        return Error{-errno, "save: writing '" + args[1] + "': " + std::strerror(errno)};
    return ok();
}

}  // namespace hal::halcmd
