// SPDX-License-Identifier: GPL-2.0-or-later
// line_parser.cpp - see line_parser.hpp.
#include "line_parser.hpp"

#include <cstdlib>

namespace hal::halcmd {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Where a bare $VAR or [SECTION]VAR name ends: whitespace, quotes or a comment.
bool ends_bare_name(char c) { return is_space(c) || c == '"' || c == '\'' || c == '#'; }

struct Expansion {
    std::string value;
    size_t next = 0;                 // index just after the variable reference
};

// A parenthesised name starting at line[open] == '('.
Result<Expansion> read_paren_name(std::string_view line, size_t open, std::string_view what)
{
    size_t close = line.find(')', open + 1);
    if (close == std::string_view::npos)
        return Error{-22, "missing ')' after '" + std::string(what) + "('"};
    Expansion e;
    e.value = std::string(line.substr(open + 1, close - open - 1));
    e.next = close + 1;
    if (e.value.empty())
        return Error{-22, "empty variable name in '" + std::string(what) + "()'"};
    return e;
}

size_t bare_name_end(std::string_view line, size_t from)
{
    size_t i = from;
    while (i < line.size() && !ends_bare_name(line[i]))
        i++;
    return i;
}

// $VAR or $(VAR) at line[at] == '$'. nullopt: a lone '$', kept literally.
Result<std::optional<Expansion>> expand_env(std::string_view line, size_t at, const Substitutions& subs)
{
    Expansion e;
    std::string name;
    if (at + 1 < line.size() && line[at + 1] == '(') {
        auto p = read_paren_name(line, at + 1, "$");
        if (!p)
            return p.error();
        name = p->value;
        e.next = p->next;
    } else {
        size_t end = bare_name_end(line, at + 1);
        if (end == at + 1)
            return std::optional<Expansion>{};
        name = std::string(line.substr(at + 1, end - at - 1));
        e.next = end;
    }
    std::optional<std::string> v = subs.env ? subs.env(name) : std::nullopt;
    if (!v)
        return Error{-2, "environment variable '" + name + "' is not set"};
    e.value = *v;
    return std::optional<Expansion>{e};
}

// [SECTION]VAR or [SECTION](VAR) at line[at] == '['. nullopt: not of that form, or
// no inifile given; the '[' is then kept literally.
Result<std::optional<Expansion>> expand_ini(std::string_view line, size_t at, const Substitutions& subs)
{
    if (!subs.ini)
        return std::optional<Expansion>{};
    size_t close = at + 1;
    while (close < line.size() && line[close] != ']' && !ends_bare_name(line[close]) && line[close] != '[')
        close++;
    if (close >= line.size() || line[close] != ']' || close == at + 1)
        return std::optional<Expansion>{};
    std::string section(line.substr(at + 1, close - at - 1));
    Expansion e;
    std::string name;
    if (close + 1 < line.size() && line[close + 1] == '(') {
        auto p = read_paren_name(line, close + 1, "[" + section + "]");
        if (!p)
            return p.error();
        name = p->value;
        e.next = p->next;
    } else {
        size_t end = bare_name_end(line, close + 1);
        if (end == close + 1)
            return std::optional<Expansion>{};
        name = std::string(line.substr(close + 1, end - close - 1));
        e.next = end;
    }
    std::optional<std::string> v = subs.ini->find(section, name);
    if (!v)
        return Error{-2, "inifile variable [" + section + "]" + name + " not found in '" + subs.ini->path() + "'"};
    e.value = *v;
    return std::optional<Expansion>{e};
}

Result<std::optional<Expansion>> expand_at(std::string_view line, size_t at, const Substitutions& subs)
{
    return line[at] == '$' ? expand_env(line, at, subs) : expand_ini(line, at, subs);
}

class Splitter {
public:
    void add(char c) { cur_ += c; in_word_ = true; }
    void start_word() { in_word_ = true; }   // quotes make a word even when empty
    void end_word()
    {
        if (in_word_)
            words_.push_back(std::move(cur_));
        cur_.clear();
        in_word_ = false;
    }
    std::vector<std::string> finish() { end_word(); return std::move(words_); }

private:
    std::vector<std::string> words_;
    std::string cur_;
    bool in_word_ = false;
};

}  // namespace

Substitutions process_substitutions(const IniFile* ini)
{
    Substitutions s;
    s.env = [](const std::string& name) -> std::optional<std::string> {
        const char* v = std::getenv(name.c_str());
        if (!v)
            return std::nullopt;
        return std::string(v);
    };
    s.ini = ini;
    return s;
}

Result<std::vector<std::string>> tokenize(std::string_view line, const Substitutions& subs)
{
    Splitter out;
    size_t i = 0;
    while (i < line.size()) {
        char c = line[i];
        if (is_space(c)) {
            out.end_word();
            i++;
        } else if (c == '#') {
            break;                               // comment to end of line
        } else if (c == '\'') {
            size_t close = line.find('\'', i + 1);
            if (close == std::string_view::npos)
                return Error{-22, "unterminated single quote"};
            out.start_word();
            for (size_t k = i + 1; k < close; k++)
                out.add(line[k]);
            i = close + 1;
        } else if (c == '"') {
            out.start_word();
            i++;
            for (;;) {
                if (i >= line.size())
                    return Error{-22, "unterminated double quote"};
                char q = line[i];
                if (q == '"') {
                    i++;
                    break;
                }
                if (q == '\\' && i + 1 < line.size() &&
                    (line[i + 1] == '"' || line[i + 1] == '\\' || line[i + 1] == '$')) {
                    out.add(line[i + 1]);
                    i += 2;
                    continue;
                }
                if (q == '$' || q == '[') {
                    auto e = expand_at(line, i, subs);
                    if (!e)
                        return e.error();
                    if (*e) {
                        for (char v : (*e)->value)
                            out.add(v);          // no word splitting inside quotes
                        i = (*e)->next;
                        continue;
                    }
                }
                out.add(q);
                i++;
            }
        } else if (c == '$' || c == '[') {
            auto e = expand_at(line, i, subs);
            if (!e)
                return e.error();
            if (!*e) {
                out.add(c);
                i++;
                continue;
            }
            for (char v : (*e)->value) {
                if (is_space(v))
                    out.end_word();              // unquoted: split like the line itself
                else
                    out.add(v);
            }
            i = (*e)->next;
        } else {
            out.add(c);
            i++;
        }
    }
    return out.finish();
}

bool join_continuation(std::string& logical, std::string_view physical)
{
    while (!physical.empty() && (physical.back() == '\r' || physical.back() == '\n'))
        physical.remove_suffix(1);
    // Trailing blanks after the backslash are forgiven: they are invisible in editors.
    size_t end = physical.find_last_not_of(" \t");
    bool continues = end != std::string_view::npos && physical[end] == '\\';
    if (continues) {
        // Joined directly, as LinuxCNC does: "names=d1\" + ",d2" is "names=d1,d2".
        logical.append(physical.substr(0, end));
    } else {
        logical.append(physical);
    }
    return continues;
}

bool is_arrow(std::string_view word)
{
    return word == "=>" || word == "<=" || word == "<=>";
}

}  // namespace hal::halcmd
