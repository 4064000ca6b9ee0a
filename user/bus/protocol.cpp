// SPDX-License-Identifier: GPL-2.0-or-later
// protocol.cpp - line splitting, the command table, request parsing and the socket
// path rules of the machine bus (docs/bus.md).
#include "bus/protocol.hpp"

#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace hal::bus {

const std::vector<CommandSpec>& commands()
{
    static const std::vector<CommandSpec> table = {
        {"PING", 0, 0, false, ""},
        {"STATUS", 0, 0, false, ""},
        {"STATE", 1, 1, false, "ESTOP|ESTOP_RESET|OFF|ON"},
        {"MODE", 1, 1, false, "MANUAL|AUTO|MDI"},
        {"MDI", 1, 1, true, "G-CODE LINE"},
        {"OPEN", 1, 1, true, "FILE"},
        {"CLOSE", 0, 0, false, ""},
        {"RUN", 0, 1, false, "[LINE]"},
        {"PAUSE", 0, 0, false, ""},
        {"RESUME", 0, 0, false, ""},
        {"STEP", 0, 0, false, ""},
        {"ABORT", 0, 0, false, ""},
        {"PLAN_INIT", 0, 0, false, ""},
        {"OPTIONAL_STOP", 1, 1, false, "0|1"},
        {"BLOCK_DELETE", 1, 1, false, "0|1"},
        {"FEED_OVERRIDE", 1, 1, false, "SCALE"},
        {"RAPID_OVERRIDE", 1, 1, false, "SCALE"},
        {"SPINDLE_OVERRIDE", 1, 2, false, "SCALE [SPINDLE]"},
        {"MAX_VELOCITY", 1, 1, false, "UNITS/S"},
        {"HOME", 1, 1, false, "JOINT|-1"},
        {"UNHOME", 1, 1, false, "JOINT|-1"},
        {"JOG_CONT", 2, 2, false, "JOINT|AXIS VEL"},
        {"JOG_INCR", 3, 3, false, "JOINT|AXIS VEL DISTANCE"},
        {"JOG_ABS", 3, 3, false, "JOINT|AXIS VEL POSITION"},
        {"JOG_STOP", 1, 1, false, "JOINT|AXIS"},
        {"TELEOP", 1, 1, false, "0|1"},
        {"OVERRIDE_LIMITS", 1, 1, false, "JOINT|-1"},
        {"MIST", 1, 1, false, "ON|OFF"},
        {"FLOOD", 1, 1, false, "ON|OFF"},
        {"LUBE", 1, 1, false, "ON|OFF"},
        {"SPINDLE", 1, 3, false, "FORWARD|REVERSE|OFF|INCREASE|DECREASE|CONSTANT [RPM [SPINDLE]]"},
        {"BRAKE", 1, 2, false, "ON|OFF [SPINDLE]"},
        {"TOOL_OFFSET", 3, 3, false, "TOOL LENGTH DIAMETER"},
        {"LOAD_TOOL_TABLE", 0, 1, true, "[FILE]"},
        {"PROBE_CLEAR", 0, 0, false, ""},
        {"DEBUG", 1, 1, false, "LEVEL"},
    };
    return table;
}

static std::string upper(std::string_view s)
{
    std::string r(s);
    for (char& c : r)
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
    return r;
}

const CommandSpec* find_command(std::string_view name)
{
    const std::string u = upper(name);
    for (const CommandSpec& c : commands())
        if (u == c.name)
            return &c;
    return nullptr;
}

static bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::vector<std::string> split_words(std::string_view s, size_t max_words)
{
    std::vector<std::string> out;
    size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && is_blank(s[i]))
            ++i;
        if (i >= s.size())
            break;
        if (max_words > 0 && out.size() + 1 == max_words) {
            out.emplace_back(s.substr(i));
            break;
        }
        size_t j = i;
        while (j < s.size() && !is_blank(s[j]))
            ++j;
        out.emplace_back(s.substr(i, j - i));
        i = j;
    }
    return out;
}

bool is_printable(std::string_view s)
{
    for (unsigned char c : s)
        if ((c < 0x20 && c != '\t') || c == 0x7f)
            return false;
    return true;
}

std::string sanitize(std::string_view s, size_t max_len)
{
    std::string r;
    for (unsigned char c : s) {
        if (r.size() >= max_len) {
            r += "...";
            break;
        }
        r += ((c < 0x20 && c != '\t') || c == 0x7f) ? '?' : static_cast<char>(c);
    }
    return r;
}

Result<Request> parse_request(std::string_view line)
{
    if (!is_printable(line))
        return Error{-1, "control characters in the line"};
    std::vector<std::string> head = split_words(line, 3);
    if (head.empty())
        return Error{-1, "empty line"};
    Request r;
    const std::string& s = head[0];
    char* end = nullptr;
    errno = 0;
    long serial = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno != 0 || serial < 1 || serial > MAX_SERIAL || s[0] == '+')
        return Error{-1, "bad serial '" + sanitize(s, 40) + "' (a number 1.." + std::to_string(MAX_SERIAL) + ")"};
    r.serial = serial;
    if (head.size() < 2)
        return Error{-1, "no command after serial " + s};
    const CommandSpec* spec = find_command(head[1]);
    if (!spec)
        return Error{-1, "unknown command '" + sanitize(head[1], 40) + "'"};
    r.verb = spec->name;
    std::string rest = head.size() > 2 ? head[2] : "";
    if (spec->rest_of_line) {
        // trailing blanks of a file name or G-code line are not part of it
        while (!rest.empty() && is_blank(rest.back()))
            rest.pop_back();
        if (!rest.empty())
            r.args.push_back(rest);
    } else {
        r.args = split_words(rest);
    }
    const int n = static_cast<int>(r.args.size());
    if (n < spec->min_args || n > spec->max_args) {
        std::string want = spec->min_args == spec->max_args
                               ? std::to_string(spec->min_args)
                               : std::to_string(spec->min_args) + ".." + std::to_string(spec->max_args);
        return Error{-1, r.verb + ": needs " + want + " argument" + (spec->max_args == 1 ? "" : "s") +
                             (spec->usage[0] ? std::string(" (") + spec->usage + ")" : std::string()) +
                             ", got " + std::to_string(n)};
    }
    return r;
}

void LineBuffer::append(const char* data, size_t n)
{
    buf_.append(data, n);
}

std::optional<std::string> LineBuffer::next(bool* too_long)
{
    *too_long = false;
    for (;;) {
        size_t nl = buf_.find('\n');
        if (skipping_) {
            if (nl == std::string::npos) {
                buf_.clear();
                return std::nullopt;
            }
            buf_.erase(0, nl + 1);
            skipping_ = false;
            continue;
        }
        if (nl == std::string::npos) {
            if (buf_.size() >= MAX_LINE) {
                // no newline within the limit: report once, drop up to the newline
                buf_.clear();
                skipping_ = true;
                *too_long = true;
            }
            return std::nullopt;
        }
        if (nl + 1 > MAX_LINE) {
            buf_.erase(0, nl + 1);
            *too_long = true;
            return std::nullopt;
        }
        std::string line = buf_.substr(0, nl);
        buf_.erase(0, nl + 1);
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        return line;
    }
}

std::string default_socket_path(const std::string& ini_path)
{
    std::string key = "default";
    if (!ini_path.empty()) {
        char real[PATH_MAX];
        std::string p = realpath(ini_path.c_str(), real) ? std::string(real) : ini_path;
        uint64_t h = 1469598103934665603ull;   // FNV-1a
        for (unsigned char c : p) {
            h ^= c;
            h *= 1099511628211ull;
        }
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
        key = hex;
    }
    const char* run = std::getenv("XDG_RUNTIME_DIR");
    std::string dir = (run && run[0] == '/') ? run : "/tmp";
    return dir + "/emcbus-" + std::to_string(getuid()) + "/" + key + ".sock";
}

Result<std::string> resolve_socket_path(const std::string& explicit_path, const std::string& ini_path)
{
    std::string p = explicit_path;
    if (p.empty()) {
        const char* env = std::getenv("EMCBUS");
        if (env && env[0])
            p = env;
    }
    if (p.empty()) {
        std::string ini = ini_path;
        if (ini.empty()) {
            const char* env = std::getenv("INI_FILE_NAME");
            if (env && env[0])
                ini = env;
        }
        if (ini.empty())
            return Error{-1, "no bus given: use -bus PATH or -ini FILE (or set EMCBUS / INI_FILE_NAME)"};
        p = default_socket_path(ini);
    }
    if (p.size() >= 108)
        return Error{-1, "bus socket path too long (" + std::to_string(p.size()) + " bytes, max 107): " + p};
    return p;
}

}  // namespace hal::bus
