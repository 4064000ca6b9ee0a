// SPDX-License-Identifier: GPL-2.0-or-later
// text.hpp - emcrsh's wire text: lines in (any run of CR and LF ends one, capped
// length) and the reply forms with their line ends (emcrsh-and-halui.md 1.2).
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "bus/protocol.hpp"

namespace hal::emcrsh {

// Longest request line kept; a longer one is dropped up to its line end and
// answered LINE_TOO_LONG.
inline constexpr size_t MAX_LINE = 1024;
inline constexpr const char* LINE_TOO_LONG = "NAK line too long\r\n";

class LineReader {
public:
    void append(const char* data, size_t n);
    // The next complete, non-empty line; *too_long is set (and nullopt returned) once
    // for every line that overflowed MAX_LINE. nullopt: nothing complete yet.
    std::optional<std::string> next(bool* too_long);
    size_t pending() const { return cur_.size(); }

private:
    std::string cur_;                              // the line being collected
    std::deque<std::optional<std::string>> done_;  // complete lines; nullopt: too long
    bool skipping_ = false;   // inside an over-long line: dropped up to its end
};

// Words split at blanks (space, tab): the bus's splitter; LineReader has already
// taken CR and LF off.
using hal::bus::split_words;
// The rest of the line after the first n words (leading blanks removed).
std::string rest_after(const std::string& line, size_t n);
std::string upper(std::string s);

// Reply forms. GET's NAK carries two line ends, SET's use "\n\r" (both as the
// reference does); everything else ends "\r\n".
inline std::string crlf(const std::string& s) { return s + "\r\n"; }
inline std::string get_nak(const std::string& sub) { return "GET " + sub + " NAK\r\n\r\n"; }
inline std::string set_nak(const std::string& sub) { return "SET " + sub + " NAK\n\r"; }
inline std::string set_ack(const std::string& sub) { return "SET " + sub + " ACK\n\r"; }

// "%f"
std::string fmt(double v);

}  // namespace hal::emcrsh
