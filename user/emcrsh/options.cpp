// SPDX-License-Identifier: GPL-2.0-or-later
// options.cpp - emcrsh's command line (options.hpp).
#include "options.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace hal::emcrsh {

const char* usage_text()
{
    return "usage: emcrsh [OPTIONS] [-- -ini INI_FILE [-bus PATH]]\n"
           "  -p, --port PORT          TCP port (default 5007; 0 = any free port)\n"
           "  -n, --name NAME          server name in HELLO ACK (default EMCNETSVR)\n"
           "  -w, --connectpw PW       HELLO password (default EMC)\n"
           "  -e, --enablepw PW        SET ENABLE password (default EMCTOO)\n"
           "  -s, --sessions N         most simultaneous sessions (default -1: no limit)\n"
           "  -d, --path DIR           directory for relative program files (SET OPEN)\n"
           "  -h, --help               this text\n";
}

static bool to_long(const std::string& s, long lo, long hi, long& out)
{
    if (s.empty())
        return false;
    char* end = nullptr;
    errno = 0;
    long v = std::strtol(s.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || v < lo || v > hi)
        return false;
    out = v;
    return true;
}

Result<Options> parse_options(int argc, const char* const* argv)
{
    Options o;
    bool after_dashes = false;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&](std::string& out) -> bool {
            if (i + 1 >= argc)
                return false;
            out = argv[++i];
            return true;
        };
        std::string v;
        if (after_dashes) {
            // EMC options: only the INI file (and our bus path) mean anything here
            if (a == "-ini" || a == "--ini") {
                if (!value(o.ini))
                    return Error{-1, a + ": needs a file name"};
            } else if (a == "-bus" || a == "--bus") {
                if (!value(o.bus))
                    return Error{-1, a + ": needs a socket path"};
            } else {
                return Error{-1, "unknown EMC option '" + a + "' after '--' (only -ini FILE and -bus PATH)"};
            }
            continue;
        }
        if (a == "--") {
            after_dashes = true;
        } else if (a == "-h" || a == "--help") {
            o.help = true;
        } else if (a == "-p" || a == "--port") {
            long n = 0;
            if (!value(v) || !to_long(v, 0, 65535, n))
                return Error{-1, a + ": '" + v + "' is not a port number (0..65535)"};
            o.port = static_cast<int>(n);
        } else if (a == "-s" || a == "--sessions") {
            long n = 0;
            if (!value(v) || !to_long(v, -1, 100000, n) || n == 0)
                return Error{-1, a + ": '" + v + "' is not a number of sessions (-1 or 1..100000)"};
            o.max_sessions = static_cast<int>(n);
        } else if (a == "-n" || a == "--name") {
            if (!value(o.name) || o.name.empty() || o.name.find_first_of(" \t\r\n") != std::string::npos)
                return Error{-1, a + ": needs a name without blanks"};
        } else if (a == "-w" || a == "--connectpw") {
            if (!value(o.connect_pw) || o.connect_pw.empty())
                return Error{-1, a + ": needs a password"};
        } else if (a == "-e" || a == "--enablepw") {
            if (!value(o.enable_pw) || o.enable_pw.empty())
                return Error{-1, a + ": needs a password"};
        } else if (a == "-d" || a == "--path") {
            if (!value(o.path) || o.path.empty())
                return Error{-1, a + ": needs a directory"};
        } else if (a == "-ini" || a == "--ini") {
            // accepted before "--" too (as milltask and io take it)
            if (!value(o.ini))
                return Error{-1, a + ": needs a file name"};
        } else {
            return Error{-1, "unknown option '" + a + "'"};
        }
    }
    return o;
}

}  // namespace hal::emcrsh
