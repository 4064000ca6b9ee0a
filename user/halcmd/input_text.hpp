// SPDX-License-Identifier: GPL-2.0-or-later
// input_text.hpp - the bytes halcmd takes from its input and how untrusted text
// appears in its messages (issue 19, items 4, 5 and 9). A .hal line is text: a NUL
// or control character in it is an error naming its column (it used to cut names
// and values short); lines are bounded; every message shows control characters and
// invalid UTF-8 as \xNN, so input never reaches the terminal as escape sequences.
// Pure: no HAL, no I/O except LineReader's stdio stream.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "hal/result.hpp"

namespace hal::halcmd {

// Longest physical or logical (continued) line halcmd reads, in bytes.
inline constexpr size_t max_line_bytes = 64 * 1024;

// Error for a NUL or control character (any byte below 0x20 but tab, and 0x7f) in
// a line read without its '\n'; one '\r' at the very end (a CRLF file) is allowed.
// Columns count bytes from 1.
Result<void> check_line_text(std::string_view line);

// 's' with control characters, DEL, C1 controls and invalid UTF-8 bytes as \xNN;
// printable ASCII and valid UTF-8 pass unchanged.
std::string printable(std::string_view s);

// Physical lines of a stream, each without its '\n', at most max_line_bytes. A read
// error (a directory, an I/O error) or an overlong line is an error; after one,
// next() returns no more lines (an unbounded line, /dev/zero, is never read whole).
class LineReader {
public:
    explicit LineReader(std::FILE* in) : in_(in) {}
    // false at the end of the input, or after an error (then error() is set).
    bool next(std::string& line);
    const Error* error() const { return has_error_ ? &error_ : nullptr; }

private:
    std::FILE* in_;
    bool done_ = false;
    bool has_error_ = false;
    Error error_{0, ""};
};

}  // namespace hal::halcmd
