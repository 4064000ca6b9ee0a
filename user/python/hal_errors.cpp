// SPDX-License-Identifier: GPL-2.0-or-later
// hal_errors.cpp - see hal_errors.hpp.
#include "hal_errors.hpp"

#include <cstring>

extern "C" {
#include "rtapi.h"
}

namespace hal::py {

namespace {

// Only one capture is active at a time (module calls hold the GIL).
rtapi_msg_handler_t previous_handler = nullptr;
std::string captured;

void capture_handler(msg_level_t level, const char* msg)
{
    if (level != RTAPI_MSG_ERR) {
        if (previous_handler)
            previous_handler(level, msg);
        return;
    }
    std::string line(msg);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
        line.pop_back();
    // Several lines: the first names the object; later ones are usually context.
    if (captured.empty())
        captured = line;
}

}  // namespace

MessageCapture::MessageCapture()
{
    captured.clear();
    previous_handler = rtapi_get_msg_handler();
    rtapi_set_msg_handler(capture_handler);
}

MessageCapture::~MessageCapture()
{
    rtapi_set_msg_handler(previous_handler);
    previous_handler = nullptr;
}

std::string MessageCapture::last_error() const
{
    return captured;
}

void fail(const MessageCapture& capture, int rc, const std::string& what)
{
    std::string msg = capture.last_error();
    if (msg.empty())
        msg = what + ": " + std::strerror(rc < 0 ? -rc : rc);
    throw HalError(msg);
}

}  // namespace hal::py
