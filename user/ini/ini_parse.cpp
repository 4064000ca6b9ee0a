// SPDX-License-Identifier: GPL-2.0-or-later
// ini_parse.cpp - turning INI text into IniFile entries: lines, comments, sections,
// key lines, continuation lines and #INCLUDE (ini-and-launch.md 1.1, 1.2).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <map>

#include "ini/ini_file.hpp"

namespace hal::ini {

namespace {

constexpr int kMaxContinuations = 20;   // the 2.9 reader's limit
constexpr int kMaxIncludeDepth = 16;    // the 2.10 reader's limit

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view ltrim(std::string_view s)
{
    while (!s.empty() && is_blank(s.front()))
        s.remove_prefix(1);
    return s;
}

std::string_view rtrim(std::string_view s)
{
    while (!s.empty() && (is_blank(s.back()) || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

std::string dir_of(const std::string& path)
{
    size_t slash = path.rfind('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

bool readable(const std::string& path)
{
    struct stat st;
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), R_OK) == 0;
}

// The whole file, read under a shared (advisory) lock as the EMC readers take one. A
// lock held by someone else does not stop us: nobody writes INI files under a lock.
Result<std::string> read_file(const std::string& path)
{
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return Error{-errno, "cannot open inifile '" + path + "': " + std::strerror(errno)};
    struct stat st;
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return Error{-22, "cannot read inifile '" + path + "': not a regular file"};
    }
    struct flock lk {};
    lk.l_type = F_RDLCK;
    lk.l_whence = SEEK_SET;
    (void)::fcntl(fd, F_SETLK, &lk);
    std::string text;
    char buf[8192];
    for (;;) {
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            int err = errno;
            ::close(fd);
            return Error{-err, "cannot read inifile '" + path + "': " + std::strerror(err)};
        }
        if (n == 0)
            break;
        text.append(buf, static_cast<size_t>(n));
    }
    ::close(fd);
    return text;
}

// 2.9's launcher shell-expands #INCLUDE names: ~ and $VAR / ${VAR} are what configs use.
Result<std::string> expand_name(std::string_view name)
{
    std::string out;
    if (name.size() >= 1 && name[0] == '~' && (name.size() == 1 || name[1] == '/')) {
        const char* home = std::getenv("HOME");
        if (!home)
            return Error{-22, "'~' in #INCLUDE name but HOME is not set"};
        out = home;
        name.remove_prefix(1);
    }
    for (size_t i = 0; i < name.size(); i++) {
        if (name[i] != '$') {
            out += name[i];
            continue;
        }
        size_t start = i + 1, end;
        bool braced = start < name.size() && name[start] == '{';
        if (braced) {
            end = name.find('}', start);
            if (end == std::string_view::npos)
                return Error{-22, "missing '}' in #INCLUDE name"};
            start++;
        } else {
            end = start;
            while (end < name.size() && (std::isalnum(static_cast<unsigned char>(name[end])) || name[end] == '_'))
                end++;
        }
        std::string var(name.substr(start, end - start));
        const char* v = var.empty() ? nullptr : std::getenv(var.c_str());
        if (!v)
            return Error{-22, "environment variable '" + var + "' in #INCLUDE name is not set"};
        out += v;
        i = braced ? end : end - 1;
    }
    return out;
}

}  // namespace

// Walks the lines of one file and the files it includes, appending to one IniFile.
class Parser {
public:
    explicit Parser(IniFile& ini) : ini_(ini) {}

    Result<void> run(std::string_view text, const std::string& file, int depth);

private:
    struct Line {
        std::string_view text;
        int number;
    };
    Result<void> include(std::string_view rest, const std::string& file, int line, int depth);
    void section(std::string_view t, const std::string& file, int line);
    Result<void> key_line(std::string_view t, std::vector<Line>& lines, size_t& i, const std::string& file);

    IniFile& ini_;
    std::string section_;
    bool in_section_ = false;              // false before the first header and after a bad one
    bool reachable_ = false;               // false in a repeated block of a section name
    std::map<std::string, std::string, std::less<>> first_block_;   // name -> "file:line"
    std::vector<std::string> stack_;       // files being read, for recursion checks
};

Result<void> Parser::run(std::string_view text, const std::string& file, int depth)
{
    std::vector<Line> lines;
    bool dos = false;
    int number = 0;
    while (!text.empty()) {
        size_t nl = text.find('\n');
        std::string_view l = text.substr(0, nl);
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
        number++;
        if (!l.empty() && l.back() == '\r') {
            l.remove_suffix(1);
            dos = true;
        }
        if (l.find('\r') != std::string_view::npos)
            return Error{-22, file + ":" + std::to_string(number) +
                                  ": ambiguous carriage return (a CR not followed by LF)"};
        lines.push_back({l, number});
    }
    if (dos)
        ini_.warnings_.push_back(file + ": file contains DOS-style line endings");

    stack_.push_back(file);
    for (size_t i = 0; i < lines.size(); i++) {
        std::string_view raw = lines[i].text;
        int line = lines[i].number;
        if (raw.starts_with("#INCLUDE") && (raw.size() == 8 || is_blank(raw[8]))) {
            auto r = include(raw.substr(8), file, line, depth);
            if (!r) {
                stack_.pop_back();
                return r;
            }
            continue;
        }
        std::string_view t = ltrim(raw);
        if (t.empty() || t[0] == ';' || t[0] == '#')
            continue;
        if (t[0] == '[') {
            section(t, file, line);
            continue;
        }
        auto r = key_line(t, lines, i, file);
        if (!r) {
            stack_.pop_back();
            return r;
        }
    }
    stack_.pop_back();
    return hal::ok();
}

Result<void> Parser::include(std::string_view rest, const std::string& file, int line, int depth)
{
    std::string at = file + ":" + std::to_string(line) + ": ";
    std::string_view name = rtrim(ltrim(rest));
    if (name.empty())
        return Error{-22, at + "#INCLUDE without a file name"};
    auto expanded = expand_name(name);
    if (!expanded)
        return Error{-22, at + expanded.error().message};
    std::string target = *expanded;
    // An absolute name as given; else next to the including file, then from the cwd.
    if (target[0] != '/') {
        std::string beside = dir_of(file) + "/" + target;
        if (readable(beside) || !readable(target))
            target = beside;
    }
    if (depth + 1 > kMaxIncludeDepth)
        return Error{-22, at + "#INCLUDE nested more than " + std::to_string(kMaxIncludeDepth) + " levels deep"};
    char real_target[PATH_MAX];
    if (::realpath(target.c_str(), real_target)) {
        for (const std::string& open : stack_) {
            char real_open[PATH_MAX];
            if (::realpath(open.c_str(), real_open) && std::strcmp(real_open, real_target) == 0)
                return Error{-22, at + "#INCLUDE '" + std::string(name) + "' includes itself (recursion)"};
        }
    }
    auto text = read_file(target);
    if (!text)
        return Error{text.error().code, at + "#INCLUDE: " + text.error().message};
    return run(*text, target, depth + 1);
}

// "[NAME]..." at the line start: NAME is the text up to the first ']', the rest of the
// line is not looked at. Only a name's first block is searched by the 2.9 reader.
void Parser::section(std::string_view t, const std::string& file, int line)
{
    std::string at = file + ":" + std::to_string(line);
    size_t close = t.find(']');
    if (close == std::string_view::npos) {
        in_section_ = false;
        ini_.warnings_.push_back(at + ": section header without ']': the lines after it belong to no section");
        return;
    }
    section_ = std::string(t.substr(1, close - 1));
    in_section_ = true;
    auto [it, inserted] = first_block_.emplace(section_, at);
    reachable_ = inserted;
    if (!inserted)
        ini_.warnings_.push_back(at + ": second [" + section_ + "] block is never read (the first one is at " +
                                 it->second + ")");
}

// "KEY = value": KEY ends at a blank, tab or '='; the value starts at the first
// non-blank after the first '='. A value ending in '\' takes the next line (as is).
Result<void> Parser::key_line(std::string_view t, std::vector<Line>& lines, size_t& i, const std::string& file)
{
    int line = lines[i].number;
    size_t key_end = 0;
    while (key_end < t.size() && !is_blank(t[key_end]) && t[key_end] != '=')
        key_end++;
    size_t eq = t.find('=', key_end);
    if (key_end == 0 || eq == std::string_view::npos)
        return hal::ok();                 // not a key line: never found by a lookup
    std::string value(ltrim(t.substr(eq + 1)));
    int joined = 0;
    while (!value.empty() && value.back() == '\\' && i + 1 < lines.size()) {
        if (++joined > kMaxContinuations)
            return Error{-22, file + ":" + std::to_string(line) + ": more than " +
                                  std::to_string(kMaxContinuations) + " continuation lines (Too many backslash line extends)"};
        value.pop_back();
        value += lines[++i].text;
    }
    value = std::string(rtrim(value));
    if (!in_section_)
        ini_.warnings_.push_back(file + ":" + std::to_string(line) + ": key line outside any section is never read");
    ini_.entries_.push_back({in_section_ ? section_ : std::string(), std::string(t.substr(0, key_end)),
                             std::move(value), file, line, in_section_ && reachable_});
    return hal::ok();
}

Result<IniFile> IniFile::parse(std::string_view text, std::string path)
{
    IniFile ini;
    ini.path_ = std::move(path);
    Parser p(ini);
    auto r = p.run(text, ini.path_, 0);
    if (!r)
        return r.error();
    return ini;
}

Result<IniFile> IniFile::load(const std::string& path)
{
    auto text = read_file(path);
    if (!text)
        return text.error();
    return parse(*text, path);
}

}  // namespace hal::ini
