// SPDX-License-Identifier: GPL-2.0-or-later
// options.cpp - see options.hpp.
#include "options.hpp"

namespace hal::launcher {

Result<Options> parse_options(std::span<const std::string> args)
{
    Options o;
    for (size_t i = 0; i < args.size(); i++) {
        const std::string& a = args[i];
        if (a == "-" || a.empty() || a[0] != '-') {
            if (!o.inifile.empty() || (o.last && a == "-"))
                return Error{-22, "more than one INI file given ('" + a + "')"};
            if (a == "-")
                o.last = true;
            else
                o.inifile = a;
            continue;
        }
        if (a == "--help") {
            o.help = true;
            continue;
        }
        // Single-letter flags, possibly bundled (-vk); -H takes a value.
        for (size_t k = 1; k < a.size(); k++) {
            switch (a[k]) {
            case 'v': o.verbose = true; break;
            case 'd': o.trace = o.verbose = true; break;
            case 'k': o.keep_going = true; break;
            case 'r': o.no_redirect = true; break;
            case 'l': o.last = true; break;
            case 'h': o.help = true; break;
            case 'H': {
                std::string dir = a.substr(k + 1);
                if (dir.empty()) {
                    if (i + 1 >= args.size())
                        return Error{-22, "-H needs a directory"};
                    dir = args[++i];
                }
                o.hal_dirs.push_back(dir);
                k = a.size();
                break;
            }
            case 't':
            case 'm':
                return Error{-22, std::string("-") + a[k] +
                                      ": this motion controller has its planner and homing built into motmod "
                                      "(no tpmod/homemod to choose)"};
            default:
                return Error{-22, std::string("unknown option '-") + a[k] + "'"};
            }
        }
    }
    if (o.last && !o.inifile.empty())
        return Error{-22, "-l and an INI file given: choose one"};
    return o;
}

std::string usage_text(const std::string& prog)
{
    return "usage: " + prog + " [-v] [-d] [-k] [-r] [-l] [-H DIR]... [-h] [INIFILE | -]\n"
           "  -v       verbose: print each step\n"
           "  -d       debug: print every command run as well\n"
           "  -k       keep going after a failing HAL file or [HAL]HALCMD line\n"
           "  -r       accepted for compatibility (output is never redirected)\n"
           "  -l, -    use the INI file of the last run (~/.emcrc)\n"
           "  -H DIR   search DIR for [HAL]HALFILE names first (repeatable)\n"
           "  -h       this help\n"
           "Starts realtime, [EMCIO]EMCIO, [HAL]HALUI, the [HAL]HALFILEs, [TASK]TASK,\n"
           "[HAL]HALCMD lines, the threads, [APPLICATIONS]APP and [DISPLAY]DISPLAY; when the\n"
           "display exits (or, without one, on SIGINT/SIGTERM) everything is cleaned up.\n";
}

}  // namespace hal::launcher
