// SPDX-License-Identifier: GPL-2.0-or-later
// gen_doc.cpp - see gen_doc.hpp. Doc strings are copied verbatim (they may hold
// \fB...\fR font changes); only lines that groff would read as requests are escaped.
#include "gen_doc.hpp"

#include <cctype>
#include <cstdio>
#include <sstream>

#include "names.hpp"

namespace hal::comp {

namespace {

std::string upper(std::string s)
{
    for (char& c : s)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// Text body: a line starting with '.' or '\'' would be a request; \& defuses it.
std::string body(const std::string& raw)
{
    // Leading blanks would make groff indent the line; surrounding space means nothing.
    std::size_t b = raw.find_first_not_of(" \t\n"), e = raw.find_last_not_of(" \t\n");
    std::string text = b == std::string::npos ? std::string() : raw.substr(b, e - b + 1);
    std::string out;
    bool line_start = true;
    for (char c : text) {
        if (line_start && (c == '.' || c == '\''))
            out += "\\&";
        out += c;
        line_start = c == '\n';
    }
    if (!out.empty() && out.back() != '\n')
        out += '\n';
    return out;
}

// Name of an array item with the index shown as M's: "in-##" -> "in-MM", plus "(MM=00..15)".
std::string array_doc_name(const Item& it, std::string* range)
{
    std::string hal = to_hal(it.name), out;
    int width = 0;
    for (char c : hal) {
        if (c == '#') {
            out += 'M';
            ++width;
        } else {
            out += c;
        }
    }
    char lo[64], hi[64];
    width = width > 9 ? 9 : width;  // keeps the snprintf below in bounds
    std::snprintf(lo, sizeof(lo), "%0*d", width, 0);
    std::snprintf(hi, sizeof(hi), "%0*d", width, it.array_size - 1);
    *range = " (" + std::string(width, 'M') + "=" + lo + ".." +
             (it.array_count.empty() ? std::string(hi) : it.array_count) + ")";
    return out;
}

std::string prefix_roff(const Component& c)
{
    if (c.is_singleton())
        return to_hal(c.name);
    return to_hal(c.name) + ".\\fIN\\fB";
}

}  // namespace

std::string synopsis_text(const Component& c)
{
    if (c.is_userspace())
        return "loadusr " + c.name;
    std::string s = "loadrt " + c.name;
    bool count_fn = c.option_on("count_function");
    if (!c.is_singleton() && !count_fn)
        s += " [count=N|names=name1[,name2...]]";
    if (c.has_personality())
        s += count_fn ? " personality=P" : " [personality=P,P,...]";
    for (const ModParam& m : c.modparams)
        s += " [" + m.name + "=N]";
    return s;
}

std::string generate_doc(const Component& c, const std::string& date)
{
    std::ostringstream o;
    o << ".TH " << upper(c.name) << " \"9\" \"" << date
      << "\" \"EMC Documentation\" \"HAL Component\"\n"
      << ".de TQ\n.br\n.ns\n.TP \\\\$1\n..\n\n";
    o << ".SH NAME\n" << c.name << " \\- " << c.doc << "\n";
    o << ".SH SYNOPSIS\n.HP\n";
    std::string syn = synopsis_text(c);
    // Placeholders in italics, as the reference pages print them.
    std::string roff;
    for (std::size_t i = 0; i < syn.size(); ++i) {
        if (syn.compare(i, 2, "=N") == 0 || syn.compare(i, 2, "=P") == 0) {
            roff += std::string("=\\fI") + syn[i + 1] + "\\fB";
            ++i;
        } else if (syn.compare(i, 5, "name1") == 0 || syn.compare(i, 5, "name2") == 0) {
            roff += "\\fI" + syn.substr(i, 5) + "\\fB";
            i += 4;
        } else {
            roff += syn[i];
        }
    }
    o << ".B " << roff << "\n";
    for (const ModParam& m : c.modparams)
        if (!m.doc.empty())
            o << ".RS 4\n.TP\n\\fB" << m.name << "\\fR\n" << body(m.doc) << ".RE\n";
    if (!c.description.empty())
        o << ".SH DESCRIPTION\n" << body(c.description);
    if (!c.functions.empty()) {
        o << ".SH FUNCTIONS\n";
        for (const Function& f : c.functions) {
            o << ".TP\n\\fB" << prefix_roff(c) << (f.name == "_" ? "" : "." + to_hal(f.name)) << "\\fR";
            if (f.fp)
                o << " (requires a floating-point thread)";
            o << "\n" << body(f.doc);
        }
    }
    for (bool pins : {true, false}) {
        bool any = false;
        for (const Item& it : c.items) {
            if (it.is_pin != pins)
                continue;
            if (!any)
                o << (pins ? ".SH PINS\n" : ".SH PARAMETERS\n");
            any = true;
            std::string range;
            std::string name = it.array_size ? array_doc_name(it, &range) : to_hal(it.name);
            o << ".TP\n.B " << prefix_roff(c) << "." << name << "\\fR " << type_name(it.type) << " "
              << dir_name(it.dir);
            if (!it.condition.empty())
                o << " [if " << it.condition << "]";
            o << range;
            if (!it.default_value.empty())
                o << " (default: \\fI" << it.default_value << "\\fR)";
            o << "\n" << body(it.doc);
        }
    }
    if (!c.notes.empty())
        o << ".SH NOTES\n" << body(c.notes);
    if (!c.see_also.empty())
        o << ".SH SEE ALSO\n" << body(c.see_also);
    if (!c.author.empty())
        o << ".SH AUTHOR\n" << body(c.author);
    if (!c.license.empty())
        o << ".SH LICENSE\n" << body(c.license);
    return o.str();
}

}  // namespace hal::comp
