// SPDX-License-Identifier: GPL-2.0-or-later
// parser.cpp - a hand-written recursive-descent reader of the .comp declarations.
// The declaration part is read character by character because a HAL name
// ("out-#", "x.y") and a C expression ("personality & 0x100") need different
// token rules; everything after the ";;" line is kept verbatim as C code.
#include "parser.hpp"

#include <cctype>
#include <cstdlib>
#include <set>

#include "check.hpp"
#include "names.hpp"

namespace hal::comp {

namespace {

struct ParseError {
    int line;
    std::string message;
};

class Reader {
public:
    explicit Reader(const std::string& text) : s_(text) {}

    int line() const { return line_; }
    int token_end_line() const { return token_end_line_; }  // line where the last token ended
    bool at_end() { skip(); return i_ >= s_.size(); }
    char peek() { skip(); return i_ < s_.size() ? s_[i_] : '\0'; }
    bool peek_is(const char* text)
    {
        skip();
        return s_.compare(i_, std::string(text).size(), text) == 0;
    }

    // Whitespace and C/C++ comments.
    void skip()
    {
        while (i_ < s_.size()) {
            char c = s_[i_];
            if (c == '\n') {
                ++line_, ++i_;
            } else if (std::isspace(static_cast<unsigned char>(c))) {
                ++i_;
            } else if (s_.compare(i_, 2, "//") == 0) {
                while (i_ < s_.size() && s_[i_] != '\n')
                    ++i_;
            } else if (s_.compare(i_, 2, "/*") == 0) {
                std::size_t end = s_.find("*/", i_ + 2);
                if (end == std::string::npos)
                    fail("unterminated /* comment");
                for (; i_ < end + 2; ++i_)
                    if (s_[i_] == '\n')
                        ++line_;
            } else {
                break;
            }
        }
    }

    [[noreturn]] void fail(const std::string& message) const { throw ParseError{line_, message}; }
    [[noreturn]] void fail_at(int line, const std::string& message) const { throw ParseError{line, message}; }

    bool accept(char c)
    {
        if (peek() != c)
            return false;
        ++i_;
        token_end_line_ = line_;
        return true;
    }

    void expect(char c, const std::string& context)
    {
        if (!accept(c))
            fail(std::string("expected '") + c + "' " + context + describe_next());
    }

    // What comes next, for messages: ", found 'xyz'" or ", found end of file".
    std::string describe_next()
    {
        skip();
        if (i_ >= s_.size())
            return ", found end of file";
        std::size_t n = 0;
        while (i_ + n < s_.size() && n < 20 && !std::isspace(static_cast<unsigned char>(s_[i_ + n])))
            ++n;
        return ", found '" + s_.substr(i_, n ? n : 1) + "'";
    }

    // Run of characters accepted by 'ok' (possibly empty).
    template <typename Pred>
    std::string word(Pred ok)
    {
        skip();
        std::size_t start = i_;
        while (i_ < s_.size() && ok(s_[i_], i_ - start))
            ++i_;
        if (i_ > start)
            token_end_line_ = line_;
        return s_.substr(start, i_ - start);
    }

    std::string identifier()
    {
        return word([](char c, std::size_t n) {
            return c == '_' || std::isalpha(static_cast<unsigned char>(c)) ||
                   (n > 0 && std::isdigit(static_cast<unsigned char>(c)));
        });
    }

    std::string halname()
    {
        return word([](char c, std::size_t n) {
            return c == '_' || c == '#' || std::isalpha(static_cast<unsigned char>(c)) ||
                   (n > 0 && (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.'));
        });
    }

    // A default value: number, boolean word or C identifier ("-1.5e-3", "TRUE", "M_PI").
    std::string value()
    {
        return word([](char c, std::size_t) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
                   c == '+' || c == '-';
        });
    }

    // "..." or """...""" with C escapes.
    std::string string_literal()
    {
        skip();
        bool triple = s_.compare(i_, 3, "\"\"\"") == 0;
        if (!triple && (i_ >= s_.size() || s_[i_] != '"'))
            fail("expected a string" + describe_next());
        int start_line = line_;
        i_ += triple ? 3 : 1;
        std::string out;
        for (;;) {
            if (i_ >= s_.size()) {
                line_ = start_line;
                fail("unterminated string");
            }
            char c = s_[i_];
            if (triple ? s_.compare(i_, 3, "\"\"\"") == 0 : c == '"') {
                i_ += triple ? 3 : 1;
                token_end_line_ = line_;
                return out;
            }
            if (c == '\n') {
                if (!triple) {
                    line_ = start_line;
                    fail("unterminated string (use \"\"\"...\"\"\" for text over several lines)");
                }
                ++line_;
            }
            if (c == '\\' && i_ + 1 < s_.size()) {
                char e = s_[++i_];
                switch (e) {
                case 'n': out += '\n'; break;
                case 't': out += '\t'; break;
                case '\n': ++line_; break;  // line continuation
                default: out += e;          // \" \\ and anything else: the character itself
                }
                ++i_;
                continue;
            }
            out += c;
            ++i_;
        }
    }

    bool at_string() { return peek() == '"'; }

    // Raw C text up to (not including) one of 'stops' at bracket depth 0.
    std::string expression(const std::string& stops)
    {
        skip();
        std::size_t start = i_;
        int depth = 0;
        while (i_ < s_.size()) {
            char c = s_[i_];
            if (depth == 0 && stops.find(c) != std::string::npos)
                break;
            if (c == '(' || c == '[')
                ++depth;
            else if ((c == ')' || c == ']') && depth > 0)
                --depth;
            else if (c == '\n')
                ++line_;
            ++i_;
        }
        std::string e = s_.substr(start, i_ - start);
        while (!e.empty() && std::isspace(static_cast<unsigned char>(e.back())))
            e.pop_back();
        return e;
    }

    // After the ";;" separator: the rest of that line is skipped; returns the code.
    std::string rest_after_separator(int* code_line)
    {
        std::size_t nl = s_.find('\n', i_);
        if (nl == std::string::npos) {
            *code_line = line_ + 1;
            return "";
        }
        *code_line = line_ + 1;
        return s_.substr(nl + 1);
    }

    void advance(std::size_t n) { i_ += n; }

private:
    const std::string& s_;
    std::size_t i_ = 0;
    int line_ = 1;
    int token_end_line_ = 1;
};

const std::set<std::string> declaration_keywords = {
    "component", "pin", "param", "function", "variable", "option", "modparam", "include",
    "license", "author", "description", "notes", "see_also"};

bool is_number(const std::string& v)
{
    if (v.empty())
        return false;
    char* end = nullptr;
    std::strtod(v.c_str(), &end);
    if (*end == '\0')
        return true;
    std::strtoll(v.c_str(), &end, 0);
    return *end == '\0';
}

bool is_c_identifier(const std::string& v)
{
    if (v.empty() || std::isdigit(static_cast<unsigned char>(v[0])))
        return false;
    for (char c : v)
        if (!(c == '_' || std::isalnum(static_cast<unsigned char>(c))))
            return false;
    return true;
}

class Parser {
public:
    Parser(const std::string& text, Component& comp) : r_(text), c_(comp) {}

    void run()
    {
        if (r_.at_end())
            r_.fail("empty file: expected 'component NAME;'");
        std::string kw = r_.identifier();
        if (kw != "component")
            r_.fail("expected 'component NAME;' as the first declaration" +
                    (kw.empty() ? r_.describe_next() : ", found '" + kw + "'"));
        component();
        for (;;) {
            if (r_.at_end())
                return;  // no ";;" and no C code: only valid for code-less components
            if (r_.peek_is(";;")) {
                r_.advance(2);
                c_.code = r_.rest_after_separator(&c_.code_line);
                return;
            }
            declaration();
        }
    }

private:
    // The ';' that ends a declaration. When the next thing starts another declaration,
    // the ';' was forgotten: say so on the line of the unfinished declaration.
    void end(const std::string& what)
    {
        if (r_.peek_is(";;"))  // the separator line, so this declaration's ';' is missing
            r_.fail_at(r_.token_end_line(), "expected ';' after " + what + " declaration");
        if (r_.accept(';'))
            return;
        missing_semicolon(what);
        r_.expect(';', "after " + what + " declaration");
    }

    void missing_semicolon(const std::string& what)
    {
        if (r_.peek_is(";;"))
            return;
        int line = r_.token_end_line();
        Reader probe = r_;
        std::string w = probe.identifier();
        if (declaration_keywords.contains(w) || r_.at_end())
            r_.fail_at(line, "expected ';' after " + what + " declaration");
    }

    std::string optional_doc() { return r_.at_string() ? r_.string_literal() : std::string(); }

    void component()
    {
        c_.line = r_.line();
        c_.name = r_.identifier();
        if (c_.name.empty())
            r_.fail("expected a component name (letters, digits, _)" + r_.describe_next());
        c_.doc = optional_doc();
        end("component");
    }

    void declaration()
    {
        int line = r_.line();
        std::string kw = r_.identifier();
        if (kw.empty())
            r_.fail("expected a declaration (pin, param, function, variable, option, ...) or ';;'" +
                    r_.describe_next());
        if (kw == "pin" || kw == "param")
            item(kw == "pin", line);
        else if (kw == "function")
            function(line);
        else if (kw == "variable")
            variable(line);
        else if (kw == "option")
            option(line);
        else if (kw == "modparam")
            modparam(line);
        else if (kw == "include")
            include();
        else if (kw == "license" || kw == "author" || kw == "description" || kw == "notes" ||
                 kw == "see_also")
            text_field(kw);
        else if (kw == "component")
            r_.fail("a second 'component' declaration (the first was '" + c_.name + "')");
        else
            r_.fail("unknown declaration '" + kw +
                    "' (expected pin, param, function, variable, option, modparam, include, "
                    "license, author, description, notes or see_also)");
    }

    HalType hal_type(const std::string& what)
    {
        std::string t = r_.identifier();
        if (t == "bit") return HalType::Bit;
        if (t == "float") return HalType::Float;
        // si32/ui32: spellings LinuxCNC's halcompile also takes
        if (t == "s32" || t == "si32" || t == "signed") return HalType::S32;
        if (t == "u32" || t == "ui32" || t == "unsigned") return HalType::U32;
        if (t == "s64") return HalType::S64;
        if (t == "u64") return HalType::U64;
        r_.fail("expected the " + what + " type bit, float, s32, u32, s64 or u64" +
                (t.empty() ? r_.describe_next() : ", found '" + t + "'"));
    }

    std::string default_value(const std::string& what)
    {
        std::string v = r_.value();
        if (v == "TRUE" || v == "FALSE" || v == "true" || v == "false" || v == "yes" ||
            v == "no" || is_number(v) || is_c_identifier(v))
            return v;
        r_.fail("bad default value for " + what + (v.empty() ? r_.describe_next() : " '" + v + "'") +
                " (expected a number, TRUE, FALSE or a C name)");
    }

    void item(bool is_pin, int line)
    {
        const std::string kind = is_pin ? "pin" : "param";
        Item it;
        it.is_pin = is_pin;
        it.line = line;
        std::string d = r_.identifier();
        if (is_pin && d == "in") it.dir = Dir::In;
        else if (is_pin && d == "out") it.dir = Dir::Out;
        else if (is_pin && d == "io") it.dir = Dir::Io;
        else if (!is_pin && d == "r") it.dir = Dir::Ro;
        else if (!is_pin && d == "rw") it.dir = Dir::Rw;
        else
            r_.fail(std::string("expected the ") + kind + " direction " +
                    (is_pin ? "in, out or io" : "r or rw") +
                    (d.empty() ? r_.describe_next() : ", found '" + d + "'"));
        it.type = hal_type(kind);
        it.name = r_.halname();
        if (it.name.empty())
            r_.fail("expected a " + kind + " name" + r_.describe_next());
        if (r_.accept('[')) {
            std::string n = r_.word([](char c, std::size_t) {
                return std::isalnum(static_cast<unsigned char>(c)) != 0;
            });
            char* endp = nullptr;
            long size = std::strtol(n.c_str(), &endp, 0);
            if (n.empty() || *endp || size < 1 || size > 1000)
                r_.fail("array size of " + kind + " '" + it.name + "' must be a number 1..1000" +
                        (n.empty() ? r_.describe_next() : ", found '" + n + "'"));
            it.array_size = static_cast<int>(size);
            if (r_.accept(':')) {
                it.array_count = r_.expression("]");
                if (it.array_count.empty())
                    r_.fail("expected an expression after ':' in the array size of '" + it.name + "'");
            }
            r_.expect(']', "after the array size of " + kind + " '" + it.name + "'");
        }
        if (r_.accept('='))
            it.default_value = default_value(kind + " '" + it.name + "'");
        if (std::isalpha(static_cast<unsigned char>(r_.peek()))) {
            missing_semicolon(kind);
            std::string w = r_.identifier();
            if (w != "if")
                r_.fail("expected '=', 'if', a doc string or ';' after " + kind + " '" + it.name +
                        "', found '" + w + "'");
            it.condition = r_.expression("\";");
            if (it.condition.empty())
                r_.fail("expected a condition after 'if' for " + kind + " '" + it.name + "'");
        }
        it.doc = optional_doc();
        end(kind);
        c_.items.push_back(std::move(it));
    }

    void function(int line)
    {
        Function f;
        f.line = line;
        f.name = r_.identifier();
        if (f.name.empty())
            r_.fail("expected a function name (or _)" + r_.describe_next());
        if (r_.peek_is("fp") || r_.peek_is("nofp")) {
            std::string w = r_.identifier();
            if (w == "fp" || w == "nofp")
                f.fp = w == "fp";
            else
                r_.fail("expected fp, nofp, a doc string or ';' after function '" + f.name +
                        "', found '" + w + "'");
        }
        f.doc = optional_doc();
        end("function");
        c_.functions.push_back(std::move(f));
    }

    void variable(int line)
    {
        Variable v;
        v.line = line;
        v.ctype = r_.identifier();
        if (v.ctype.empty())
            r_.fail("expected a C type after 'variable'" + r_.describe_next());
        while (r_.accept('*'))
            v.stars += '*';
        v.name = r_.identifier();
        if (v.name.empty())
            r_.fail("expected a variable name after '" + v.ctype + v.stars + "'" + r_.describe_next());
        if (r_.accept('[')) {
            std::string n = r_.word([](char c, std::size_t) {
                return std::isalnum(static_cast<unsigned char>(c)) != 0;
            });
            char* endp = nullptr;
            long size = std::strtol(n.c_str(), &endp, 0);
            if (n.empty() || *endp || size < 1)
                r_.fail("array size of variable '" + v.name + "' must be a positive number");
            v.array_size = static_cast<int>(size);
            r_.expect(']', "after the array size of variable '" + v.name + "'");
        }
        if (r_.accept('='))
            v.default_value = default_value("variable '" + v.name + "'");
        end("variable");
        c_.variables.push_back(std::move(v));
    }

    void option(int line)
    {
        Option o;
        o.line = line;
        o.name = r_.identifier();
        if (o.name.empty())
            r_.fail("expected an option name" + r_.describe_next());
        if (r_.at_string())
            o.value = r_.string_literal();
        else if (r_.peek() != ';')
            o.value = r_.value();
        if (o.value.empty() && r_.peek() != ';')
            r_.fail("bad value for option '" + o.name + "'" + r_.describe_next());
        if (o.value.empty())
            o.value = "yes";
        end("option");
        c_.options.push_back(std::move(o));
    }

    void modparam(int line)
    {
        ModParam m;
        m.line = line;
        m.type = r_.identifier();
        if (m.type != "int" && m.type != "long" && m.type != "string" && m.type != "dummy")
            r_.fail("expected the modparam type int, long, string or dummy" +
                    (m.type.empty() ? r_.describe_next() : ", found '" + m.type + "'"));
        m.name = r_.identifier();
        if (m.name.empty())
            r_.fail("expected a modparam name" + r_.describe_next());
        if (r_.accept('=')) {
            if (r_.at_string())
                m.default_value = c_quote(r_.string_literal());
            else
                m.default_value = default_value("modparam '" + m.name + "'");
        }
        m.doc = optional_doc();
        end("modparam");
        c_.modparams.push_back(std::move(m));
    }

    void include()
    {
        if (r_.accept('<')) {
            std::string h = r_.expression(">;\n");
            r_.expect('>', "after the header name");
            c_.includes.push_back("<" + h + ">");
        } else {
            c_.includes.push_back(c_quote(r_.string_literal()));
        }
        end("include");
    }

    void text_field(const std::string& kw)
    {
        std::string text = r_.string_literal();
        std::string* field = kw == "license" ? &c_.license
                             : kw == "author" ? &c_.author
                             : kw == "description" ? &c_.description
                             : kw == "notes" ? &c_.notes
                                             : &c_.see_also;
        if (!field->empty())
            *field += "\n";
        *field += text;
        end(kw);
    }

    Reader r_;
    Component& c_;
};

}  // namespace

Result<Component> parse_comp(const std::string& text, const std::string& file, std::string* warnings)
{
    Component c;
    c.file = file;
    try {
        Parser(text, c).run();
    } catch (const ParseError& e) {
        return Error{-1, file + ":" + std::to_string(e.line) + ": " + e.message};
    }
    if (auto r = check_component(c, warnings); !r)
        return r.error();
    return c;
}

}  // namespace hal::comp
