// SPDX-License-Identifier: GPL-2.0-or-later
// hal_errors.hpp - how the Python hal module reports failures. HalError becomes
// hal.error (a RuntimeError subclass, as LinuxCNC's module raises for refusals of
// the HAL itself). The HAL library prints its one-line reason through
// rtapi_print_msg; MessageCapture catches that line so it becomes the exception's
// text instead of stray stderr output.
#pragma once

#include <stdexcept>
#include <string>

namespace hal::py {

struct HalError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// While alive, RTAPI error messages of this process are collected instead of
// printed. Anything else (warnings, info) is passed to the previous handler. Not
// reentrant; the GIL serialises the module's calls.
class MessageCapture {
public:
    MessageCapture();
    ~MessageCapture();
    MessageCapture(const MessageCapture&) = delete;
    MessageCapture& operator=(const MessageCapture&) = delete;

    // The last error line the HAL printed (no newline), or "" if none.
    std::string last_error() const;
};

// Throws HalError: the HAL's own message if it printed one during 'capture',
// else "<what>: <strerror(-rc)>".
[[noreturn]] void fail(const MessageCapture& capture, int rc, const std::string& what);

}  // namespace hal::py
