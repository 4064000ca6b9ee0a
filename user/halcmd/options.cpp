// SPDX-License-Identifier: GPL-2.0-or-later
// options.cpp - getopt-style parsing of halcmd/halrun options (halcmd(1) OPTIONS),
// written as a pure function: clustered flags (-kf), "-i FILE" or "-iFILE", "--".
#include "options.hpp"

namespace hal::halcmd {

static Error usage_error(std::string msg)
{
    return Error{-22, std::move(msg) + " (try 'halcmd -h')"};
}

// "--flavor=F" or "--flavor F" at args[i] (i moves past F).
static Result<std::string> take_flavor(std::span<const std::string> args, size_t& i)
{
    const std::string& a = args[i];
    std::string f;
    if (a.rfind("--flavor=", 0) == 0)
        f = a.substr(9);
    else if (a == "--flavor" && i + 1 < args.size())
        f = args[++i];
    else if (a == "--flavor")
        return usage_error("option --flavor needs kernel or sim");
    else
        return usage_error("unknown option '" + a + "'");
    if (f != "kernel" && f != "sim")
        return usage_error("--flavor=" + f + ": must be kernel or sim");
    return f;
}

Result<Options> parse_halcmd_options(std::span<const std::string> args)
{
    Options o;
    size_t i = 0;
    for (; i < args.size(); i++) {
        const std::string& a = args[i];
        if (a == "--") {
            i++;
            break;
        }
        if (a.rfind("--flavor", 0) == 0) {
            auto f = take_flavor(args, i);
            if (!f)
                return f.error();
            o.flavor = *f;
            continue;
        }
        if (a.size() < 2 || a[0] != '-')
            break;                       // first command word
        for (size_t k = 1; k < a.size(); k++) {
            switch (a[k]) {
            case 'f': o.from_file = true; break;
            case 'k': o.keep_going = true; break;
            case 'q': o.verbosity = Verbosity::errors; break;
            case 'Q': o.verbosity = Verbosity::silent; break;
            case 'v': o.verbosity = Verbosity::verbose; break;
            case 'V': o.verbosity = Verbosity::debug; break;
            case 's': o.script_mode = true; break;
            case 'R': o.release_mutex = true; break;
            case 'h': o.help = true; break;
            case 'i':
                if (k + 1 < a.size()) {
                    o.inifile = a.substr(k + 1);
                } else if (i + 1 < args.size()) {
                    o.inifile = args[++i];
                } else {
                    return usage_error("option -i needs an inifile argument");
                }
                k = a.size();            // the rest of this word was the argument
                break;
            case 'I':
                return usage_error("option -I is for halrun only and must come first");
            case 'U':
                return usage_error("option -U is for halrun only and must be its only argument");
            default:
                return usage_error(std::string("unknown option '-") + a[k] + "'");
            }
        }
    }
    std::vector<std::string> rest(args.begin() + static_cast<long>(i), args.end());
    if (o.help) {
        if (rest.size() > 1)
            return usage_error("-h takes at most one command name");
        if (!rest.empty())
            o.help_topic = rest[0];
        return o;
    }
    if (o.from_file) {
        // halcmd(1): the rest of the command line after the file is ignored.
        if (!rest.empty())
            o.file = rest[0];
        return o;
    }
    o.command = std::move(rest);
    return o;
}

static bool ends_with(const std::string& s, std::string_view suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Result<HalrunOptions> parse_halrun_options(std::span<const std::string> args)
{
    HalrunOptions h;
    std::string flavor;
    size_t skip = 0;                     // leading --flavor options
    while (skip < args.size() && args[skip].rfind("--flavor", 0) == 0) {
        auto f = take_flavor(args, skip);
        if (!f)
            return f.error();
        flavor = *f;
        skip++;
    }
    args = args.subspan(skip);
    h.halcmd.flavor = flavor;
    for (size_t i = 0; i < args.size(); i++) {
        if (args[i] == "-U") {
            if (args.size() != 1)
                return Error{-22, "-U must be the only argument of halrun"};
            h.force_exit = true;
            return h;
        }
        if (args[i] == "-I" && i > 0)
            return Error{-22, "-I must precede all other arguments of halrun"};
    }
    std::span<const std::string> rest = args;
    if (!rest.empty() && rest[0] == "-I") {
        h.interactive = true;
        rest = rest.subspan(1);
    }
    auto o = parse_halcmd_options(rest);
    if (!o)
        return o.error();
    h.halcmd = std::move(*o);
    if (h.halcmd.flavor.empty())
        h.halcmd.flavor = flavor;
    // "halrun file.hal" means "halcmd -f file.hal"
    if (!h.halcmd.from_file && h.halcmd.command.size() == 1 && ends_with(h.halcmd.command[0], ".hal")) {
        h.halcmd.from_file = true;
        h.halcmd.file = h.halcmd.command[0];
        h.halcmd.command.clear();
    }
    return h;
}

}  // namespace hal::halcmd
