// SPDX-License-Identifier: GPL-2.0-or-later
// fuzz_stream_line - halstreamer's line parser. The first line of the input is the
// streamer's cfg string (as loadrt streamer cfg= gives it), each later line a line
// of values.
#include <cstdint>
#include <string_view>

#include "stream_parse.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string_view text(reinterpret_cast<const char*>(data), size);
    size_t nl = text.find('\n');
    std::string_view cfg = text.substr(0, nl);
    if (cfg.size() > 20)
        cfg = cfg.substr(0, 20);
    text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    while (!text.empty()) {
        nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
        if (!hal::is_blank_line(line))
            (void)hal::parse_stream_line(cfg, line);
    }
    return 0;
}
