// SPDX-License-Identifier: GPL-2.0-or-later
// completion.cpp - see completion.hpp.
#include "completion.hpp"

#include <algorithm>
#include <cstring>
#include <optional>

#include "line_parser.hpp"

namespace hal::halcmd {

namespace {

struct Line {
    std::string command;
    std::vector<std::string> args;       // complete arguments, arrows removed
    std::string word;                    // the partial word at the cursor
};

Line split(std::string_view s)
{
    std::vector<std::string> words;
    std::string cur;
    for (char c : s) {
        if (c == ' ' || c == '\t') {
            if (!cur.empty())
                words.push_back(std::move(cur));
            cur.clear();
        } else {
            cur += c;
        }
    }
    Line l;
    l.word = cur;
    if (!words.empty()) {
        l.command = words[0];
        for (size_t i = 1; i < words.size(); i++)
            if (!is_arrow(words[i]))
                l.args.push_back(words[i]);
    }
    return l;
}

const hal_pin_info* find_pin(const Snapshot& h, std::string_view name)
{
    for (const auto& p : h.pins)
        if (name == p.name)
            return &p;
    return nullptr;
}

const hal_sig_info* find_sig(const Snapshot& h, std::string_view name)
{
    for (const auto& s : h.sigs)
        if (name == s.name)
            return &s;
    return nullptr;
}

class Collector {
public:
    explicit Collector(std::string_view word) : word_(word) {}
    void add(std::string_view name)
    {
        if (name.substr(0, word_.size()) == word_)
            out_.emplace_back(name);
    }
    void add_all(std::initializer_list<const char*> names)
    {
        for (const char* n : names)
            add(n);
    }
    std::vector<std::string> finish()
    {
        std::sort(out_.begin(), out_.end());
        out_.erase(std::unique(out_.begin(), out_.end()), out_.end());
        return std::move(out_);
    }

private:
    std::string_view word_;
    std::vector<std::string> out_;
};

// Pins a net/link may add: unlinked, of the given type when known, and no second writer.
void add_linkable_pins(Collector& c, const Snapshot& h, std::optional<hal_type_t> type, bool has_writer)
{
    for (const auto& p : h.pins) {
        if (p.signal[0] != '\0')
            continue;
        if (type && p.type != *type)
            continue;
        if (has_writer && p.dir == HAL_OUT)
            continue;
        c.add(p.name);
    }
}

void add_sigs(Collector& c, const Snapshot& h, std::optional<hal_type_t> type)
{
    for (const auto& s : h.sigs)
        if (!type || s.type == *type)
            c.add(s.name);
}

void complete_net(Collector& c, const Snapshot& h, const Line& l)
{
    if (l.args.empty()) {
        add_sigs(c, h, std::nullopt);
        return;
    }
    std::optional<hal_type_t> type;
    bool has_writer = false;
    if (const hal_sig_info* s = find_sig(h, l.args[0])) {
        type = s->type;
        has_writer = s->writers > 0;
    }
    for (size_t i = 1; i < l.args.size(); i++) {
        if (const hal_pin_info* p = find_pin(h, l.args[i])) {
            if (!type)
                type = p->type;
            has_writer = has_writer || p->dir == HAL_OUT;
        }
    }
    add_linkable_pins(c, h, type, has_writer);
}

void complete_show_names(Collector& c, const Snapshot& h, std::string_view item)
{
    bool all = item == "all";
    if (all || item == "comp")
        for (const auto& x : h.comps)
            c.add(x.name);
    if (all || item == "pin")
        for (const auto& x : h.pins)
            c.add(x.name);
    if (all || item == "param")
        for (const auto& x : h.params)
            c.add(x.name);
    if (all || item == "sig")
        for (const auto& x : h.sigs)
            c.add(x.name);
    if (all || item == "funct")
        for (const auto& x : h.functs)
            c.add(x.name);
    if (all || item == "thread")
        for (const auto& x : h.threads)
            c.add(x.info.name);
}

void complete_args(Collector& c, Completion& out, const CompletionSources& src, const Line& l)
{
    const Snapshot& h = *src.hal;
    const std::string& cmd = l.command;
    size_t pos = l.args.size();
    if (cmd == "setp" && pos == 0) {
        for (const auto& p : h.params)
            if (p.dir == HAL_RW)
                c.add(p.name);
        for (const auto& p : h.pins)
            if (p.dir != HAL_OUT && p.signal[0] == '\0')
                c.add(p.name);
    } else if ((cmd == "getp" || cmd == "ptype") && pos == 0) {
        for (const auto& p : h.params)
            c.add(p.name);
        for (const auto& p : h.pins)
            c.add(p.name);
    } else if (cmd == "sets" && pos == 0) {
        for (const auto& s : h.sigs)
            if (s.writers == 0)
                c.add(s.name);
    } else if ((cmd == "gets" || cmd == "stype" || cmd == "delsig") && pos == 0) {
        add_sigs(c, h, std::nullopt);
    } else if (cmd == "linkps" || cmd == "linkpp") {
        if (pos == 0) {
            add_linkable_pins(c, h, std::nullopt, false);
        } else if (pos == 1) {
            const hal_pin_info* p = find_pin(h, l.args[0]);
            // Set in a statement of its own: from a conditional expression, GCC 12 thinks
            // the optional's value may be read uninitialized (-Wmaybe-uninitialized).
            std::optional<hal_type_t> type;
            if (p)
                type = p->type;
            if (cmd == "linkps")
                add_sigs(c, h, type);
            else
                add_linkable_pins(c, h, type, p && p->dir == HAL_OUT);
        }
    } else if (cmd == "linksp") {
        if (pos == 0) {
            add_sigs(c, h, std::nullopt);
        } else if (pos == 1) {
            const hal_sig_info* s = find_sig(h, l.args[0]);
            add_linkable_pins(c, h, s ? std::optional<hal_type_t>(s->type) : std::nullopt,
                              s && s->writers > 0);
        }
    } else if (cmd == "unlinkp" && pos == 0) {
        for (const auto& p : h.pins)
            if (p.signal[0] != '\0')
                c.add(p.name);
    } else if (cmd == "net") {
        complete_net(c, h, l);
    } else if (cmd == "newsig" && pos == 1) {
        c.add_all({"bit", "s32", "u32", "float"});
    } else if (cmd == "addf" || cmd == "delf") {
        if (pos == 0) {
            for (const auto& f : h.functs)
                if (cmd == "addf" || f.users > 0)
                    c.add(f.name);
        } else if (pos == 1) {
            for (const auto& t : h.threads) {
                bool has = std::find(t.functs.begin(), t.functs.end(), l.args[0]) != t.functs.end();
                if (cmd == "addf" || has)
                    c.add(t.info.name);
            }
        }
    } else if (cmd == "show" || cmd == "list") {
        if (pos == 0) {
            c.add_all({"comp", "pin", "sig", "param", "funct", "thread"});
            if (cmd == "show")
                c.add("all");
        } else {
            complete_show_names(c, h, l.args[0]);
        }
    } else if (cmd == "save" && pos == 0) {
        c.add_all({"comp", "sig", "sigu", "link", "linka", "net", "neta", "netl", "netla", "param",
                   "unconnected", "thread", "all"});
    } else if (cmd == "loadrt" && pos == 0) {
        for (const auto& m : src.modules)
            c.add(m);
    } else if (cmd == "unloadrt" && pos == 0) {
        c.add("all");
        for (const auto& x : h.comps)
            if (x.is_realtime)
                c.add(x.module);
    } else if ((cmd == "unload" || cmd == "unloadusr" || cmd == "waitusr") && pos == 0) {
        if (cmd != "waitusr")
            c.add("all");
        for (const auto& x : h.comps)
            if (cmd == "unload" || !x.is_realtime)
                c.add(x.name);
    } else if ((cmd == "lock" || cmd == "unlock") && pos == 0) {
        c.add_all({"none", "load", "config", "params", "run", "all"});
    } else if (cmd == "status" && pos == 0) {
        c.add_all({"lock", "mem", "all"});
    } else if (cmd == "help" && pos == 0) {
        for (const auto& n : src.commands)
            c.add(n);
    } else if (cmd == "source" || cmd == "loadusr") {
        out.filenames = true;
    }
}

}  // namespace

Completion complete(std::string_view before_cursor, const CompletionSources& src)
{
    Line l = split(before_cursor);
    Completion out;
    Collector c(l.word);
    if (l.command.empty()) {
        for (const auto& n : src.commands)
            c.add(n);
    } else if (src.hal) {
        complete_args(c, out, src, l);
    }
    out.candidates = c.finish();
    return out;
}

}  // namespace hal::halcmd
