// SPDX-License-Identifier: GPL-2.0-or-later
// io_estop.cpp - see io_estop.hpp.
#include "io_estop.hpp"

#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace hal::task {

void IoEstop::connected()
{
    connected_ = true;
    estop_ = true;
    sync_ = ack_ = 0;
    on_ = false;
}

void IoEstop::disconnected()
{
    connected_ = false;
    estop_ = true;
}

void IoEstop::sent(long serial, bool on)
{
    if (serial > sync_) {
        sync_ = serial;
        on_ = on;
    }
    if (on)
        estop_ = true;
}

void IoEstop::report(bool estop, long ack)
{
    ack_ = ack;
    if (ack >= sync_)
        estop_ = on_ || estop;
}

std::map<std::string, long> parse_iostat(const std::string& body)
{
    std::map<std::string, long> out;
    std::istringstream in(body);
    std::string kv;
    while (in >> kv) {
        size_t eq = kv.find('=');
        if (eq == std::string::npos || eq + 1 >= kv.size())
            continue;
        const char* v = kv.c_str() + eq + 1;
        char* end = nullptr;
        errno = 0;
        long n = std::strtol(v, &end, 10);
        if (*end == '\0' && errno == 0)
            out[kv.substr(0, eq)] = n;
    }
    return out;
}

}  // namespace hal::task
