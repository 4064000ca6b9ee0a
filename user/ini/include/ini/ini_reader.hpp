// SPDX-License-Identifier: GPL-2.0-or-later
// ini_reader.hpp - typed reads of many keys in a row where the first error wins
// (task's and halui's configuration): each read keeps the variable's value as the
// default, and once one read failed the later ones are skipped, so the caller checks
// `err` once at the end and reports the first bad key with its file:line.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "ini/ini_file.hpp"

namespace hal::ini {

struct Reader {
    const IniFile& ini;
    std::string err;

    // a finite number (inf/nan are refused: they would reach motion's limits)
    void d(const std::string& sec, const char* key, double& out)
    {
        if (!err.empty())
            return;
        auto r = ini.get_double(sec, key, out);
        if (r && !std::isfinite(*r))
            err = ini.where(sec, key) + ": [" + sec + "]" + key + ": not a finite number";
        else
            keep(r, out);
    }
    void i(const std::string& sec, const char* key, int& out)
    {
        if (err.empty())
            keep(ini.get_int(sec, key, out), out);
    }
    void b(const std::string& sec, const char* key, bool& out)
    {
        if (err.empty())
            keep(ini.get_bool(sec, key, out), out);
    }
    // bit set in flags when the boolean key is true
    void flag(const std::string& sec, const char* key, int bit, int& flags)
    {
        bool v = false;
        b(sec, key, v);
        if (v)
            flags |= bit;
    }
    // [TRAJ]COORDINATES, when given: its axis letters (X Y Z A B C U V W, either case,
    // blanks between them allowed) in upper case without the blanks; a gantry repeats
    // a letter
    void coordinates(std::string& out)
    {
        auto v = ini.find("TRAJ", "COORDINATES");
        if (!err.empty() || !v)
            return;
        std::string letters;
        for (char ch : *v) {
            if (ch == ' ' || ch == '\t')
                continue;
            char up = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
            if (up == '\0' || !std::strchr("XYZABCUVW", up)) {
                err = ini.where("TRAJ", "COORDINATES") + ": [TRAJ]COORDINATES: '" + std::string(1, ch) +
                      "' is not one of X Y Z A B C U V W";
                return;
            }
            letters += up;
        }
        out = letters;
    }
    // a number as the messages show it (%g)
    static std::string num(double v)
    {
        char b[32];
        std::snprintf(b, sizeof b, "%g", v);
        return b;
    }
    // a value already read must lie in lo..hi
    void range(const std::string& sec, const char* key, double v, double lo, double hi)
    {
        if (err.empty() && !(v >= lo && v <= hi))
            err = ini.where(sec, key) + ": [" + sec + "]" + key + ": " + num(v) + " out of range " + num(lo) +
                  ".." + num(hi);
    }

private:
    template <typename R, typename T>
    void keep(const R& r, T& out)
    {
        if (!r)
            err = r.error().message;
        else
            out = static_cast<T>(*r);
    }
};

}  // namespace hal::ini
