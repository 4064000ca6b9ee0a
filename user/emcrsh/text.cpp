// SPDX-License-Identifier: GPL-2.0-or-later
// text.cpp - line splitting and words (text.hpp).
#include "text.hpp"

#include <cctype>
#include <cstdio>

namespace hal::emcrsh {

void LineReader::append(const char* data, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        char c = data[i];
        if (c == '\r' || c == '\n') {
            if (skipping_)
                skipping_ = false;
            else if (!cur_.empty())
                done_.push_back(std::move(cur_));
            cur_.clear();
            continue;
        }
        if (skipping_)
            continue;
        if (cur_.size() >= MAX_LINE) {
            cur_.clear();
            skipping_ = true;
            done_.push_back(std::nullopt);
            continue;
        }
        cur_ += c == '\0' ? ' ' : c;
    }
}

std::optional<std::string> LineReader::next(bool* too_long)
{
    *too_long = false;
    while (!done_.empty()) {
        std::optional<std::string> line = std::move(done_.front());
        done_.pop_front();
        if (!line) {
            *too_long = true;
            return std::nullopt;
        }
        if (line->find_first_not_of(" \t") != std::string::npos)
            return line;   // lines of blanks are skipped like empty ones
    }
    return std::nullopt;
}

std::string rest_after(const std::string& line, size_t n)
{
    size_t i = 0;
    auto blank = [](char c) { return c == ' ' || c == '\t'; };
    for (size_t k = 0; k < n; ++k) {
        while (i < line.size() && blank(line[i]))
            ++i;
        while (i < line.size() && !blank(line[i]))
            ++i;
    }
    while (i < line.size() && blank(line[i]))
        ++i;
    size_t e = line.size();
    while (e > i && blank(line[e - 1]))
        --e;
    return line.substr(i, e - i);
}

std::string upper(std::string s)
{
    for (char& c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string fmt(double v)
{
    char b[64];
    std::snprintf(b, sizeof b, "%f", v);
    return b;
}

}  // namespace hal::emcrsh
