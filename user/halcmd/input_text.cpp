// SPDX-License-Identifier: GPL-2.0-or-later
// input_text.cpp - see input_text.hpp.
#include "input_text.hpp"

#include <cerrno>
#include <cstring>

namespace hal::halcmd {

namespace {

bool is_control(unsigned char c) { return (c < 0x20 && c != '\t') || c == 0x7f; }

std::string hex_byte(unsigned char c)
{
    static const char digits[] = "0123456789abcdef";
    return std::string("\\x") + digits[c >> 4] + digits[c & 15];
}

// Length of the valid UTF-8 sequence at s[i] that is not a C1 control, else 0.
size_t utf8_length(std::string_view s, size_t i)
{
    auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    unsigned char c = b(i);
    size_t n = c >= 0xf0 && c <= 0xf4 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
    if (n == 0 || i + n > s.size())
        return 0;
    for (size_t k = 1; k < n; ++k)
        if ((b(i + k) & 0xc0) != 0x80)
            return 0;
    if (n == 2 && c == 0xc2 && b(i + 1) < 0xa0)
        return 0;  // U+0080..U+009F: C1 controls (0x9b is a terminal's CSI)
    if (n == 3 && ((c == 0xe0 && b(i + 1) < 0xa0) || (c == 0xed && b(i + 1) >= 0xa0)))
        return 0;  // overlong, or a surrogate
    if (n == 4 && ((c == 0xf0 && b(i + 1) < 0x90) || (c == 0xf4 && b(i + 1) >= 0x90)))
        return 0;  // overlong, or past U+10FFFF
    return n;
}

}  // namespace

Result<void> check_line_text(std::string_view line)
{
    if (!line.empty() && line.back() == '\r')
        line.remove_suffix(1);
    for (size_t i = 0; i < line.size(); ++i) {
        auto c = static_cast<unsigned char>(line[i]);
        if (!is_control(c))
            continue;
        std::string what = c == 0 ? "a NUL byte" : "control character " + hex_byte(c);
        return Error{-EINVAL, what + " at column " + std::to_string(i + 1) +
                                  " (a .hal line is text: no NUL or control characters "
                                  "but tab)"};
    }
    return {};
}

std::string printable(std::string_view s)
{
    std::string out;
    out.reserve(s.size());
    for (size_t i = 0; i < s.size();) {
        auto c = static_cast<unsigned char>(s[i]);
        if (c < 0x80) {
            out += is_control(c) ? hex_byte(c) : std::string(1, s[i]);
            ++i;
            continue;
        }
        size_t n = utf8_length(s, i);
        if (n == 0) {
            out += hex_byte(c);
            ++i;
        } else {
            out.append(s.substr(i, n));
            i += n;
        }
    }
    return out;
}

bool LineReader::next(std::string& line)
{
    line.clear();
    if (done_)
        return false;
    for (;;) {
        int c = getc_unlocked(in_);  // one reader per stream
        if (c == EOF) {
            done_ = true;
            if (std::ferror(in_)) {
                int err = errno ? errno : EIO;
                has_error_ = true;
                error_ = Error{-err, std::string("cannot read: ") + std::strerror(err)};
                return false;
            }
            return !line.empty();  // a last line without '\n'
        }
        if (c == '\n')
            return true;
        if (line.size() >= max_line_bytes) {
            done_ = true;
            has_error_ = true;
            error_ = Error{-E2BIG, "line longer than " + std::to_string(max_line_bytes) +
                                       " bytes; stopped reading"};
            return false;
        }
        line.push_back(static_cast<char>(c));
    }
}

}  // namespace hal::halcmd
