// SPDX-License-Identifier: GPL-2.0-or-later
// ini_file.hpp - the one INI reader of every tool (halcmd -i, the interpreter, the emc
// launcher, task, iocontrol). Behaviour is that of the EMC2 2.4 ... LinuxCNC 2.9 reader
// (ini-and-launch.md 1.1) plus the 2.10 reader's #INCLUDE (1.2); docs/ini.md lists
// every rule and the keys the project reads.
//
//   [SECTION]           case-sensitive; only the FIRST block of a name is searched
//   KEY = value         no trailing comments; value trimmed; key lines without '=' ignored
//   ; or # comment      only as the first non-blank character of a line
//   KEY = a\            continuation: backslash removed, next line appended as is
//   #INCLUDE file       at column 1: the file's lines take this line's place
//
// Every value remembers the file and line it came from, so errors name them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hal/result.hpp"

namespace hal::ini {

class IniFile {
public:
    // One KEY = value line. 'reachable' is false for keys outside any section and in a
    // repeated block of a section name (the reader never searches those).
    struct Entry {
        std::string section;
        std::string key;
        std::string value;
        std::string file;      // the file the line is in (an #INCLUDEd one, maybe)
        int line = 0;          // 1-based; the first line of a continued value
        bool reachable = true;
    };

    // Reads PATH (with a shared fcntl read lock while reading). Errors:
    // "cannot open inifile 'PATH': REASON" or "FILE:LINE: REASON".
    static hal::Result<IniFile> load(const std::string& path);
    // TEXT as if read from PATH: #INCLUDE names are resolved against PATH's directory.
    static hal::Result<IniFile> parse(std::string_view text, std::string path);

    // The nth (1-based) occurrence of KEY in the first [SECTION] block.
    std::optional<std::string> find(std::string_view section, std::string_view key, int nth = 1) const;
    // Every occurrence, in file order (list keys: HALFILE, HALCMD, APP, ...).
    std::vector<std::string> find_all(std::string_view section, std::string_view key) const;

    // Typed reads of the first occurrence: FALLBACK when the key is absent, an Error
    // "FILE:LINE: [SECTION]KEY: 'TEXT' is not a number" when its text does not convert.
    hal::Result<double> get_double(std::string_view section, std::string_view key, double fallback) const;
    // C's %i: decimal, 0x hex, leading-zero octal.
    hal::Result<long> get_int(std::string_view section, std::string_view key, long fallback) const;
    // YES/NO TRUE/FALSE ON/OFF (any case), or any integer (non-zero = true).
    hal::Result<bool> get_bool(std::string_view section, std::string_view key, bool fallback) const;

    // "FILE:LINE" of the nth occurrence, or the INI path alone when there is none.
    std::string where(std::string_view section, std::string_view key, int nth = 1) const;
    const std::string& path() const { return path_; }

    // Every key line in file order (for #<_ini[section]key> tables and dumps).
    const std::vector<Entry>& entries() const { return entries_; }
    // Non-fatal findings, each "FILE:LINE: text" (DOS line endings, unterminated
    // section headers, key lines outside any section).
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    const Entry* lookup(std::string_view section, std::string_view key, int nth) const;

    std::string path_;
    std::vector<Entry> entries_;
    std::vector<std::string> warnings_;

    friend class Parser;
};

}  // namespace hal::ini
