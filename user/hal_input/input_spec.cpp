// SPDX-License-Identifier: GPL-2.0-or-later
// input_spec.cpp - inputspec parsing and matching; see input_spec.hpp.
#include "input_spec.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace hal::input {

namespace {

bool parse_int(std::string_view s, int& out)
{
    if (s.empty())
        return false;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && out >= 0;
}

bool text_matches(const std::string& pattern, const std::string& text)
{
    return text.find(pattern) != std::string::npos || fnmatch(pattern.c_str(), text.c_str(), 0) == 0;
}

}  // namespace

Result<std::vector<InputSpec>> parse_input_args(std::span<char* const> args)
{
    std::vector<InputSpec> specs;
    std::optional<Features> pending;
    for (size_t i = 1; i < args.size(); i++) {
        std::string a = args[i];
        if (a.size() > 1 && a[0] == '-') {
            Features f{false, false, false, false};
            for (char c : a.substr(1)) {
                switch (c) {
                case 'K': f.keys = true; break;
                case 'R': f.rel = true; break;
                case 'A': f.abs = true; break;
                case 'L': f.leds = true; break;
                default:
                    return Error{-22, "option '" + a + "': '" + std::string(1, c) +
                                          "' is not one of K (keys), R (relative), A (absolute), L (LEDs)"};
                }
            }
            pending = f;
            continue;
        }
        InputSpec s;
        s.text = a;
        if (pending)
            s.features = *pending;
        pending.reset();
        std::string body = a;
        if (!body.empty() && body[0] == '+') {
            s.exclusive = true;
            body.erase(0, 1);
        }
        if (body.empty())
            return Error{-22, "inputspec '" + a + "' names no device"};
        int n;
        if (parse_int(body, n)) {
            s.event_number = n;
        } else {
            size_t colon = body.rfind(':');
            if (colon != std::string::npos && parse_int(std::string_view(body).substr(colon + 1), n)) {
                s.index = n;
                body.erase(colon);
            }
            if (body.empty())
                return Error{-22, "inputspec '" + a + "' names no device"};
            s.pattern = body;
        }
        specs.push_back(s);
    }
    if (pending)
        return Error{-22, "a -KRAL option must be followed by an inputspec"};
    if (specs.empty())
        return Error{-22, "no inputspec given"};
    return specs;
}

std::string format_id(unsigned bus, unsigned vendor, unsigned product, unsigned version)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "Bus=%04x Vendor=%04x Product=%04x Version=%04x", bus & 0xffff,
                  vendor & 0xffff, product & 0xffff, version & 0xffff);
    return buf;
}

bool device_matches(const InputSpec& spec, const DeviceInfo& d)
{
    if (spec.event_number >= 0)
        return d.event_number == spec.event_number;
    return text_matches(spec.pattern, d.name) || text_matches(spec.pattern, d.phys) ||
           text_matches(spec.pattern, d.id);
}

std::optional<DeviceInfo> select_device(const InputSpec& spec, std::vector<DeviceInfo> devices)
{
    std::sort(devices.begin(), devices.end(),
              [](const DeviceInfo& a, const DeviceInfo& b) { return a.event_number < b.event_number; });
    int seen = 0;
    for (const DeviceInfo& d : devices) {
        if (!device_matches(spec, d))
            continue;
        if (spec.event_number >= 0 || seen++ == spec.index)
            return d;
    }
    return std::nullopt;
}

}  // namespace hal::input
