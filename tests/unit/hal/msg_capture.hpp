// SPDX-License-Identifier: GPL-2.0-or-later
// msg_capture.hpp - collects RTAPI messages while a test runs, so error paths can
// check the one line they print (STYLE.md: every message has a test).
#pragma once
#include <string>
#include <vector>

#include "rtapi.h"

namespace hal_test {

class MsgCapture {
public:
    MsgCapture() : prev_(rtapi_get_msg_handler()) { lines().clear(); rtapi_set_msg_handler(&MsgCapture::handle); }
    ~MsgCapture() { rtapi_set_msg_handler(prev_); }
    MsgCapture(const MsgCapture&) = delete;
    MsgCapture& operator=(const MsgCapture&) = delete;

    // Everything printed since construction or the last clear(), one string per call.
    std::string text() const
    {
        std::string all;
        for (const auto& l : lines())
            all += l;
        return all;
    }
    void clear() { lines().clear(); }

private:
    static std::vector<std::string>& lines()
    {
        static std::vector<std::string> store;   // the handler has no context argument
        return store;
    }
    static void handle(msg_level_t, const char* msg) { lines().emplace_back(msg); }

    rtapi_msg_handler_t prev_;
};

}  // namespace hal_test
